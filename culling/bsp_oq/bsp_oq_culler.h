// `bsp-oq`, `bsp-oq-simple` and `bsp-vfc`: J. Kovalčík, J. Sochor, "Fast
// rendering of complex dynamic scenes", section 3 (Algorithm 1): a
// scene tree (3.2, scene_bsp.h) whose nodes hold objects, complex objects
// with BSP trees of their own (3.1, object_bsp.h), both traversed front to
// back (3.3), each node's visibility estimated before its contents are drawn
// (3.4, Algorithms 2 to 4) with occlusion queries on an ImageTarget
// (culling/api/image_target.h: the shared software rasterizer, or OpenGL's
// GL_ANY_SAMPLES_PASSED).
//
// A frame (Algorithm 2). The active nodes are a stack whose top is the
// nearest node still to process, so that "the list is sorted approximately by
// the distance from the viewer". Its top is given FirstVisibilityTest
// (Algorithm 3), which says, in order:
//   Invisible   a node with nothing to draw, or whose box is outside the
//               frustum (Full: or projects between every pixel centre);
//   Visible     the eye is in its box, or the box crosses the near plane
//               (occlusionQueryTriviallyVisible: a query cannot be drawn);
//   NeedQuery   it was not visible last frame;
//   Visible     it was, and its query is still postponed: after a query answers
//               visible, the query is skipped for as many frames as there were
//               visible answers among the node's last `history` queries
//               (Figure 3; bspSkipFrames), lengthened by up to half with
//               `skip_spread` (bspSpreadSkip);
//   NeedQuery   otherwise.
// A NeedQuery node joins the current batch if its query box's screen
// rectangle overlaps neither a rectangle of the batch nor one of a node already
// waiting; otherwise it waits ("nodes with overlapping projections have to
// wait until the results of previous queries are returned") and the nodes
// under it on the stack go on. When the batch holds `batch` queries, or as
// many nodes wait, or the stack is empty, the waiting nodes go back on the
// stack in their order, the batch's answers are read, each visible node is
// processed (last issued first, so the nearest ends on top), and a new batch
// begins. A Visible node is processed at once
// (ProcessVisibleNode, Algorithm 4): a scene node draws its objects without a
// tree (each one tested against the frustum) and puts its near child, its
// objects with trees (their roots, by centroid distance) and its far child on
// the stack, nearest on top; an object node puts its children (a leaf: draws
// its triangles, one "object part").
//
// Modes (section 4): Full (`bsp-oq`) as above, with shrunk query boxes: a
// scene node whose contents did not change for `shrink_delay` frames is
// queried on the box of its objects, an object node on its triangles' bounds.
// Simple OC (`bsp-oq-simple`): "does not issue occlusion queries in parallel
// and does not use the recent query results": every node in the frustum is
// queried, one query at a time, on its cell. VFC only (`bsp-vfc`): every node
// in the frustum is drawn.
//
// The PVS is every object drawn, whole or in part. It is conservative: a node
// is dropped only outside the frustum, with nothing in it, or when its query
// says no pixel centre sees its box nearer than what was drawn; and what was
// drawn is a subset of the scene's surfaces at the oracle's pixel centres
// (the same rasterizer at the same resolution), so at a pixel where the
// oracle sees an object nothing drawn is nearer than the object. Nothing
// nearer is not enough for a box that is only as near: the depth test is
// strict, and a box of a node's objects (shrunk, or an object part's bounds)
// has the objects' faces for its own, which tie with another object's face in
// the same plane (rooms' walls overlapping at a corner); the oracle gives a
// tied pixel to whichever it drew first, the culler may have drawn the other.
// So every box a node is tested on is grown by a margin (about 1e-9 of its
// coordinates, bsp_oq_culler.cpp), which makes it strictly nearer there than
// anything it holds.
//
// Departures from the paper, and why:
// - The transform of an object's tree is a translation: scenes move objects
//   rigidly by translation (object_bsp.h), and copies of a mesh share a tree.
// - An object gets a tree when its mesh has more triangles than one leaf may
//   hold (the paper's TooComplex, which it leaves unspecified).
// - A node whose box contains the eye or crosses the near plane is visible
//   without a query, in every mode (the paper's ViewerInside): a box cut by the
//   near plane cannot be drawn as a query. The count of queries leaves these
//   out in every mode.
// - The rule of Figure 3 is ours: the paper shows a curve without numbers.
//   Its spread is ours too: without it every node that answered visible in
//   the same frame comes due in the same frames (1, 3, 6, 10, ... after the
//   first frame: the query count's spikes and the frame-time stalls of
//   docs/results/bsp-oq.md's first run).
// - Objects without trees in a visible scene node are tested against the
//   frustum one by one before they are drawn (the paper renders them), in
//   every mode, so that VFC only draws what its name says.
// - "Contents not changed for several frames" is tracked per scene node: a
//   moving object marks the nodes on its old and new path to the root.
// - Every box a node is tested on (cell, shrunk box or part bounds) is grown
//   by about 1e-9 of its coordinates (the paper queries the box itself): a
//   box as near as its objects loses the strict depth test to a surface drawn
//   flush with them, and the long sweep caught shrunk boxes dropping walls
//   seen only where they tie with another wall (tests/culling/bsp_oq/
//   bsp_oq_coplanar_test.cpp).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "culling/api/culler.h"
#include "culling/api/image_target.h"
#include "culling/bsp_oq/bsp_oq_options.h"
#include "culling/bsp_oq/bsp_oq_snapshot.h"
#include "culling/bsp_oq/object_bsp.h"
#include "culling/bsp_oq/scene_bsp.h"
#include "culling/raster/screen_mapping.h"

