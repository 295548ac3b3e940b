// The scene tree: J. Kovalčík, J. Sochor, "Fast rendering of complex dynamic
// scenes", section 3.2 (scene partitioning), traversed as in section 3.3.
//
// "An axis-aligned BSP-like tree ... objects are not split, but only tied to a
// respective node. An object intersecting the splitting plane between two
// children of a node, is placed in the parent node. Consequently any object
// belongs exactly to one node, which is the smallest node denoting the subspace
// the object is fully contained in." Nodes store the boxes of their subspaces
// (cells) for visibility tests. Objects are named by dense non-negative ids
// (scene object indices) and given by their world boxes.
//
// Cells: the root's cell is params.world. A node split on axis a at s has a low
// child [min, s) on a and a high child [s, max] (the parent's faces on the
// other axes and the parent's openness of its max face on a for the high
// child): siblings are disjoint, so the nodes whose cells contain a box form
// one chain from the root and "the smallest node containing the box" is
// unique. A box touching s from below, or of zero thickness on s, goes high or
// stays in the parent accordingly (cellContains is the one predicate).
//
// Build (the paper: "constructed in a similar way" to the object trees of 3.1,
// which split "until a number of triangles in parts drops below threshold
// level"): a node holding more than max_node_objects objects, above
// max_depth, is split on its cell's longest axis at the median of its
// objects' box centroids; if that leaves a child with as many objects as the
// node, or puts the plane on the cell's boundary, the other axes are tried
// (longer first), and if none works the node stays a leaf. So the build ends on
// any input (coincident objects, objects larger than their cell). Every inner
// node has both children.
//
// Update (3.2: "the objects are tested with respect to space subdivision and
// if necessary, they are relinked to respective node moving thus up or down in
// the scene tree. Space subdivision is not changed."): relink() climbs from
// the object's node to the first ancestor whose cell contains the new box,
// then descends from there to the smallest node containing it.
// relinkFromRoot() is the plain alternative (find the object from the root,
// insert it from the root) for comparison; both end in the same node.
//
// Lazy reconstruction (3.2: "after several frames the scene subdivision tree is
// locally adjusted to reflect the dynamic changes"; the paper gives no rule,
// this is ours): a relink notes every node whose own or subtree object count it
// changed. A noted node is out of shape when the build would now make it
// differently by the count rule: a leaf above max_depth holding more than
// max_node_objects objects of its own (over-full), or an inner node whose
// subtree holds at most max_node_objects (under-full). A node found out of
// shape at frame f is rebuilt (its subtree's objects gathered, its descendants
// freed, the build run on its cell) at the end of the first update() at frame
// >= f + rebuild_delay_frames, if it is still out of shape then; a negative
// delay turns reconstruction off. The delay is the paper's "after several
// frames": objects that pass through a region do not make it rebuilt. Nodes are
// handled shallowest first, so an under-full ancestor absorbs its descendants'
// rebuilds. An over-full leaf that is unsplittable is tried again only after
// it changes again.
//
// Objects outside the world: a box not wholly inside the root's cell (partly
// or wholly outside, or with a NaN coordinate) is tied to the root and flagged
// outside (isOutside, outsideCount). The root's cell then does not bound its
// objects: a culler must not prune the root by its cell while outsideCount() >
// 0. Outside objects never go down, whatever the build or the lazy rebuild do.
//
// Traversal (3.3): "the child node closer to a camera is processed first, then
// the objects stored in the node and finally the child node further from the
// camera. The objects stored directly in the node are sorted by the distance of
// their bounding boxes' centroids from the camera." The closer child is the
// one whose side of the plane holds the eye (low when eye[a] < s). Ties in
// distance go by id; a non-finite distance (NaN or huge boxes) sorts last.
//
// Storage: nodes in a pool (a vector and a free list), objects' node links as
// intrusive lists in tables indexed by id, the list of noted nodes and the
// scratch arrays of rebuild and traversal sized by build()/reserve(): relink,
// update and traversal allocate nothing once the pool has grown to its
// high-water mark (reserve() can size it up front). Not thread-safe: the
// traversal sorts in a scratch array of the tree, and its visitors must not
// change the tree.
#pragma once
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/scene/scene.h"
#include "grid/aabb.h"

