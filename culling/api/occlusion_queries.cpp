// The rule every occlusion-query target shares (culling/api/occlusion_queries.h):
// which boxes answer visible without being rasterized.
#include "culling/api/occlusion_queries.h"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

namespace gridcull {

bool occlusionQueryTriviallyVisible(const Camera& camera, const Aabb& box) {
    if (box.contains(camera.position)) return true;
    glm::dvec3 right, up, forward;
    camera.basis(right, up, forward);
    double z_min = std::numeric_limits<double>::infinity(), z_max = -z_min;
    for (int i = 0; i < 8; ++i) {
        const double z = glm::dot(box.corner(i) - camera.position, forward);
        z_min = std::min(z_min, z);
        z_max = std::max(z_max, z);
    }
    return z_min < camera.near && z_max >= camera.near;
}

}  // namespace gridcull
