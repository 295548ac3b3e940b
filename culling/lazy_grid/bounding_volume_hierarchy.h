// A hierarchy of axis-aligned bounding boxes over a 3D scene's objects, for the
// lazy occlusion grid's front-to-back traversal (Hey, Tobler & Purgathofer,
// sections 4 and 7: "a hierarchy of axis-aligned bounding boxes ... built
// initially for the given set of primitive objects"; in their forest "each tree
// is a primitive object with an own bounding box").
//
// Built top down: a node's objects are split at the median of their box centres
// along the longest axis of those centres, until a node holds at most
// max_leaf_objects (default 1: every object its own box, as in the forest).
// Nodes are stored in pre-order (a child's index is larger than its parent's), so
// refitting is one backward pass.
//
// Moving objects: update(t) refits every box to the objects' bounds at t
// (Scene::boundsAt). Refitting keeps the tree valid but lets boxes grow as
// objects drift apart, so when the summed surface area of all boxes exceeds
// kRebuildGrowth times its value right after the last build, the tree is rebuilt
// from the positions at t. A scene without moving objects is never refitted.
//
// No allocation after the first build of a scene (capacities are 2n - 1 nodes).
#pragma once
#include <cstdint>
#include <vector>

#include "culling/scene/scene.h"

namespace gridcull {

struct BvhNode {
    Aabb box;
    int32_t left = -1, right = -1;  // children; -1 in a leaf
    int32_t parent = -1;
    int32_t first = 0, count = 0;  // a leaf's objects: objectOrder()[first .. first + count)
    bool isLeaf() const { return left < 0; }
};

class BoundingVolumeHierarchy {
public:
    static constexpr double kRebuildGrowth = 1.5;

    // Builds over every object of `scene` at time t.
    void build(const Scene& scene, double t, int max_leaf_objects = 1);
    // Refits to time t, rebuilding when refitting has made the boxes too loose.
    // Returns true when it rebuilt.
    bool update(const Scene& scene, double t);

    bool empty() const { return nodes_.empty(); }
    const std::vector<BvhNode>& nodes() const { return nodes_; }
    const std::vector<int32_t>& objectOrder() const { return order_; }  // object indices
    // The leaf holding object index i.
    int32_t leafOf(int object_index) const { return leaf_of_[size_t(object_index)]; }
    // Sum of the surface areas of all boxes: the looseness that triggers a rebuild.
    double surfaceAreaSum() const;
    int rebuilds() const { return rebuilds_; }

private:
    int32_t buildNode(int32_t parent, int32_t first, int32_t count);
    void refit();

    int max_leaf_objects_ = 1;
    bool dynamic_ = false;
    std::vector<BvhNode> nodes_;
    std::vector<int32_t> order_;
    std::vector<int32_t> leaf_of_;
    std::vector<Aabb> object_bounds_;  // per object index, at the last build / update
    double area_after_build_ = 0.0;
    int rebuilds_ = 0;
};

}  // namespace gridcull
