#include "ui/rgvc/rgvc_family_view.h"

#include <limits>
#include <vector>

#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/rgvc/rgvc_hovered_voxel.h"
#include "ui/rgvc/rgvc_object_voxels.h"
#include "ui/rgvc/rgvc_overlay.h"
#include "ui/rgvc/rgvc_overlay3d.h"
#include "ui/rgvc/rgvc_panel.h"
#include "ui/rgvc/rgvc_pick3d.h"

namespace gridcull {

namespace {

// The view state the command line can set.
struct RgvcViewFlags {
    int layer = -1;      // chess layer shown up to; -1: every layer
    int occluder = -1;   // picked occluder; -1: none
    int slice = -1;      // 3D: the slice shown instead of boxes; -1: boxes
    int slice_axis = 1;  // 3D: 0 x, 1 y, 2 z
    int object = -1;     // the object (scene id) whose voxels the panel lists; -1: none
    int tbv = -1;        // 1 shows T, 0 hides it; -1: the overlay preset decides
    int static_voxels = -1;  // 3D: 1 shows Os apart from O, 0 folds it in; -1: the preset decides
};

constexpr int kMaxFlagValue = 100000000;

const KnobTable<RgvcViewFlags>& rgvcViewFlags() {
    static const KnobTable<RgvcViewFlags> table{
        derivedKnob("rgvc-layer", &RgvcViewFlags::layer, 0, kMaxFlagValue, "all", "every layer",
                    "show the traversal up to chess layer N, that layer and its seed "
                    "highlighted, and O, H, I and T as they stood after it"),
        derivedKnob("rgvc-occluder", &RgvcViewFlags::occluder, 0, kMaxFlagValue, "none", "none",
                    "pick occluder N (0-based, in the order the traversal found them): 2D, "
                    "the extended occluder's steps and occlusion polygon; 3D, the voxel's "
                    "layer cap, its extrusion and the direction-map cells its pass covered"),
        derivedKnob("rgvc-slice", &RgvcViewFlags::slice, 0, kMaxFlagValue, "none", "voxel boxes",
                    "3D: show the plane of voxels with index N along --rgvc-slice-axis "
                    "(clamped to the grid) instead of the voxel boxes"),
        knob("rgvc-slice-axis", &RgvcViewFlags::slice_axis, 0, 2,
             "3D: the axis the slice is cut across: 0 x, 1 y, 2 z"),
        derivedKnob("rgvc-object", &RgvcViewFlags::object, 0, std::numeric_limits<int>::max(),
                    "none", "none",
                    "pick the object with scene id N, as a click in the window does: the "
                    "panel lists its voxels in I and what the traversal found in each"),
        derivedKnob("rgvc-tbv", &RgvcViewFlags::tbv, 0, 1, "default", "the overlay preset's",
                    "1 shows the TBV matrix T (3D: a voxel where 2 of Txy, Txz and Tyz hold an "
                    "id), 0 hides it, over the overlay preset's toggles"),
        derivedKnob("rgvc-static", &RgvcViewFlags::static_voxels, 0, 1, "default",
                    "the overlay preset's",
                    "3D: 1 draws the static objects' opaque voxels Os apart from O (grey), 0 "
                    "draws them as O, over the overlay preset's toggles"),
    };
    return table;
}

class RgvcFamilyView final : public FamilyView {
public:
    bool applyFlags(const KnobValues& flags, const Scene& scene, std::string& error) override {
        followDimensions(scene.dimensions);
        const RgvcViewFlags f = rgvcViewFlags().read(flags);
        view_.layer = f.layer;
        view_.occluder = f.occluder;
        view_.slice_axis = f.slice_axis;
        tbv_flag_ = f.tbv;
        static_flag_ = f.static_voxels;
        applyLayerFlags();
        // Flags not given take their defaults: a lesson's steps set them again
        // one after another.
        view_.mode = f.slice >= 0 ? RgvcVoxelMode::Slice : RgvcVoxelMode::Boxes;
        if (f.slice >= 0) view_.slice_index = f.slice;
        pinned_object_ = -1;
        if (f.object < 0) return true;
        pinned_object_ = scene.indexOf(f.object);
        if (pinned_object_ >= 0) return true;
        error =
            "--rgvc-object " + std::to_string(f.object) + ": the scene has no object with that id";
        return false;
    }

    std::vector<OverlayPreset> overlayPresets() const override { return rgvcOverlayPresets(); }

    void applyOverlayPreset(OverlayPreset preset) override {
        // The preset asks for T itself: --rgvc-tbv no longer overrides it.
        preset_ = preset;
        tbv_flag_ = -1;
        static_flag_ = -1;
        if (toggles_for_ != 0) rgvcApplyPreset(view_, preset_, toggles_for_);
    }

    void sceneChanged() override {
        hovering_ = false;
        has_pinned_voxel_ = false;
        pinned_object_ = -1;
    }

    void pointer(const FamilyViewContext& context, const ViewPointer& pointer) override {
        followDimensions(context.scene->dimensions);
        hovering_ = false;
        if (!pointer.over_view) return;  // the pinned voxel stays in the panel
        const RgvcSnapshot* rgvc = snapshotOf(context);
        if (context.scene->dimensions == 2) {
            // The culler's grid (--rgvc-grid-res may differ from the scene's),
            // which the overlay draws and the voxel description reads.
            const glm::ivec3 v = (rgvc ? rgvc->grid : context.scene->grid).voxelOf(pointer.origin);
            hovered_voxel_ = {v.x, v.y, 0};
            hovering_ = true;
            if (pointer.clicked && rgvc) view_.occluder = rgvcOccluderAt(*rgvc, {v.x, v.y});
        } else if (rgvc && rgvc->dimensions == 3) {
            scratch3d_.index.update(*rgvc, rgvcShownLayer(*rgvc, view_.layer));
            hovering_ = pickRgvcVoxel3d(*rgvc, view_, scratch3d_.index, scratch3d_.index.layer(),
                                        pointer.origin, pointer.direction, hovered_voxel_);
            if (pointer.clicked)
                view_.occluder = hovering_ ? rgvcOccluder3dAt(*rgvc, hovered_voxel_) : -1;
        }
        if (pointer.clicked && rgvc) {
            has_pinned_voxel_ = hovering_;
            pinned_voxel_ = hovered_voxel_;
            pinned_object_ = context.hovered_object;
        }
    }

