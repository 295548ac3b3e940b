// Twice the signed area of a polygon in the x-y plane (the shoelace sum): positive
// for counter-clockwise order, negative for clockwise, zero for no area. z is
// ignored. Cost: O(n).
#pragma once
#include <vector>

#include <glm/vec3.hpp>

namespace gridcull {

inline double signedDoubleArea(const std::vector<glm::dvec3>& points) {
    double sum = 0.0;
    const size_t n = points.size();
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3& p = points[i];
        const glm::dvec3& q = points[(i + 1) % n];
        sum += p.x * q.y - q.x * p.y;
    }
    return sum;
}

}  // namespace gridcull
