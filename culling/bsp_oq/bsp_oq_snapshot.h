// What BSP culling with occlusion queries (`bsp-oq`, `bsp-oq-simple`,
// `bsp-vfc`; culling/bsp_oq/bsp_oq_culler.h) did in its last frame, for the
// window and for tests, in Kovalčík & Sochor's terms ("Fast rendering of
// complex dynamic scenes", sections 3.2 to 3.4, Algorithms 2 to 4):
//  - every live node of the scene tree, and every node of each object tree
//    the traversal reached, with the box it was tested on, what
//    FirstVisibilityTest or its query decided, its recent query results and
//    how many more frames its query is postponed;
//  - the occlusion queries of the frame in issue order, each with its screen
//    rectangle and its batch (a batch's rectangles never overlap);
//  - the frame's counters.
//
// Filled only while BspOqCuller::setDebugCapture(true), from the culler's own
// per-node records at the end of cull(): capture reads them and changes
// nothing, so the PVS is the same with it on or off. The vectors keep their
// capacity across frames. Object indices index Scene::objects.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "culling/api/counters.h"
#include "culling/api/debug_snapshot.h"
#include "culling/api/pixel_rect.h"
#include "grid/aabb.h"

namespace gridcull {

enum class BspOqMode : uint8_t {
    Full,    // `bsp-oq`: coherence, batches, shrunk boxes (the paper's "Full")
    Simple,  // `bsp-oq-simple`: a query for every node in the frustum ("Simple OC")
    Vfc,     // `bsp-vfc`: frustum culling of the trees only ("VFC only")
};

// What the frame decided about a node.
enum class BspNodeState : uint8_t {
    NotReached,      // skipped: an ancestor was culled, or the frame never came to it
    FrustumCulled,   // its box is outside the frustum, or between every pixel centre
    Empty,           // nothing in it to draw (a scene subtree with no object)
    ViewerInside,    // the eye is in its box, or its box crosses the near plane: visible
    InFrustum,       // `bsp-vfc`: in the frustum, drawn without a test
    AssumedVisible,  // visible last frame, its query postponed (temporal coherence)
    QueriedVisible,  // its occlusion query answered visible
    QueriedHidden,   // its occlusion query answered hidden: culled with its subtree
};
constexpr int kBspNodeStateCount = 8;

struct BspNodeRecord {
    Aabb box;              // the box it was tested on (shrunk or its cell), world units
    Aabb cell;             // its subspace (an object node's: moved with the object)
    int32_t node = 0;      // SceneBsp node index, or ObjectBsp node index
    int32_t object = -1;   // -1: a scene node; else the object whose tree holds it
    int32_t depth = 0;     // the root is 0
    int32_t contents = 0;  // scene node: objects in its subtree; object node: triangles
    BspNodeState state = BspNodeState::NotReached;
    bool leaf = false;
    bool shrunk = false;         // `box` is the shrunk box of its contents, not its cell
    uint32_t history = 0;        // recent query results, bit 0 the latest (1: visible)
    int32_t history_length = 0;  // valid bits of `history`
    int32_t skip = 0;            // frames its query is still postponed after this one
    int32_t query = -1;          // its query's index in BspOqSnapshot::queries, -1: none
};

struct BspQueryRecord {
    PixelRect rect;       // the query box's screen rectangle
    int32_t record = -1;  // the node: index in scene_nodes (object < 0) or object_nodes
    bool object_node = false;
    int32_t batch = 0;     // batches in issue order, from 0
    bool visible = false;  // the answer
};

struct BspOqSnapshot final : DebugSnapshot {
    static const DebugSnapshotKind kKind;
    BspOqSnapshot() : DebugSnapshot(kKind) {}

    bool valid = false;
    BspOqMode mode = BspOqMode::Full;
    int64_t frame = 0;  // frames culled since reset, the first is 1
    double t = 0.0;
    int width = 0;  // the image the culler drew and queried, pixels
    int height = 0;

    // The scene tree: every live node, in pool order.
    std::vector<BspNodeRecord> scene_nodes;
    // The object trees the traversal entered: the nodes of object i's tree are
    // object_nodes[object_first[i] .. + object_count[i]) in ObjectBsp order
    // (object_first[i] == -1: its tree was not entered, or it has none).
    std::vector<BspNodeRecord> object_nodes;
    std::vector<int32_t> object_first;
    std::vector<int32_t> object_count;
    std::vector<uint8_t> has_tree;  // by object index: 1 when the object has a BSP tree

    std::vector<BspQueryRecord> queries;
    int32_t batch_count = 0;

    std::array<int64_t, kBspNodeStateCount> state_count{};  // scene and object nodes
    CullStats stats;
};

const char* bspNodeStateName(BspNodeState state);
const char* bspOqModeName(BspOqMode mode);

}  // namespace gridcull
