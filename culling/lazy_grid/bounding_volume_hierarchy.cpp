#include "culling/lazy_grid/bounding_volume_hierarchy.h"

#include <algorithm>
#include <cassert>

namespace gridcull {

namespace {

double surfaceArea(const Aabb& box) {
    const glm::dvec3 e = glm::max(box.extent(), glm::dvec3(0.0));
    return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

}  // namespace

void BoundingVolumeHierarchy::build(const Scene& scene, double t, int max_leaf_objects) {
    assert(max_leaf_objects >= 1);
    max_leaf_objects_ = max_leaf_objects;
    const size_t n = scene.objects.size();
    dynamic_ = false;
    object_bounds_.resize(n);
    order_.resize(n);
    leaf_of_.resize(n);
    for (size_t i = 0; i < n; ++i) {
        object_bounds_[i] = scene.boundsAt(scene.objects[i], t);
        order_[i] = int32_t(i);
        dynamic_ = dynamic_ || scene.objects[i].isDynamic();
    }
    nodes_.clear();
    nodes_.reserve(n == 0 ? 0 : 2 * n - 1);
    if (n > 0) buildNode(-1, 0, int32_t(n));
    area_after_build_ = surfaceAreaSum();
}

int32_t BoundingVolumeHierarchy::buildNode(int32_t parent, int32_t first, int32_t count) {
    const int32_t index = int32_t(nodes_.size());
    assert(nodes_.size() < nodes_.capacity() && "build() reserves every node");
    nodes_.push_back(BvhNode{});
    BvhNode node;
    node.parent = parent;
    node.first = first;
    node.count = count;
    node.box = object_bounds_[size_t(order_[size_t(first)])];
    Aabb centres{node.box.center(), node.box.center()};
    for (int32_t k = first + 1; k < first + count; ++k) {
        const Aabb& b = object_bounds_[size_t(order_[size_t(k)])];
        node.box.merge(b);
        centres.merge({b.center(), b.center()});
    }
    if (count <= max_leaf_objects_) {
        for (int32_t k = first; k < first + count; ++k) leaf_of_[size_t(order_[size_t(k)])] = index;
        nodes_[size_t(index)] = node;
        return index;
    }
    const glm::dvec3 e = centres.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const int32_t half = count / 2;
    auto begin = order_.begin() + first;
    // Ties broken by index, so the tree does not depend on nth_element's order.
    std::nth_element(begin, begin + half, begin + count, [&](int32_t a, int32_t b) {
        const double ca = object_bounds_[size_t(a)].center()[axis];
        const double cb = object_bounds_[size_t(b)].center()[axis];
        return ca < cb || (ca == cb && a < b);
    });
    node.left = buildNode(index, first, half);
    node.right = buildNode(index, first + half, count - half);
    nodes_[size_t(index)] = node;
    return index;
}

void BoundingVolumeHierarchy::refit() {
    for (size_t k = nodes_.size(); k-- > 0;) {
        BvhNode& node = nodes_[k];
        if (node.isLeaf()) {
            node.box = object_bounds_[size_t(order_[size_t(node.first)])];
            for (int32_t j = node.first + 1; j < node.first + node.count; ++j)
                node.box.merge(object_bounds_[size_t(order_[size_t(j)])]);
        } else {
            node.box = nodes_[size_t(node.left)].box;
            node.box.merge(nodes_[size_t(node.right)].box);
        }
    }
}

bool BoundingVolumeHierarchy::update(const Scene& scene, double t) {
    if (!dynamic_ || nodes_.empty()) return false;
    assert(object_bounds_.size() == scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].isDynamic()) object_bounds_[i] = scene.boundsAt(scene.objects[i], t);
    refit();
    if (surfaceAreaSum() <= kRebuildGrowth * area_after_build_) return false;
    nodes_.clear();  // capacity stays: no allocation
    buildNode(-1, 0, int32_t(scene.objects.size()));
    area_after_build_ = surfaceAreaSum();
    ++rebuilds_;
    return true;
}

double BoundingVolumeHierarchy::surfaceAreaSum() const {
    double sum = 0.0;
    for (const BvhNode& node : nodes_) sum += surfaceArea(node.box);
    return sum;
}

}  // namespace gridcull
