// The dynamic octree T of octree-based dynamic scene occlusion culling:
// O. Sudarsky, C. Gotsman, "Dynamic scene occlusion culling" (IEEE TVCG 1999),
// section 4 (insertion, deletion, update under the least common ancestor, Figs.
// 5, 7 and 9) and section 3.3 (T holds the IDs of dynamic objects and TBVs), over
// the octree of Greene, Kass & Miller's hierarchical z-buffer (section 2.1.1).
//
// Each object (an object or its TBV: a box the caller names by a non-negative
// int id) is associated with exactly one node, the smallest octree node that
// wholly contains its box: the single primitive references of Fig. 9. Nodes are
// created when an insertion descends into them and freed when they hold no
// object and no child (the paper's collapse), so the set of nodes is exactly the
// union of the paths from the root to the objects' nodes, a function of the
// boxes alone: any order of insertions, deletions and updates that ends with the
// same boxes ends with the same tree.
//
// Descent: a node's children split it at its centre c (Aabb::center()) into
// octants, octant bit a set for the high half [c[a], max[a]] of axis a, clear for
// the low half [min[a], c[a]]. A box goes down into the child whose closed box
// contains it; a box lying in both halves of an axis (zero thickness on c[a])
// goes to the low half. It stays in a node when it straddles a split plane or
// when the node may not be split:
// - max_depth: the root has depth 0, and a node at max_depth has no children.
//   It bounds the tree's height, and so every operation's cost, whatever the
//   objects' sizes (a point-sized object would otherwise sink forever).
// - min_node_size (world units): a node has children only when their longest
//   side, half its own, is at least min_node_size. It stops the subdivision at
//   the scale below which a node is not worth a separate occlusion test (its
//   screen rectangle would be a few texels), independently of the scene's size;
//   0 leaves only max_depth.
//
// Update (Fig. 9): dissociate the object from its node v; climb from v, freeing
// the nodes left empty (collapse), until the first node on the new box's descent
// path, which is the least common ancestor (LCA) of the old and new positions;
// descend from there. updateFromRoot() is Fig. 5 (delete from the root, insert
// at the root) for comparison; both give the same tree (tests/culling/hzb_tbv/).
// Every operation returns the nodes it visited, created and freed.
//
// Objects outside the root: a box not wholly inside the root's box (partly or
// wholly outside it, or with a NaN coordinate) is associated with the root,
// flagged outside (isOutside, outsideCount). The root's box then does not bound
// its objects: a culler must not prune the root by its box while outsideCount()
// > 0 (or must test those objects on their own boxes).
//
// Front-to-back order (Greene et al.): traverseFrontToBack visits a node, then
// its existing children in octant order near ^ k for k = 0..7, near being the
// eye's octant: the eye's octant first, the opposite one last, and a child never
// after one it may hide (an octant can only hide one whose differing axes all
// lie farther from the eye). The visitor returns false to prune the subtree.
//
// Departures from the paper, and why:
// - Single references (Fig. 9), not the multiple references of Fig. 10: an
//   object lives in the one smallest node containing its box, not in every leaf
//   it intersects, so an update touches one node per end and a node's box bounds
//   its subtree's objects (outside objects apart). The hierarchical z-buffer
//   still tests every node and object on its box, which is all the culler needs.
// - Nodes are split wherever an object fits deeper (up to max_depth and
//   min_node_size), not when a node holds "too many primitives": the tree is
//   then canonical, which makes LCA update and delete + insert comparable node
//   for node.
// - The descent predicate on the climb is exact, not the closed "v contains
//   primitive" of Fig. 9: a node whose low face is a split plane crossed to its
//   high side refuses a box of zero thickness lying on that plane (the descent
//   sends it to the low side), so the climb stops exactly where the root descent
//   would pass.
//
// Storage: nodes in a pool (a vector and a free list), objects' node links as
// intrusive lists in a table indexed by id (its size is the largest id + 1, so
// ids should be dense, e.g. scene object indices), so steady updates allocate
// nothing once the pool and the id table have grown to their peak (reserve()
// sizes them up front). The octree is not thread-safe; the traversal's visitor must not change
// the tree.
#pragma once
#include <cassert>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "grid/aabb.h"

