// Draws the bsp family's overlays (culling/bsp_oq/bsp_oq_snapshot.h):
//  - World space: the scene tree's nodes as wire boxes on the box each was
//    tested on (shrunk or its cell), coloured by what the frame decided of it,
//    each state a toggle; the picked object's tree the same way; the focused
//    node (under the pointer, or picked) again, heavier;
//  - View space, over the view through the culling camera (an ImageFrame, as
//    every image-space family's): the frame's occlusion queries as their screen
//    rectangles, coloured by answer, each labelled with its batch number, all
//    batches or one.
// Colours and toggles: ui/bsp_oq/bsp_oq_view.h.
//
// Cost per draw: 12 lines a box, O(nodes drawn + queries); allocates nothing of
// its own (the DebugDraw's buffers keep their capacity).
#pragma once
#include "culling/bsp_oq/bsp_oq_snapshot.h"
#include "ui/bsp_oq/bsp_oq_view.h"
#include "ui/debug_draw.h"
#include "ui/image_frame.h"

namespace gridcull {

// The focused node's line width, and the query rectangles'.
constexpr float kBspFocusWidth = kHeavyLine;
constexpr float kBspQueryWidth = kFineLine;
// A query rectangle gets its batch number when it is at least this many view
// pixels wide and high: room for three digits; a label over a smaller one
// would hide it and its neighbours.
constexpr double kBspMinLabelledWidth = 28.0;
constexpr double kBspMinLabelledHeight = 16.0;
constexpr float kBspLabelScale = 1.5f;  // 10.5-pixel glyphs

// What one draw emitted, for the panel and tests.
struct BspOverlayCounts {
    int scene_nodes = 0;   // scene-tree boxes drawn
    int object_nodes = 0;  // boxes of the picked object's tree drawn
    bool focus = false;    // the focused node drawn heavier
    int queries = 0;       // query rectangles drawn
    int labels = 0;        // of those, labelled with their batch
};

// The World-space part: nodes of the scene tree and of object `tree_object`'s
// tree (an object index, -1: none) whose state `view` shows, and `focus` (none:
// no heavy box). Nothing when the snapshot is not valid.
BspOverlayCounts drawBspOqNodes(const BspOqSnapshot& snapshot, const BspOqViewState& view,
                                int tree_object, BspNodeRef focus, DebugDraw& draw);

// The View-space part: the query rectangles of the batches `view` shows, in
// `frame`, which must be made for the snapshot's image size. Nothing when the
// snapshot is not valid or queries are not shown.
BspOverlayCounts drawBspOqQueries(const BspOqSnapshot& snapshot, const BspOqViewState& view,
                                  const ImageFrame& frame, DebugDraw& draw);

}  // namespace gridcull
