// The hzb family's view and its view flags (ui/hzb_tbv/hzb_tbv_family_view.h).
#include "ui/hzb_tbv/hzb_tbv_family_view.h"

#include <limits>

#include "culling/hzb_tbv/hzb_tbv_snapshot.h"
#include "ui/hzb_tbv/hzb_pyramid_images.h"
#include "ui/hzb_tbv/hzb_tbv_overlay.h"
#include "ui/hzb_tbv/hzb_tbv_panel.h"

namespace gridcull {

namespace {

// The view state the command line can set; -1: the overlay preset's.
struct HzbTbvViewFlags {
    int show_tbvs = -1;
    // Outcomes shown, a bit each: 1 frustum-culled, 2 Z-culled, 4 entered.
    int show_nodes = -1;
    int show_pyramid = -1;
    int pyramid_level = -1;  // -1: auto
    int object = -1;         // scene id of the picked object; -1: none
};

static_assert(kHzbMaxNodesDrawn == 1500, "--hzb-show-nodes's help names the cap");

// Deeper than any pyramid of the largest image (kMaxImageResolution).
constexpr int kMaxPyramidLevel = 31;

const KnobTable<HzbTbvViewFlags>& hzbTbvViewFlags() {
    static const KnobTable<HzbTbvViewFlags> table{
        derivedKnob("hzb-show-tbvs", &HzbTbvViewFlags::show_tbvs, 0, 1, "preset",
                    "the overlay preset's",
                    "1 draws each hidden dynamic object's TBV as a wire box, coloured by the "
                    "part of its validity period left; 0 hides them"),
        derivedKnob("hzb-show-nodes", &HzbTbvViewFlags::show_nodes, 0, 7, "preset",
                    "the overlay preset's",
                    "the octree nodes the traversal reached drawn as wire boxes, by outcome, a "
                    "bit each: 1 frustum-culled, 2 Z-culled (hidden by the Z-pyramid), 4 "
                    "entered; 0 none, 7 all (at most 1500 boxes, front to back)"),
        derivedKnob("hzb-show-pyramid", &HzbTbvViewFlags::show_pyramid, 0, 1, "preset",
                    "the overlay preset's",
                    "1 shows Z-pyramid levels as grey images in the view's corner (near light, "
                    "far dark, empty black); 0 hides them"),
        derivedKnob("hzb-pyramid-level", &HzbTbvViewFlags::pyramid_level, 0, kMaxPyramidLevel,
                    "auto", "the finest level at most 64 texels wide",
                    "the finest Z-pyramid level shown (0 is the z-buffer; levels over 256 "
                    "texels a side give the finest captured one), with the next two coarser"),
        derivedKnob("hzb-object", &HzbTbvViewFlags::object, 0, std::numeric_limits<int>::max(),
                    "none", "none",
                    "pick the object with scene id N, as a click in the window does: its TBV "
                    "drawn heavier, its state and TBV in the panel"),
    };
    return table;
}

class HzbTbvFamilyView final : public FamilyView {
public:
    HzbTbvFamilyView() { hzbTbvApplyPreset(view_, hzbTbvOverlayPresets().front()); }

    bool applyFlags(const KnobValues& flags, const Scene& scene, std::string& error) override {
        // The toggles' flags override the preset's toggles only when given.
        const HzbTbvViewFlags f = hzbTbvViewFlags().read(flags);
        if (f.show_tbvs >= 0) view_.show_tbvs = f.show_tbvs != 0;
        if (f.show_nodes >= 0)
            for (int k = 0; k < kHzbNodeOutcomeCount; ++k)
                view_.show_nodes[k] = (f.show_nodes >> k) & 1;
        if (f.show_pyramid >= 0) view_.show_pyramid = f.show_pyramid != 0;
        view_.pyramid_level = f.pyramid_level;
        pinned_ = -1;  // not given: none (a lesson's steps set the flags one after another)
        if (f.object < 0) return true;
        pinned_ = scene.indexOf(f.object);
        if (pinned_ >= 0) return true;
        error =
            "--hzb-object " + std::to_string(f.object) + ": the scene has no object with that id";
        return false;
    }

    std::vector<OverlayPreset> overlayPresets() const override { return hzbTbvOverlayPresets(); }
    void applyOverlayPreset(OverlayPreset preset) override { hzbTbvApplyPreset(view_, preset); }

    void sceneChanged() override { pinned_ = -1; }  // an index into the old scene

    void pointer(const FamilyViewContext& context, const ViewPointer& pointer) override {
        // A click keeps the object under the pointer (none: clears the pick).
        if (pointer.clicked && snapshotOf(context)) pinned_ = context.hovered_object;
    }

    int focusedObject(const FamilyViewContext& context) const override {
        if (!snapshotOf(context)) return context.hovered_object;
        return context.hovered_object >= 0 ? context.hovered_object : pinned_;
    }

    void drawPanel(const FamilyViewContext& context, FamilyAction& action) override {
        (void)action;
        const HzbTbvSnapshot* hzb = snapshotOf(context);
        if (!hzb) return;
        HzbTbvPanelInput input;
        input.scene = context.scene;
        input.algo = context.algo;
        input.focus_object = focusedObject(context);
        input.focus_pinned = context.hovered_object < 0 && pinned_ >= 0;
        drawHzbTbvPanel(*hzb, input, view_);
    }

    void drawOverlay(const FamilyViewContext& context, const OverlayView& view,
                     DebugDraw& draw) override {
        const HzbTbvSnapshot* hzb = snapshotOf(context);
        if (!hzb) return;
        drawHzbTbvOverlay(*hzb, view_, focusedObject(context), draw);
        drawHzbPyramidImages(*hzb, view_, view.width, view.height, draw);
    }

private:
    static const HzbTbvSnapshot* snapshotOf(const FamilyViewContext& context) {
        const HzbTbvSnapshot* hzb =
            context.snapshot ? context.snapshot->as<HzbTbvSnapshot>() : nullptr;
        return hzb && hzb->valid ? hzb : nullptr;
    }

    HzbTbvViewState view_;
    int pinned_ = -1;  // object index picked by a click or --hzb-object
};

}  // namespace

FamilyViewEntry hzbTbvFamilyView() {
    FamilyViewEntry entry;
    entry.family = "hzb";
    entry.flags = hzbTbvViewFlags().knobs();
    entry.make = [] { return std::make_unique<HzbTbvFamilyView>(); };
    return entry;
}

}  // namespace gridcull
