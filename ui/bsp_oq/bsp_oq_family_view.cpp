// The bsp family's view and its view flags (ui/bsp_oq/bsp_oq_family_view.h).
#include "ui/bsp_oq/bsp_oq_family_view.h"

#include <limits>

#include "culling/bsp_oq/bsp_oq_snapshot.h"
#include "ui/bsp_oq/bsp_oq_overlay.h"
#include "ui/bsp_oq/bsp_oq_panel.h"

namespace gridcull {

namespace {

// The view state the command line can set.
struct BspOqViewFlags {
    // States shown, a bit each (bit k: BspNodeState k); the default is the
    // view state's, the first overlay preset's.
    int show_nodes = bspNodeMask(BspOqViewState{});
    int show_queries = 1;
    int batch = -1;   // -1: every batch
    int object = -1;  // scene id of the picked object; -1: none
    int node = -1;    // scene-tree node (pool index) picked; -1: none
};

static_assert(kBspNodeStateCount == 8 && kBspMaxNodesDrawn == 1500,
              "--bsp-show-nodes's help names the states' bits and the cap");

const KnobTable<BspOqViewFlags>& bspOqViewFlags() {
    static const KnobTable<BspOqViewFlags> table{
        knob("bsp-show-nodes", &BspOqViewFlags::show_nodes, 0, 255,
             "the scene tree's nodes (and the picked object's tree's) drawn as wire boxes on the "
             "box each was tested on, by state, a bit each: 1 not reached, 2 outside the "
             "frustum, 4 empty, 8 viewer inside, 16 in the frustum (bsp-vfc), 32 assumed "
             "visible (query skipped), 64 queried visible, 128 queried hidden; 0 none, 255 all "
             "(at most 1500 boxes a tree)"),
        knob("bsp-show-queries", &BspOqViewFlags::show_queries, 0, 1,
             "1 draws the frame's occlusion queries as screen rectangles over the view through "
             "the culling camera, by answer, labelled with their batch; 0 hides them"),
        derivedKnob("bsp-show-batch", &BspOqViewFlags::batch, 0, std::numeric_limits<int>::max(),
                    "all", "every batch",
                    "show only the query rectangles of batch N (0 is the frame's first)"),
        derivedKnob("bsp-object", &BspOqViewFlags::object, 0, std::numeric_limits<int>::max(),
                    "none", "none",
                    "pick the object with scene id N, as a click in the window does: its BSP "
                    "tree's nodes drawn by state when the traversal entered it"),
        derivedKnob("bsp-node", &BspOqViewFlags::node, 0, std::numeric_limits<int>::max(), "none",
                    "none",
                    "pick scene-tree node N (as the panel numbers them), as a click on its box "
                    "does: drawn heavier, its recent query answers and skip counter in the panel"),
    };
    return table;
}

// A node as the view keeps it across frames: the tree it belongs to (-1: the
// scene tree) and its index there, which the snapshot's records carry.
struct NodeKey {
    int object = -1;
    int node = -1;
};

BspNodeRef resolve(const BspOqSnapshot& s, NodeKey key) {
    if (key.node < 0) return {};
    if (key.object >= 0) {
        if (bspShownTree(s, key.object) < 0 || key.node >= s.object_count[size_t(key.object)])
            return {};
        return {s.object_first[size_t(key.object)] + key.node, true};
    }
    for (size_t i = 0; i < s.scene_nodes.size(); ++i)
        if (s.scene_nodes[i].node == key.node) return {int32_t(i), false};
    return {};
}

NodeKey keyOf(const BspOqSnapshot& s, BspNodeRef ref) {
    const BspNodeRecord* r = bspNodeOf(s, ref);
    return r ? NodeKey{r->object, r->node} : NodeKey{};
}

class BspOqFamilyView final : public FamilyView {
public:
    bool applyFlags(const KnobValues& flags, const Scene& scene, std::string& error) override {
        // The toggles' flags override the preset's toggles only when given.
        const BspOqViewFlags f = bspOqViewFlags().read(flags);
        if (flags.has("bsp-show-nodes")) setBspNodeMask(view_, f.show_nodes);
        if (flags.has("bsp-show-queries")) view_.show_queries = f.show_queries != 0;
        view_.batch = f.batch;
        pinned_node_ = {-1, f.node};
        pinned_ = -1;  // not given: none (a lesson's steps set the flags one after another)
        if (f.object < 0) return true;
        pinned_ = scene.indexOf(f.object);
        if (pinned_ >= 0) return true;
        error =
            "--bsp-object " + std::to_string(f.object) + ": the scene has no object with that id";
        return false;
    }

