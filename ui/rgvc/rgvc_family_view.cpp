#include "ui/rgvc/rgvc_family_view.h"

#include <vector>

#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/rgvc/rgvc_overlay.h"
#include "ui/rgvc/rgvc_panel.h"

namespace gridcull {

namespace {

// The view state the command line can set.
struct RgvcViewFlags {
    int layer = -1;     // chess layer shown up to; -1: every layer
    int occluder = -1;  // picked extended occluder; -1: none
};

constexpr int kMaxFlagValue = 100000000;

const KnobTable<RgvcViewFlags>& rgvcViewFlags() {
    static const KnobTable<RgvcViewFlags> table{
        derivedKnob("rgvc-layer", &RgvcViewFlags::layer, 0, kMaxFlagValue, "all", "every layer",
                    "show the traversal up to chess layer N, that layer and its seed "
                    "highlighted"),
        derivedKnob("rgvc-occluder", &RgvcViewFlags::occluder, 0, kMaxFlagValue, "none", "none",
                    "pick extended occluder N (0-based, in the order the traversal found "
                    "them): its extension steps and occlusion polygon"),
    };
    return table;
}

class RgvcFamilyView final : public FamilyView {
public:
    bool applyFlags(const KnobValues& flags, const Scene&, std::string&) override {
        const RgvcViewFlags f = rgvcViewFlags().read(flags);
        view_.layer = f.layer;
        view_.occluder = f.occluder;
        return true;
    }

    void sceneChanged() override { voxel_hovered_ = false; }

    void pointer(const FamilyViewContext& context, const ViewPointer& pointer) override {
        voxel_hovered_ = pointer.over_view && context.scene->dimensions == 2;
        if (!voxel_hovered_) return;
        // The culler's grid (--rgvc-grid-res may differ from the scene's), which
        // the overlay draws and the voxel description reads.
        const RgvcSnapshot* rgvc = snapshotOf(context);
        const glm::ivec3 voxel = (rgvc ? rgvc->grid : context.scene->grid).voxelOf(pointer.origin);
        hovered_voxel_ = {voxel.x, voxel.y};
        if (pointer.clicked && rgvc) view_.occluder = rgvcOccluderAt(*rgvc, hovered_voxel_);
    }

    void drawPanel(const FamilyViewContext& context, FamilyAction&) override {
        const RgvcSnapshot* rgvc = snapshotOf(context);
        if (!rgvc) return;
        if (voxel_hovered_) describeRgvcVoxel(*rgvc, *context.scene, hovered_voxel_, voxel_);
        drawRgvcPanel(*rgvc, view_, voxel_hovered_ ? &voxel_ : nullptr);
    }

    void drawOverlay(const FamilyViewContext& context, const OverlayView&,
                     DebugDraw& draw) override {
        const RgvcSnapshot* rgvc = snapshotOf(context);
        if (rgvc && context.scene->dimensions == 2) drawRgvcOverlay(*rgvc, view_, draw, scratch_);
    }

private:
    static const RgvcSnapshot* snapshotOf(const FamilyViewContext& context) {
        const RgvcSnapshot* rgvc =
            context.snapshot ? context.snapshot->as<RgvcSnapshot>() : nullptr;
        return rgvc && rgvc->valid ? rgvc : nullptr;
    }

    RgvcViewState view_;
    bool voxel_hovered_ = false;
    glm::ivec2 hovered_voxel_{0};
    RgvcVoxelInfo voxel_;
    std::vector<uint8_t> scratch_;
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
