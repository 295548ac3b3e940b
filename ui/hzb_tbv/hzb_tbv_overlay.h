// Draws the hzb family's World-space overlay (culling/hzb_tbv/hzb_tbv_snapshot.h)
// over the scene view: each hidden dynamic object's TBV as the wire box T holds
// in its place, coloured by the fraction of its validity period left (the
// focused object's TBV heavier), and the octree nodes the front-to-back
// traversal reached, as wire boxes coloured by outcome (frustum-culled,
// Z-culled, entered), each outcome a toggle, at most kHzbMaxNodesDrawn of them
// in traversal order. Colours and toggles: ui/hzb_tbv/hzb_tbv_view.h.
//
// Cost per draw: 12 lines a box, O(dynamic objects + nodes drawn); allocates
// nothing of its own (the DebugDraw's buffers keep their capacity).
#pragma once
#include "culling/hzb_tbv/hzb_tbv_snapshot.h"
#include "ui/debug_draw.h"
#include "ui/hzb_tbv/hzb_tbv_view.h"

namespace gridcull {

// Line widths of the TBVs: every TBV, and the focused object's.
constexpr float kHzbTbvWidth = kBoldLine;
constexpr float kHzbFocusedTbvWidth = kHeavyLine;

// What one draw emitted, for the panel and tests.
struct HzbOverlayCounts {
    int tbvs = 0;         // TBV boxes drawn
    int nodes_shown = 0;  // nodes whose outcome is shown
    int nodes_drawn = 0;  // of those, drawn (at most kHzbMaxNodesDrawn)
};

// The nodes whose outcome `view` shows, and how many of them are drawn. O(nodes).
HzbOverlayCounts countHzbNodesShown(const HzbTbvSnapshot& snapshot, const HzbTbvViewState& view);

// Emits the overlay for `snapshot` as `view` asks; `focus_object` (an object
// index, -1: none) gets its TBV drawn heavier. Nothing when the snapshot is not
// valid.
HzbOverlayCounts drawHzbTbvOverlay(const HzbTbvSnapshot& snapshot, const HzbTbvViewState& view,
                                   int focus_object, DebugDraw& draw);

}  // namespace gridcull
