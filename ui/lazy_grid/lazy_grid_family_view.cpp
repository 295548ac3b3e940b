#include "ui/lazy_grid/lazy_grid_family_view.h"

#include <limits>

#include "culling/lazy_grid/lazy_grid_snapshot.h"
#include "ui/image_plane_draw.h"
#include "ui/lazy_grid/lazy_grid_hovered_cell.h"
#include "ui/lazy_grid/lazy_grid_overlay.h"
#include "ui/lazy_grid/lazy_grid_panel.h"

namespace gridcull {

namespace {

struct LazyGridViewFlags {
    int object = -1;  // scene id of the picked object; -1: none
};

const KnobTable<LazyGridViewFlags>& lazyGridViewFlags() {
    static const KnobTable<LazyGridViewFlags> table{
        derivedKnob("lazy-object", &LazyGridViewFlags::object, 0, std::numeric_limits<int>::max(),
                    "none", "none",
                    "pick the object with scene id N, as a click in the window does: the cells "
                    "its deciding test touched and its screen rectangle over the view through "
                    "the culling camera, the step that decided it in the panel"),
    };
    return table;
}

class LazyGridFamilyView final : public FamilyView {
public:
    LazyGridFamilyView() { lazyGridApplyPreset(view_, lazyGridOverlayPresets().front()); }

    bool applyFlags(const KnobValues& flags, const Scene& scene, std::string& error) override {
        const int id = lazyGridViewFlags().read(flags).object;
        pinned_ = -1;  // not given: none (a lesson's steps set the flags one after another)
        if (id < 0) return true;
        pinned_ = scene.indexOf(id);
        if (pinned_ >= 0) return true;
        error = "--lazy-object " + std::to_string(id) + ": the scene has no object with that id";
        return false;
    }

    std::vector<OverlayPreset> overlayPresets() const override { return lazyGridOverlayPresets(); }
    void applyOverlayPreset(OverlayPreset preset) override { lazyGridApplyPreset(view_, preset); }

    void sceneChanged() override { pinned_ = -1; }  // an index into the old scene

    void pointer(const FamilyViewContext& context, const ViewPointer& pointer) override {
        // The ray, for the cell under it: which cell depends on the view's
        // camera, which only the overlay's draw is told.
        pointing_ = pointer.over_view;
        ray_origin_ = pointer.origin;
        ray_direction_ = pointer.direction;
        // A click keeps the object under the pointer (none: clears the pick).
        if (pointer.clicked && snapshotOf(context)) pinned_ = context.hovered_object;
    }

    int focusedObject(const FamilyViewContext& context) const override {
        // A picked object is outlined as if it were under the pointer.
        if (!snapshotOf(context)) return context.hovered_object;
        return context.hovered_object >= 0 ? context.hovered_object : pinned_;
    }

    void drawPanel(const FamilyViewContext& context, FamilyAction& action) override {
        const LazyGridSnapshot* lazy = snapshotOf(context);
        if (!lazy) return;
        LazyGridPanelInput input;
        input.scene = context.scene;
        input.algo = context.algo;
        input.view_mode = context.view_mode;
        input.focus_object = focusedObject(context);
        input.focus_pinned = context.hovered_object < 0 && pinned_ >= 0;
        drawLazyGridPanel(*lazy, input, view_, panel_, action);
    }

    void drawOverlay(const FamilyViewContext& context, const OverlayView& view,
                     DebugDraw& draw) override {
        const LazyGridSnapshot* lazy = snapshotOf(context);
        if (!lazy) return;
        // The grid is the culling camera's image, so it lies on the objects only
        // when the view looks through that camera; from outside, it is held up
        // across the camera's frustum, over the objects it stands for.
        if (!view.through_culling_camera) {
            if (context.scene->dimensions != 3) return;
            const Camera& camera = view.culling_camera;
            ImagePlaneDraw plane(draw, camera,
                                 imagePlaneDistance(camera, context.scene->grid.world.extent()),
                                 lazy->width, lazy->height);
            drawLazyGridOverlay(*lazy, view_, focusedObject(context),
                                imagePixelFrame(lazy->width, lazy->height), plane, scratch_);
            return;
        }
        const ImageFrame frame = view.cullingImage(lazy->width, lazy->height);
        drawLazyGridOverlay(*lazy, view_, focusedObject(context), frame, draw, scratch_);
        int cx = 0, cy = 0;
        if (pointing_ && lazyCellUnderPointer(*lazy, view, ray_origin_, ray_direction_, cx, cy))
            drawLazyHoveredCell(*lazy, frame, cx, cy, draw);
    }

private:
    static const LazyGridSnapshot* snapshotOf(const FamilyViewContext& context) {
        const LazyGridSnapshot* lazy =
            context.snapshot ? context.snapshot->as<LazyGridSnapshot>() : nullptr;
        return lazy && lazy->valid ? lazy : nullptr;
    }

    LazyGridViewState view_;
    LazyGridPanelState panel_;
    int pinned_ = -1;  // object index picked by a click or --lazy-object
    bool pointing_ = false;  // the pointer is over the view, along the ray below
    glm::dvec3 ray_origin_{0.0}, ray_direction_{0.0};
    LazyGridOverlayScratch scratch_;
};

}  // namespace

FamilyViewEntry lazyGridFamilyView() {
    FamilyViewEntry entry;
    entry.family = "lazy-grid";
    entry.flags = lazyGridViewFlags().knobs();
    entry.make = [] { return std::make_unique<LazyGridFamilyView>(); };
    return entry;
}

}  // namespace gridcull