namespace gridcull {

// Figure 3's rule: frames a query is skipped after it answered visible, given
// the node's recent answers (bit 0 the latest, 1 visible) of which the last
// `history` count (0: none, no skipping; at most kMaxBspHistory).
int bspSkipFrames(uint32_t answers, int history);
// The skip lengthened by a spread in [0, skip / 2], a hash of `key` (the
// node's identity and the frame): deterministic, and different for nodes that
// answered visible together.
int bspSpreadSkip(int skip, uint64_t key);

class BspOqCuller final : public Culler {
public:
    // target: where to draw and query; null: the software rasterizer.
    BspOqCuller(std::string name, BspOqMode mode, const BspOqOptions& options,
                int reference_resolution, std::unique_ptr<ImageTarget> target = nullptr);
    const char* name() const override { return name_.c_str(); }
    void reset(const Scene& scene) override;
    void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) override;
    std::unique_ptr<Culler> clone() const override;

    void setDebugCapture(bool on) override { capture_ = on; }
    const DebugSnapshot* debugSnapshot() const override {
        return capture_ && snapshot_.valid ? &snapshot_ : nullptr;
    }
    const BspOqSnapshot& snapshot() const { return snapshot_; }

    // For tests: the structures as the last frame left them.
    const SceneBsp& sceneTree() const { return scene_tree_; }
    // Object i's tree, or null when it has none.
    const ObjectBsp* objectTree(int object) const;
    ImageTarget& target() { return *target_; }

private:
    enum class Estimate : uint8_t { Invisible, Visible, NeedQuery };
    // A node on the stack or in a batch: a scene node (object < 0) or node
    // `node` of object `object`'s tree.
    struct ActiveNode {
        int32_t object = -1;
        int32_t node = 0;
    };
    // What a node keeps between frames, and what this frame decided of it.
    struct NodeState {
        uint32_t answers = 0;  // recent query answers, bit 0 the latest
        int32_t answer_count = 0;
        int32_t skip = 0;            // frames the query is still postponed
        int64_t visible_frame = -1;  // the last frame it was found visible
        int64_t state_frame = -1;    // the frame `state` and `box` are from
        BspNodeState state = BspNodeState::NotReached;
        bool shrunk = false;
        int32_t query = -1;  // index into query_log_ (capture only)
        Aabb box;
        // The frame it was last estimated NeedQuery in, and its rectangle then:
        // a node waiting for a batch's answers is not estimated again.
        int64_t need_query_frame = -1;
        PixelRect rect;
    };
    struct SceneNodeState {
        NodeState node;
        uint32_t serial = 0;        // SceneBsp::nodeSerial it belongs to
        int64_t changed_frame = 0;  // the last frame its contents changed
        int64_t tight_frame = -1;   // the frame `tight` was computed
        Aabb tight;                 // the box of its subtree's objects
    };
    struct PendingQuery {
        ActiveNode node;
        OcclusionQuery query;
        PixelRect rect;
    };