    int focusedObject(const FamilyViewContext& context) const override {
        // A picked object is outlined as if it were under the pointer.
        if (!snapshotOf(context)) return context.hovered_object;
        return context.hovered_object >= 0 ? context.hovered_object : pinned_object_;
    }

    void drawPanel(const FamilyViewContext& context, FamilyAction&) override {
        followDimensions(context.scene->dimensions);
        const RgvcSnapshot* rgvc = snapshotOf(context);
        if (!rgvc) return;
        RgvcPanelInput input;
        const glm::ivec3* voxel = hovering_           ? &hovered_voxel_
                                  : has_pinned_voxel_ ? &pinned_voxel_
                                                      : nullptr;
        if (voxel) {
            describeRgvcVoxel(*rgvc, *context.scene, *voxel, voxel_);
            input.voxel = &voxel_;
            input.voxel_hovered = hovering_;
        }
        const int object = context.hovered_object >= 0 ? context.hovered_object : pinned_object_;
        scratch3d_.index.update(*rgvc, rgvcShownLayer(*rgvc, view_.layer));
        describeRgvcObject(*rgvc, *context.scene, scratch3d_.index, object, object_);
        input.object = &object_;
        if (context.states && object >= 0 && size_t(object) < context.states->size())
            input.object_state = (*context.states)[size_t(object)];
        if (rgvc->dimensions == 3 && view_.occluder >= 0) {
            buildRgvcCap3d(*rgvc, context.scene->camera.near, view_.occluder, scratch3d_.cap);
            input.cap = &scratch3d_.cap;
        }
        drawRgvcPanel(*rgvc, view_, input);
    }

    void drawOverlay(const FamilyViewContext& context, const OverlayView& overlay,
                     DebugDraw& draw) override {
        followDimensions(context.scene->dimensions);
        const RgvcSnapshot* rgvc = snapshotOf(context);
        if (!rgvc) return;
        if (rgvc->dimensions == 2 && context.scene->dimensions == 2) {
            drawRgvcOverlay(*rgvc, view_, draw, scratch_);
        } else if (rgvc->dimensions == 3) {
            const glm::dvec3 eye = rgvcViewEye(overlay.view_projection, rgvc->grid);
            drawRgvcOverlay3d(*rgvc, view_, context.scene->camera.near, eye, draw, scratch3d_);
        } else {
            return;
        }
        // Last, so that its outline lies over the layers' of the same width.
        if (hovering_) drawRgvcHoveredVoxel(*rgvc, hovered_voxel_, draw);
    }

private:
    // The toggles are the current preset's for the scene's dimension (Os and
    // T differ), set again when a scene of the other dimension opens, and
    // --rgvc-tbv over them until a preset is picked.
    void followDimensions(int dimensions) {
        if (dimensions == toggles_for_) return;
        rgvcApplyPreset(view_, preset_, dimensions);
        toggles_for_ = dimensions;
        applyLayerFlags();
    }

    static const RgvcSnapshot* snapshotOf(const FamilyViewContext& context) {
        const RgvcSnapshot* rgvc =
            context.snapshot ? context.snapshot->as<RgvcSnapshot>() : nullptr;
        return rgvc && rgvc->valid ? rgvc : nullptr;
    }

    RgvcViewState view_;
    OverlayPreset preset_ = rgvcOverlayPresets().front();
    // --rgvc-tbv and --rgvc-static over the preset's toggles (for T and Os).
    void applyLayerFlags() {
        if (tbv_flag_ >= 0) view_.show[int(RgvcLayer::Tbv)] = tbv_flag_ == 1;
        if (static_flag_ >= 0 && rgvcLayerApplies(RgvcLayer::StaticOccluder, toggles_for_))
            view_.show[int(RgvcLayer::StaticOccluder)] = static_flag_ == 1;
    }

    int tbv_flag_ = -1;      // --rgvc-tbv: 1 shows T, 0 hides it, -1 the preset decides
    int static_flag_ = -1;   // --rgvc-static: 1 shows Os apart, 0 folds it into O, -1 the preset
    int toggles_for_ = 0;    // the dimension view_'s toggles are set for
    bool hovering_ = false;  // a voxel is under the pointer
    glm::ivec3 hovered_voxel_{0};
    bool has_pinned_voxel_ = false;  // the voxel clicked last, shown when none is hovered
    glm::ivec3 pinned_voxel_{0};
    int pinned_object_ = -1;  // object index clicked or named by --rgvc-object
    RgvcVoxelInfo voxel_;
    RgvcObjectVoxels object_;
    std::vector<uint8_t> scratch_;
    RgvcOverlay3dScratch scratch3d_;
};

}  // namespace

FamilyViewEntry rgvcFamilyView() {
    FamilyViewEntry entry;
    entry.family = "rgvc";
    entry.flags = rgvcViewFlags().knobs();
    entry.make = [] { return std::make_unique<RgvcFamilyView>(); };
    return entry;
}

}  // namespace gridcull