namespace gridcull {

struct OctreeParams {
    Aabb bounds;                 // the root's box (world units)
    int max_depth = 8;           // >= 0; the root is depth 0
    double min_node_size = 0.0;  // >= 0, world units (see above)
};

// What one operation did, for comparing LCA update with root update.
struct OctreeOpCost {
    int nodes_visited = 0;  // nodes read or written, each counted once per step
    int nodes_created = 0;
    int nodes_freed = 0;
};

// The ids of the objects of one node, in no particular order.
class OctreeObjectRange {
public:
    class Iterator {
    public:
        Iterator(const int* next, int id) : next_(next), id_(id) {}
        int operator*() const { return id_; }
        Iterator& operator++() {
            id_ = next_[id_];
            return *this;
        }
        bool operator==(const Iterator& other) const { return id_ == other.id_; }
        bool operator!=(const Iterator& other) const { return id_ != other.id_; }

    private:
        const int* next_;
        int id_;
    };
    OctreeObjectRange() = default;
    OctreeObjectRange(const int* next, int first, int count)
        : next_(next), first_(first), count_(count) {}
    Iterator begin() const { return {next_, first_}; }
    Iterator end() const { return {next_, -1}; }
    int size() const { return count_; }
    bool empty() const { return count_ == 0; }

private:
    const int* next_ = nullptr;
    int first_ = -1;
    int count_ = 0;
};

// What the front-to-back traversal shows of a node.
struct OctreeNodeView {
    int id = 0;  // the node's index (DynamicOctree::kRoot for the root)
    int depth = 0;
    Aabb box;  // the node's cell; does not bound outside objects (root only)
    int child_count = 0;
    OctreeObjectRange objects;
};

class DynamicOctree {
public:
    static constexpr int kNone = -1;
    static constexpr int kRoot = 0;

    explicit DynamicOctree(const OctreeParams& params = {});
    // Empties the tree for new params; keeps the pool's and the id table's memory.
    void reset(const OctreeParams& params);
    // Makes room for `nodes` nodes and ids in [0, objects), so that no operation
    // within them allocates.
    void reserve(int nodes, int objects);
    const OctreeParams& params() const { return params_; }

    // Each operation is O(tree height); the object must (insert: must not) be in
    // the tree. Boxes have min <= max on every axis.
    OctreeOpCost insert(int object, const Aabb& box);
    OctreeOpCost remove(int object);
    // Fig. 9: bottom-up, under the LCA of the old and new positions.
    OctreeOpCost update(int object, const Aabb& new_box);
    // Fig. 5: deletion searched down from the root along the old box, then
    // insertion from the root.
    OctreeOpCost updateFromRoot(int object, const Aabb& new_box);

    bool contains(int object) const {
        return object >= 0 && size_t(object) < objects_.size() &&
               objects_[size_t(object)].node != kNone;
    }
    const Aabb& boxOf(int object) const { return record(object).box; }
    int nodeOf(int object) const { return record(object).node; }
    bool isOutside(int object) const { return record(object).outside; }
    int objectCount() const { return object_count_; }
    int outsideCount() const { return outside_count_; }

    // Nodes, by index: live ones only (the root always is).
    int nodeCount() const { return live_nodes_; }
    // Live and free nodes together: what the pool has allocated.
    int poolSize() const { return int(nodes_.size()); }
    bool isLive(int node) const { return node >= 0 && node < poolSize() && at(node).live; }
    const Aabb& nodeBox(int node) const { return at(node).box; }
    int nodeDepth(int node) const { return at(node).depth; }
    int nodeParent(int node) const { return at(node).parent; }
    int nodeChild(int node, int octant) const { return at(node).children[octant]; }
    int nodeChildCount(int node) const { return at(node).child_count; }
    OctreeObjectRange nodeObjects(int node) const {
        return {next_in_node_.data(), at(node).first_object, at(node).object_count};
    }
    OctreeNodeView view(int node) const {
        const Node& n = at(node);
        return {node, n.depth, n.box, n.child_count, nodeObjects(node)};
    }