    std::vector<OverlayPreset> overlayPresets() const override { return bspOqOverlayPresets(); }
    void applyOverlayPreset(OverlayPreset preset) override { bspOqApplyPreset(view_, preset); }

    void sceneChanged() override {  // indices into the old scene
        pinned_ = -1;
        pinned_node_ = hovered_node_ = {};
    }

    void pointer(const FamilyViewContext& context, const ViewPointer& pointer) override {
        const BspOqSnapshot* bsp = snapshotOf(context);
        hovered_node_ = {};
        if (!bsp || !pointer.over_view) return;
        const BspNodeRef ref = pickBspNode(*bsp, view_, bspShownTree(*bsp, focusedObject(context)),
                                           pointer.origin, pointer.direction);
        hovered_node_ = keyOf(*bsp, ref);
        // A click keeps the object and the node under the pointer (none: clears them).
        if (!pointer.clicked) return;
        pinned_ = context.hovered_object;
        pinned_node_ = hovered_node_;
    }

    int focusedObject(const FamilyViewContext& context) const override {
        if (!snapshotOf(context)) return context.hovered_object;
        return context.hovered_object >= 0 ? context.hovered_object : pinned_;
    }

    void drawPanel(const FamilyViewContext& context, FamilyAction& action) override {
        (void)action;
        const BspOqSnapshot* bsp = snapshotOf(context);
        if (!bsp) return;
        BspOqPanelInput input;
        input.scene = context.scene;
        input.algo = context.algo;
        input.focus_object = focusedObject(context);
        input.focus_pinned = context.hovered_object < 0 && pinned_ >= 0;
        input.focus_node = focusNode(*bsp);
        input.node_pinned = !resolve(*bsp, hovered_node_).valid() && input.focus_node.valid();
        drawBspOqPanel(*bsp, input, view_);
    }

    void drawOverlay(const FamilyViewContext& context, const OverlayView& view,
                     DebugDraw& draw) override {
        const BspOqSnapshot* bsp = snapshotOf(context);
        if (!bsp) return;
        drawBspOqNodes(*bsp, view_, bspShownTree(*bsp, focusedObject(context)), focusNode(*bsp),
                       draw);
        // The rectangles are the culling camera's image, so they lie on the
        // objects only when the view looks through that camera.
        if (view.through_culling_camera)
            drawBspOqQueries(*bsp, view_, view.cullingImage(bsp->width, bsp->height), draw);
    }

private:
    static const BspOqSnapshot* snapshotOf(const FamilyViewContext& context) {
        const BspOqSnapshot* bsp =
            context.snapshot ? context.snapshot->as<BspOqSnapshot>() : nullptr;
        return bsp && bsp->valid ? bsp : nullptr;
    }

    BspNodeRef focusNode(const BspOqSnapshot& bsp) const {
        const BspNodeRef hovered = resolve(bsp, hovered_node_);
        return hovered.valid() ? hovered : resolve(bsp, pinned_node_);
    }

    BspOqViewState view_;  // the first preset's (bspOqOverlayPresets)
    int pinned_ = -1;  // object index picked by a click or --bsp-object
    NodeKey pinned_node_, hovered_node_;
};

}  // namespace

FamilyViewEntry bspOqFamilyView() {
    FamilyViewEntry entry;
    entry.family = "bsp";
    entry.flags = bspOqViewFlags().knobs();
    entry.make = [] { return std::make_unique<BspOqFamilyView>(); };
    return entry;
}

}  // namespace gridcull
