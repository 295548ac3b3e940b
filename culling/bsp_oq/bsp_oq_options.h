// The knobs of BSP culling with occlusion queries (Kovalčík & Sochor;
// culling/bsp_oq/bsp_oq_culler.h).
#pragma once
#include "culling/api/knobs.h"

namespace gridcull {

constexpr int kMinBspResolution = 16;
// Query results a node remembers (Algorithm 3's "recent query results"): a
// 32-bit history.
constexpr int kMaxBspHistory = 32;
// Queries one batch may hold (Algorithm 2's "maximum queries").
constexpr int kMaxBspBatch = 4096;
// Frames; a delay past this is "never" in any scene we load.
constexpr int kMaxBspDelayFrames = 1000000;

struct BspOqOptions {
    // Pixels on the long side of the image the culler draws and queries; 0
    // follows the oracle's resolution, so that false culls compare like with like.
    int resolution = 0;
    // Section 3.1's threshold: an object's BSP leaf holds at most this many
    // triangle pieces; an object (mesh) with no more triangles gets no tree.
    int leaf_triangles = 256;
    // Section 3.2: a scene node holding more objects than this is split.
    int node_objects = 4;
    // Section 3.2's lazy reconstruction: frames before a scene node out of
    // shape is rebuilt; < 0: never.
    int rebuild_delay = 8;
    // Algorithm 3: after a query answers visible, the query is skipped for as
    // many frames as there were visible answers among the last `history`
    // queries of the node; 0: no skipping (a query every frame).
    int history = 8;
    // 1: each skip is lengthened by a pseudo-random 0 to half of itself, so
    // that nodes that turned visible together (every node at the first frame,
    // a whole region after a turn) do not all come due for their queries in
    // the same frame; 0: Figure 3's count alone.
    int skip_spread = 1;
    // Algorithm 2: the most queries issued in one batch (of non-overlapping
    // screen rectangles) before their answers are read.
    int batch = 64;
    // Section 3.4's shrunk boxes: a scene node whose contents have not changed
    // for this many frames is queried on the box of its objects instead of its
    // cell; < 0: never (object-tree nodes, whose contents never change, are
    // queried on their triangles' bounds whenever this is >= 0).
    int shrink_delay = 4;
};

const KnobTable<BspOqOptions>& bspOqKnobs();

}  // namespace gridcull
