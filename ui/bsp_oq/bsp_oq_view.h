// What the window shows of BSP trees with occlusion queries (bsp-oq,
// bsp-oq-simple, bsp-vfc; culling/bsp_oq/bsp_oq_snapshot.h) and the colours it
// uses, shared by the panel (ui/bsp_oq/bsp_oq_panel.h), which changes the view
// state and keys the colours, and the overlay (ui/bsp_oq/bsp_oq_overlay.h),
// which draws it.
//
// Names are Kovalčík & Sochor's (section 3.4, Algorithms 2 to 4): scene tree,
// object tree, FirstVisibilityTest's outcomes, batches of occlusion queries,
// recent query results. Colours are the palette's hues that the object states
// (blue, sky blue, vermillion, dim grey) and the camera (yellow) leave free,
// and greys; a node state's colour is its query rectangle's colour too, so a
// rectangle and the box it was drawn from read alike:
//   queried hidden white (as the hzb view's Z-culled nodes; ui/palette.h),
//   queried visible bluish green, assumed visible (coherence) orange,
//   viewer inside reddish purple, in the frustum (bsp-vfc) light grey,
//   outside the frustum dim grey (as in every family's view),
//   not reached grey (not known), empty line grey.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/bsp_oq/bsp_oq_options.h"
#include "culling/bsp_oq/bsp_oq_snapshot.h"
#include "ui/overlay_preset.h"
#include "ui/palette.h"

namespace gridcull {

Swatch bspNodeStateSwatch(BspNodeState state);
float bspNodeStateAlpha(BspNodeState state);
float bspNodeStateWidth(BspNodeState state);
// One line of what the state means, for the panel's key.
const char* bspNodeStateMeaning(BspNodeState state);
// A query rectangle's colour: its answer's state (queried visible or hidden).
Swatch bspQuerySwatch(bool visible);

// At most this many nodes of the scene tree, and of the picked object's tree,
// are drawn (the first ones shown, in pool order), so that a deep tree stays
// readable and a draw stays cheap.
constexpr int kBspMaxNodesDrawn = 1500;

// The "occlusion only" preset's, the first (bspOqOverlayPresets).
struct BspOqViewState {
    // By BspNodeState: the states that say what a query decided or saved are on;
    // not reached, outside the frustum and empty (the clutter) are off.
    bool show_nodes[kBspNodeStateCount] = {false, false, false, true, true, true, true, true};
    bool show_queries = true;  // the frame's query rectangles (through the culling camera)
    int batch = -1;            // the batch whose rectangles are shown; -1: every batch

    bool shown(BspNodeState s) const { return show_nodes[int(s)]; }
    bool batchShown(int b) const { return batch < 0 || batch == b; }
};

// The overlay presets, the first the one a view starts with: "occlusion only"
// (the query rectangles by answer, and the nodes in the states that say what a
// query decided, or why none was needed: coherence, the eye inside, bsp-vfc's
// untested), "traversal" (every node the traversal took up, by state, outside
// the frustum and empty ones included, no rectangles) and "all". No TBVs: the
// family has none. The batch shown stays as picked.
std::vector<OverlayPreset> bspOqOverlayPresets();
void bspOqApplyPreset(BspOqViewState& view, OverlayPreset preset);

// The node states as a bit mask (bit k: BspNodeState k), and back: what
// --bsp-show-nodes reads.
int bspNodeMask(const BspOqViewState& view);
void setBspNodeMask(BspOqViewState& view, int mask);

// A node of the snapshot: record `record` of scene_nodes, or of object_nodes.
struct BspNodeRef {
    int32_t record = -1;  // -1: none
    bool object_node = false;
    bool valid() const { return record >= 0; }
    bool operator==(const BspNodeRef& o) const {
        return record == o.record && object_node == o.object_node;
    }
};
// The record `ref` names, or null when it is out of the snapshot's range.
const BspNodeRecord* bspNodeOf(const BspOqSnapshot& snapshot, const BspNodeRef& ref);

// The object whose tree the overlay draws: `object` (an object index) when the
// traversal entered its tree this frame; else -1.
int bspShownTree(const BspOqSnapshot& snapshot, int object);

// Calls fn(record, ref) for each node the overlay draws: the first
// kBspMaxNodesDrawn scene nodes (pool order) whose state `view` shows, then the
// first kBspMaxNodesDrawn shown nodes of object `tree_object`'s tree (-1, or a
// tree not entered: none). Returns how many of each were visited.
struct BspDrawnCounts {
    int scene = 0, object = 0;
};
template <class Fn>
BspDrawnCounts forEachDrawnBspNode(const BspOqSnapshot& snapshot, const BspOqViewState& view,
                                   int tree_object, Fn&& fn) {
    BspDrawnCounts counts;
    if (!snapshot.valid) return counts;
    for (size_t i = 0; i < snapshot.scene_nodes.size() && counts.scene < kBspMaxNodesDrawn; ++i) {
        if (!view.shown(snapshot.scene_nodes[i].state)) continue;
        ++counts.scene;
        fn(snapshot.scene_nodes[i], BspNodeRef{int32_t(i), false});
    }
    const int tree = bspShownTree(snapshot, tree_object);
    if (tree < 0) return counts;
    const int first = snapshot.object_first[size_t(tree)];
    const int end = first + snapshot.object_count[size_t(tree)];
    for (int k = first; k < end && counts.object < kBspMaxNodesDrawn; ++k) {
        if (!view.shown(snapshot.object_nodes[size_t(k)].state)) continue;
        ++counts.object;
        fn(snapshot.object_nodes[size_t(k)], BspNodeRef{int32_t(k), true});
    }
    return counts;
}

// The node under a pointer ray: among the boxes the overlay draws (the scene
// nodes whose state `view` shows, and those of object `tree_object`'s tree,
// -1: none), the one whose box the ray enters first from outside (a box around
// the ray's origin is skipped: every ray starts in it); a tie goes to the
// smaller box, the deeper node. None when the ray enters no drawn box.
BspNodeRef pickBspNode(const BspOqSnapshot& snapshot, const BspOqViewState& view, int tree_object,
                       const glm::dvec3& origin, const glm::dvec3& direction);

// A node's recent query answers as marks, latest first: 'V' visible, 'H'
// hidden, history_length of them (at most kMaxBspHistory); "" when it was never
// queried. `out` needs kMaxBspHistory + 1 chars.
void bspHistoryMarks(const BspNodeRecord& node, char* out);

}  // namespace gridcull