    NodeState& stateOf(const ActiveNode& n);
    SceneNodeState& sceneState(int node);
    // Notes that `node` and its ancestors changed contents this frame.
    void markChanged(int node);
    void updateSceneTree(double t);
    // The box a node is tested on: contentBox grown by a margin (sets shrunk).
    Aabb testBox(const ActiveNode& n, bool& shrunk);
    // Its cell, or with shrunk boxes the bounds of what it holds (sets shrunk).
    Aabb contentBox(const ActiveNode& n, bool& shrunk);
    Aabb tightBox(int node);
    bool nodeEmpty(const ActiveNode& n) const;
    // Algorithm 3 (once a frame for a node that needs a query: a node that
    // waits for a batch keeps its estimate and rectangle).
    Estimate firstVisibilityTest(const ActiveNode& n, PixelRect& rect);
    Estimate estimateAfresh(const ActiveNode& n, NodeState& s, PixelRect& rect);
    void processVisibleNode(const ActiveNode& n);
    void drawObject(int index);
    void drawPart(int object, int node);
    void readBatch();
    // Algorithm 2's inner loop: estimates nodes from the top of the stack,
    // processing the visible ones, until the batch is full.
    void fillBatch(int batch_limit);
    void setState(NodeState& s, BspNodeState state);
    void fillSnapshot(const FrameResult& out);

    std::string name_;
    BspOqMode mode_;
    BspOqOptions options_;
    int resolution_;
    OwnedImageTarget target_;  // copied by clone(), null when it cannot be

    const Scene* scene_ = nullptr;
    const Camera* camera_ = nullptr;
    double t_ = 0.0;
    int64_t frame_ = 0;
    bool ready_ = false;
    ScreenMapping mapping_;
    SceneBsp scene_tree_;
    std::vector<Aabb> boxes_;  // every object's box at t
    std::vector<int> moved_;   // objects whose box changed this frame

    // Object trees: one per distinct mesh, shared by its copies.
    std::vector<std::shared_ptr<const ObjectBsp>> trees_;  // built by reset(), shared by clones
    std::vector<int> tree_handle_;         // by tree: its triangle set on the target
    std::vector<int> tree_of_;             // by object: index into trees_, -1: none
    std::vector<glm::dvec3> translation_;  // by object: its tree's translation at t
    std::vector<int> object_state_first_;  // by object: its nodes in object_states_
    std::vector<NodeState> object_states_;
    std::vector<SceneNodeState> scene_states_;  // by SceneBsp pool index

    std::vector<ActiveNode> stack_;
    std::vector<PendingQuery> pending_;
    std::vector<PendingQuery> waiting_;          // nodes whose query waits for the batch's answers
    std::vector<int> walk_;                      // tightBox's subtree walk
    std::vector<std::pair<double, int>> order_;  // a node's objects by distance
    std::vector<int64_t> drawn_frame_;           // by object: last frame it was drawn
    int32_t batch_ = 0;

    FrameResult* out_ = nullptr;
    int64_t nodes_tested_ = 0, queries_ = 0, queries_hidden_ = 0, skips_ = 0, parts_ = 0,
            triangles_ = 0, objects_tested_ = 0, batches_ = 0;

    bool capture_ = false;
    BspOqSnapshot snapshot_;
    std::vector<BspQueryRecord> query_log_;  // capture only
};

}  // namespace gridcull
