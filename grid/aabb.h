// Axis-aligned box in world units. 2D scenes use the x-y plane and keep z = 0 in
// both corners, so one type serves both dimensions.
#pragma once
#include <glm/vec3.hpp>
#include <glm/common.hpp>

namespace gridcull {

struct Aabb {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};

    glm::dvec3 center() const { return (min + max) * 0.5; }
    glm::dvec3 extent() const { return max - min; }
    // Grows this box to contain `other`.
    void merge(const Aabb& other) {
        min = glm::min(min, other.min);
        max = glm::max(max, other.max);
    }
    Aabb translated(const glm::dvec3& offset) const { return {min + offset, max + offset}; }
    // Corner i in [0, 8): bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
    glm::dvec3 corner(int i) const {
        return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
    }
    bool contains(const glm::dvec3& p) const {
        return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y &&
               p.z <= max.z;
    }
};

}  // namespace gridcull