namespace gridcull {

constexpr int kMaxSceneBspDepth = 60;

struct SceneBspParams {
    Aabb world;                    // the root's cell, finite, min <= max
    int max_node_objects = 4;      // >= 1: the split threshold (see above)
    int max_depth = 24;            // in [0, kMaxSceneBspDepth]
    int rebuild_delay_frames = 8;  // frames before a node out of shape is rebuilt; < 0: never
};

// What one operation did.
struct SceneBspCost {
    int nodes_visited = 0;  // nodes read while finding an object's old and new node
    int nodes_created = 0;
    int nodes_freed = 0;
    int objects_relinked = 0;  // objects whose box changed (update only)
    int subtrees_rebuilt = 0;  // lazy reconstructions
    SceneBspCost& operator+=(const SceneBspCost& o) {
        nodes_visited += o.nodes_visited;
        nodes_created += o.nodes_created;
        nodes_freed += o.nodes_freed;
        objects_relinked += o.objects_relinked;
        subtrees_rebuilt += o.subtrees_rebuilt;
        return *this;
    }
};

// What the traversal shows of a node.
struct SceneBspNodeView {
    int id = 0;
    int depth = 0;
    Aabb cell;  // the subspace; the root's does not bound outside objects
    bool leaf = true;
    int object_count = 0;     // tied to this node
    int subtree_objects = 0;  // in its subtree, its own included
};

class SceneBsp {
public:
    static constexpr int kNone = -1;
    static constexpr int kRoot = 0;

    SceneBsp() = default;
    // A copy keeps the capacities of the original's pool and scratch lists,
    // which the update relies on to never allocate (and asserts).
    SceneBsp(const SceneBsp& other);
    SceneBsp& operator=(const SceneBsp&) = delete;
    // Builds the tree over objects 0..boxes.size()-1 (one box each, world
    // space). Keeps the memory of an earlier build. Cost: O(n log n * depth).
    void build(const SceneBspParams& params, const std::vector<Aabb>& boxes);
    // Makes room for `nodes` pool nodes, so that no operation within them
    // allocates. Call after build().
    void reserve(int nodes);
    const SceneBspParams& params() const { return params_; }

    // 3.2's relink: climb to the first ancestor containing `box`, descend.
    // O(height). `box` has min <= max per axis, or a NaN coordinate.
    SceneBspCost relink(int object, const Aabb& box);
    // The comparison: the old node found from the root, the new one from the root.
    SceneBspCost relinkFromRoot(int object, const Aabb& box);
    // One frame's changes: relinks every object whose box differs from the one
    // it was tied with (boxes.size() == objectCount()), then the lazy
    // reconstruction of the nodes due at `frame` (frames increase).
    SceneBspCost update(const std::vector<Aabb>& boxes, int frame);
    // The lazy reconstruction alone (update calls it).
    SceneBspCost rebuildDueNodes(int frame);

    int objectCount() const { return int(objects_.size()); }
    const Aabb& boxOf(int object) const { return record(object).box; }
    int nodeOf(int object) const { return record(object).node; }
    bool isOutside(int object) const { return record(object).outside; }
    int outsideCount() const { return outside_count_; }

    int nodeCount() const { return live_nodes_; }
    int poolSize() const { return int(nodes_.size()); }
    int poolCapacity() const { return int(nodes_.capacity()); }
    bool isLive(int node) const {
        return node >= 0 && node < poolSize() && nodes_[size_t(node)].live;
    }
    const Aabb& nodeCell(int node) const { return at(node).cell; }
    // Bit a set: the cell's max face on axis a is excluded (a low child's).
    int nodeOpenMax(int node) const { return at(node).open_max; }
    int nodeParent(int node) const { return at(node).parent; }
    int nodeLow(int node) const { return at(node).low; }
    int nodeHigh(int node) const { return at(node).high; }
    bool nodeIsLeaf(int node) const { return at(node).low == kNone; }
    int nodeAxis(int node) const { return at(node).axis; }
    double nodeSplit(int node) const { return at(node).split; }
    int nodeDepth(int node) const { return at(node).depth; }
    int nodeObjectCount(int node) const { return at(node).object_count; }
    int nodeSubtreeObjects(int node) const { return at(node).subtree_objects; }
    // Which allocation of its pool slot the node is (every allocNode numbers
    // anew): a culler keeping per-node state by index tells a rebuilt node from
    // the one that had its slot before.
    uint32_t nodeSerial(int node) const { return at(node).serial; }
    // fn(object id) for the objects tied to `node`, in no particular order.
    template <typename Fn>
    void forEachObjectOf(int node, Fn&& fn) const {
        for (int id = at(node).first_object; id != kNone; id = next_in_node_[size_t(id)]) fn(id);
    }
    // fn(node index) for every live node, in pool order.
    template <typename Fn>
    void forEachNode(Fn&& fn) const {
        for (int i = 0; i < poolSize(); ++i)
            if (nodes_[size_t(i)].live) fn(i);
    }
    // Is `box` wholly inside the node's cell (its open faces excluded)? False
    // for a box with a NaN coordinate.
    bool cellContains(int node, const Aabb& box) const;
    // Is the node out of shape by the count rule (see above)?
    bool outOfShape(int node) const;