    // fn(node index) for every live node, in pool order.
    template <typename Fn>
    void forEachNode(Fn&& fn) const {
        for (int i = 0; i < poolSize(); ++i)
            if (nodes_[size_t(i)].live) fn(i);
    }

    // The octant of `box` (split at its centre) that `point` lies in; a point on
    // a split plane counts as low, as boxes do.
    static int octantOf(const glm::dvec3& point, const Aabb& box);

    // Pre-order, children front to back from `eye` (see above). visit(const
    // OctreeNodeView&) returns false to skip the node's subtree.
    template <typename Visitor>
    void traverseFrontToBack(const glm::dvec3& eye, Visitor&& visit) const {
        visitFrontToBack(kRoot, eye, visit);
    }

private:
    struct Node {
        Aabb box;
        int parent = kNone;
        int children[8] = {kNone, kNone, kNone, kNone, kNone, kNone, kNone, kNone};
        int child_count = 0;
        int first_object = kNone;
        int object_count = 0;
        int depth = 0;
        int octant = 0;    // in the parent
        int open_low = 0;  // bit a: the low face on axis a is a split plane crossed high
        int next_free = kNone;
        bool live = false;
    };
    struct ObjectRecord {
        Aabb box;
        int node = kNone;  // kNone: not in the tree
        bool outside = false;
    };

    const Node& at(int node) const {
        assert(isLiveIndex(node));
        return nodes_[size_t(node)];
    }
    bool isLiveIndex(int node) const {
        return node >= 0 && size_t(node) < nodes_.size() && nodes_[size_t(node)].live;
    }
    const ObjectRecord& record(int object) const {
        assert(contains(object));
        return objects_[size_t(object)];
    }
    bool fitsRoot(const Aabb& box) const;
    bool maySplit(const Node& node) const;
    // The child octant the descent takes from `node` for a box inside it, or kNone.
    static int descentOctant(const Node& node, const Aabb& box);
    // Does the root's descent for `box` pass through `node`?
    bool onDescentPath(int node, const Aabb& box) const;
    // Descends from `node` (on the box's path) to the object's node and attaches
    // it there; `node` itself is not counted as visited.
    void descendAndAttach(int node, int object, OctreeOpCost& cost);
    // Frees `node` and its ancestors while they hold nothing; the first node left
    // standing. Counts the freed nodes and, if count_parents, the parents reached.
    int collapseFrom(int node, OctreeOpCost& cost, bool count_parents);
    int createChild(int parent, int octant);
    void freeNode(int node);
    void attach(int node, int object);
    void detach(int object);

    template <typename Visitor>
    void visitFrontToBack(int node, const glm::dvec3& eye, Visitor& visit) const {
        const Node& n = nodes_[size_t(node)];
        if (!visit(view(node))) return;
        if (n.child_count == 0) return;
        const int near = octantOf(eye, n.box);
        for (int k = 0; k < 8; ++k) {
            const int child = n.children[near ^ k];
            if (child != kNone) visitFrontToBack(child, eye, visit);
        }
    }

    OctreeParams params_;
    std::vector<Node> nodes_;
    int free_head_ = kNone;
    int live_nodes_ = 0;
    std::vector<ObjectRecord> objects_;  // by id
    std::vector<int> next_in_node_;      // by id: the node's list of objects
    std::vector<int> prev_in_node_;
    int object_count_ = 0;
    int outside_count_ = 0;
};

}  // namespace gridcull
