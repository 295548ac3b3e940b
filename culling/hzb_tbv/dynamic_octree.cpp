// The dynamic octree of Sudarsky & Gotsman, "Dynamic scene occlusion culling",
// section 4, Figs. 5, 7 and 9. dynamic_octree.h says how it departs from the
// paper (single references, canonical splitting, the exact descent predicate).
#include "culling/hzb_tbv/dynamic_octree.h"

#include <algorithm>

namespace gridcull {

namespace {

bool wellFormed(const Aabb& box) {  // NaN passes: such a box goes to the root
    for (int a = 0; a < 3; ++a)
        if (box.min[a] > box.max[a]) return false;
    return true;
}

}  // namespace

DynamicOctree::DynamicOctree(const OctreeParams& params) {
    reset(params);
}

void DynamicOctree::reset(const OctreeParams& params) {
    assert(params.max_depth >= 0 && params.min_node_size >= 0.0);
    assert(wellFormed(params.bounds));
    params_ = params;
    nodes_.clear();
    Node root;
    root.box = params.bounds;
    root.live = true;
    nodes_.push_back(root);
    free_head_ = kNone;
    live_nodes_ = 1;
    objects_.clear();
    next_in_node_.clear();
    prev_in_node_.clear();
    object_count_ = 0;
    outside_count_ = 0;
}

void DynamicOctree::reserve(int nodes, int objects) {
    nodes_.reserve(size_t(std::max(nodes, 1)));
    if (size_t(objects) > objects_.size()) {
        objects_.resize(size_t(objects));
        next_in_node_.resize(size_t(objects), kNone);
        prev_in_node_.resize(size_t(objects), kNone);
    }
}

int DynamicOctree::octantOf(const glm::dvec3& point, const Aabb& box) {
    const glm::dvec3 c = box.center();
    return (point.x > c.x ? 1 : 0) | (point.y > c.y ? 2 : 0) | (point.z > c.z ? 4 : 0);
}

bool DynamicOctree::fitsRoot(const Aabb& box) const {
    const Aabb& root = params_.bounds;
    for (int a = 0; a < 3; ++a)
        if (!(box.min[a] >= root.min[a] && box.max[a] <= root.max[a])) return false;
    return true;
}

bool DynamicOctree::maySplit(const Node& node) const {
    if (node.depth >= params_.max_depth) return false;
    const glm::dvec3 e = node.box.extent();
    return std::max({e.x, e.y, e.z}) * 0.5 >= params_.min_node_size;
}

int DynamicOctree::descentOctant(const Node& node, const Aabb& box) {
    const glm::dvec3 c = node.box.center();
    int octant = 0;
    for (int a = 0; a < 3; ++a) {
        if (box.max[a] <= c[a]) continue;  // low half; a box on the plane goes low too
        if (box.min[a] >= c[a])
            octant |= 1 << a;
        else
            return kNone;  // straddles the split plane
    }
    return octant;
}

// The descent goes low on axis a where box.max <= c and high where box.min >= c
// and box.max > c. Along a path the low planes only decrease and the high ones
// only increase, the node's max (min) being the last low (high) plane, so the
// whole path's tests reduce to closed containment in the node plus, if the path
// ever went high on axis a, box.max > the node's min.
bool DynamicOctree::onDescentPath(int node, const Aabb& box) const {
    if (node == kRoot) return true;
    const Node& n = at(node);
    for (int a = 0; a < 3; ++a) {
        if (!(box.min[a] >= n.box.min[a] && box.max[a] <= n.box.max[a])) return false;
        if (((n.open_low >> a) & 1) && !(box.max[a] > n.box.min[a])) return false;
    }
    return true;
}

void DynamicOctree::descendAndAttach(int node, int object, OctreeOpCost& cost) {
    const Aabb box = objects_[size_t(object)].box;
    int v = node;
    const bool outside = v == kRoot && !fitsRoot(box);
    while (!outside) {
        if (!maySplit(nodes_[size_t(v)])) break;
        const int octant = descentOctant(nodes_[size_t(v)], box);
        if (octant == kNone) break;
        int child = nodes_[size_t(v)].children[octant];
        if (child == kNone) {
            child = createChild(v, octant);
            ++cost.nodes_created;
        }
        v = child;
        ++cost.nodes_visited;
    }
    objects_[size_t(object)].outside = outside;
    if (outside) ++outside_count_;
    attach(v, object);
}

int DynamicOctree::collapseFrom(int node, OctreeOpCost& cost, bool count_parents) {
    int v = node;
    while (v != kRoot) {
        const Node& n = nodes_[size_t(v)];
        if (n.object_count > 0 || n.child_count > 0) break;
        const int parent = n.parent;
        freeNode(v);
        ++cost.nodes_freed;
        v = parent;
        if (count_parents) ++cost.nodes_visited;
    }
    return v;
}

OctreeOpCost DynamicOctree::insert(int object, const Aabb& box) {
    assert(object >= 0 && !contains(object) && wellFormed(box));
    if (size_t(object) >= objects_.size()) {
        objects_.resize(size_t(object) + 1);
        next_in_node_.resize(size_t(object) + 1, kNone);
        prev_in_node_.resize(size_t(object) + 1, kNone);
    }
    objects_[size_t(object)].box = box;
    OctreeOpCost cost;
    cost.nodes_visited = 1;  // the root
    descendAndAttach(kRoot, object, cost);
    ++object_count_;
    return cost;
}

OctreeOpCost DynamicOctree::remove(int object) {
    const int node = nodeOf(object);
    detach(object);
    --object_count_;
    OctreeOpCost cost;
    cost.nodes_visited = 1;
    collapseFrom(node, cost, true);
    return cost;
}

OctreeOpCost DynamicOctree::update(int object, const Aabb& new_box) {
    assert(wellFormed(new_box));
    int v = nodeOf(object);
    detach(object);  // dissociate(v, primitive)
    objects_[size_t(object)].box = new_box;
    OctreeOpCost cost;
    cost.nodes_visited = 1;
    // Climb to the LCA, collapsing the nodes left empty on the way.
    while (!onDescentPath(v, new_box)) {
        const Node& n = nodes_[size_t(v)];
        const int parent = n.parent;
        if (n.object_count == 0 && n.child_count == 0) {
            freeNode(v);
            ++cost.nodes_freed;
        }
        v = parent;
        ++cost.nodes_visited;
    }
    descendAndAttach(v, object, cost);  // insert(v, primitive)
    return cost;
}

OctreeOpCost DynamicOctree::updateFromRoot(int object, const Aabb& new_box) {
    assert(wellFormed(new_box));
    const int node = nodeOf(object);
    const Aabb old_box = boxOf(object);
    OctreeOpCost cost;
    // delete(octree, primitive): search down from the root as a tree without
    // back pointers would, then merge the emptied nodes on the way back up.
    cost.nodes_visited = 1;
    for (int v = kRoot; v != node;) {
        const int octant = descentOctant(nodes_[size_t(v)], old_box);
        assert(octant != kNone);
        v = nodes_[size_t(v)].children[octant];
        assert(v != kNone);
        ++cost.nodes_visited;
    }
    detach(object);
    collapseFrom(node, cost, false);  // its nodes were counted on the way down
    // insert(octree, primitive)
    objects_[size_t(object)].box = new_box;
    ++cost.nodes_visited;  // the root again
    descendAndAttach(kRoot, object, cost);
    return cost;
}

int DynamicOctree::createChild(int parent, int octant) {
    int child;
    if (free_head_ != kNone) {
        child = free_head_;
        free_head_ = nodes_[size_t(child)].next_free;
    } else {
        child = int(nodes_.size());
        nodes_.emplace_back();
    }
    Node& p = nodes_[size_t(parent)];
    Node fresh;
    const glm::dvec3 mid = p.box.center();
    for (int a = 0; a < 3; ++a) {
        const bool high = (octant >> a) & 1;
        fresh.box.min[a] = high ? mid[a] : p.box.min[a];
        fresh.box.max[a] = high ? p.box.max[a] : mid[a];
    }
    fresh.parent = parent;
    fresh.depth = p.depth + 1;
    fresh.octant = octant;
    fresh.open_low = p.open_low | octant;
    fresh.live = true;
    nodes_[size_t(child)] = fresh;
    p.children[octant] = child;
    ++p.child_count;
    ++live_nodes_;
    return child;
}

void DynamicOctree::freeNode(int node) {
    Node& n = nodes_[size_t(node)];
    assert(node != kRoot && n.live && n.object_count == 0 && n.child_count == 0);
    Node& p = nodes_[size_t(n.parent)];
    p.children[n.octant] = kNone;
    --p.child_count;
    n.live = false;
    n.next_free = free_head_;
    free_head_ = node;
    --live_nodes_;
}

void DynamicOctree::attach(int node, int object) {
    Node& n = nodes_[size_t(node)];
    prev_in_node_[size_t(object)] = kNone;
    next_in_node_[size_t(object)] = n.first_object;
    if (n.first_object != kNone) prev_in_node_[size_t(n.first_object)] = object;
    n.first_object = object;
    ++n.object_count;
    objects_[size_t(object)].node = node;
}

void DynamicOctree::detach(int object) {
    ObjectRecord& r = objects_[size_t(object)];
    Node& n = nodes_[size_t(r.node)];
    const int prev = prev_in_node_[size_t(object)];
    const int next = next_in_node_[size_t(object)];
    if (prev != kNone)
        next_in_node_[size_t(prev)] = next;
    else
        n.first_object = next;
    if (next != kNone) prev_in_node_[size_t(next)] = prev;
    --n.object_count;
    if (r.outside) --outside_count_;
    r.outside = false;
    r.node = kNone;
}

}  // namespace gridcull