    // 3.3: visit_node(const SceneBspNodeView&) returns false to skip the node
    // with its objects and subtree; visit_object(int id) gets each object of a
    // visited node, after the near child's subtree and before the far one's.
    // Allocates nothing.
    template <typename NodeVisitor, typename ObjectVisitor>
    void traverseFrontToBack(const glm::dvec3& eye, NodeVisitor&& visit_node,
                             ObjectVisitor&& visit_object) const {
        if (nodes_.empty()) return;
        visitNode(kRoot, eye, visit_node, visit_object);
    }

private:
    struct Node {
        Aabb cell;
        int open_max = 0;
        int parent = kNone;
        int low = kNone;
        int high = kNone;
        int axis = -1;
        double split = 0.0;
        int first_object = kNone;
        int object_count = 0;
        int subtree_objects = 0;
        int depth = 0;
        int noted_frame = -1;  // frame it was found out of shape, -1: not
        bool in_noted_list = false;
        bool live = false;
        uint32_t serial = 0;
        int next_free = kNone;
    };
    struct ObjectRecord {
        Aabb box;
        int node = kNone;
        bool outside = false;
    };

    const Node& at(int node) const {
        assert(isLive(node));
        return nodes_[size_t(node)];
    }
    Node& at(int node) {
        assert(isLive(node));
        return nodes_[size_t(node)];
    }
    const ObjectRecord& record(int object) const {
        assert(object >= 0 && object < objectCount());
        return objects_[size_t(object)];
    }
    int allocNode();
    void freeNode(int node);
    void attach(int node, int object);
    void detach(int object);
    // The smallest node at or below `node` (which contains the box) containing it.
    int descend(int node, const Aabb& box, SceneBspCost& cost) const;
    // Splits `node` over objects scratch_objects_[begin, end) (all in its
    // subtree, none attached) and ties them, recursively.
    void buildAt(int node, int begin, int end, SceneBspCost& cost);
    // Moves `object` from its node to `new_node`, fixing the subtree counts
    // below `top` (a common ancestor of both) and noting changed nodes.
    void move(int object, int new_node, int top, bool outside);
    void note(int node);
    void rebuildSubtree(int node, SceneBspCost& cost);

    template <typename NodeVisitor, typename ObjectVisitor>
    void visitNode(int i, const glm::dvec3& eye, NodeVisitor& visit_node,
                   ObjectVisitor& visit_object) const {
        const Node& n = nodes_[size_t(i)];
        const SceneBspNodeView view{
            i, n.depth, n.cell, n.low == kNone, n.object_count, n.subtree_objects};
        if (!visit_node(view)) return;
        if (n.low == kNone) {
            visitObjects(n, eye, visit_object);
            return;
        }
        const bool low_first = eye[n.axis] < n.split;
        visitNode(low_first ? n.low : n.high, eye, visit_node, visit_object);
        visitObjects(n, eye, visit_object);
        visitNode(low_first ? n.high : n.low, eye, visit_node, visit_object);
    }
    template <typename ObjectVisitor>
    void visitObjects(const Node& n, const glm::dvec3& eye, ObjectVisitor& visit_object) const {
        if (n.object_count == 0) return;
        assert(size_t(n.object_count) <= sort_scratch_.size());
        int count = 0;
        for (int id = n.first_object; id != kNone; id = next_in_node_[size_t(id)]) {
            const glm::dvec3 d = objects_[size_t(id)].box.center() - eye;
            double key = d.x * d.x + d.y * d.y + d.z * d.z;
            if (!std::isfinite(key)) key = HUGE_VAL;
            sort_scratch_[size_t(count++)] = {key, id};
        }
        assert(count == n.object_count);
        std::sort(sort_scratch_.begin(), sort_scratch_.begin() + count);
        for (int k = 0; k < count; ++k) visit_object(sort_scratch_[size_t(k)].second);
    }

    SceneBspParams params_;
    std::vector<Node> nodes_;
    int free_head_ = kNone;
    int live_nodes_ = 0;
    uint32_t serial_ = 0;
    std::vector<ObjectRecord> objects_;  // by id
    std::vector<int> next_in_node_;      // by id
    std::vector<int> prev_in_node_;
    int outside_count_ = 0;
    int frame_ = 0;                     // the frame of the current update
    std::vector<int> noted_;            // nodes noted out of shape (each once)
    std::vector<int> scratch_objects_;  // rebuild: the gathered objects
    std::vector<double> scratch_keys_;  // build: centroids for the median
    std::vector<int> scratch_nodes_;    // rebuild: the subtree walk
    mutable std::vector<std::pair<double, int>> sort_scratch_;  // traversal
};

// Every scene object's world box at time t, by index (Scene::boundsAt).
// Resizes `boxes` to the object count (no allocation once it has that size).
void objectBoxesAt(const Scene& scene, double t, std::vector<Aabb>& boxes);

}  // namespace gridcull
