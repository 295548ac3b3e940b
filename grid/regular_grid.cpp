#include "grid/regular_grid.h"

#include <cassert>
#include <cmath>

namespace gridcull {

glm::dvec3 RegularGrid::voxelSize() const {
    glm::dvec3 size = (world.max - world.min) / glm::dvec3(resolution);
    if (dimensions == 2) size.z = 1.0;  // a 2D grid is one voxel deep by convention
    return size;
}

int64_t RegularGrid::voxelCount() const {
    return int64_t(resolution.x) * int64_t(resolution.y) * int64_t(resolution.z);
}

glm::ivec3 RegularGrid::voxelOf(const glm::dvec3& p) const {
    const glm::dvec3 rel = (p - world.min) / voxelSize();
    glm::ivec3 v;
    for (int axis = 0; axis < 3; ++axis) {
        // Clamp before the cast: a point far outside must not overflow an int,
        // and a NaN (a degenerate grid or point) must not reach the cast either.
        const double f = std::floor(rel[axis]);
        v[axis] = !(f >= -1e9) ? -1000000000 : f > 1e9 ? 1000000000 : int(f);
    }
    if (dimensions == 2) v.z = 0;
    return v;
}

bool RegularGrid::inside(const glm::ivec3& v) const {
    return v.x >= 0 && v.y >= 0 && v.z >= 0 && v.x < resolution.x && v.y < resolution.y &&
           v.z < resolution.z;
}

Aabb RegularGrid::voxelBounds(const glm::ivec3& v) const {
    const glm::dvec3 d = voxelSize();
    Aabb box{world.min + glm::dvec3(v) * d, world.min + glm::dvec3(v + 1) * d};
    if (dimensions == 2) box.min.z = box.max.z = 0.0;
    return box;
}

int64_t RegularGrid::linearIndex(const glm::ivec3& v) const {
    assert(inside(v));
    return (int64_t(v.z) * resolution.y + v.y) * resolution.x + v.x;
}

std::string checkResolution(int dimensions, const glm::ivec3& resolution) {
    const int axes = dimensions == 2 ? 2 : 3;
    int64_t count = 1;
    for (int axis = 0; axis < axes; ++axis) {
        if (resolution[axis] < 1) return "must be integers >= 1";
        count *= resolution[axis];
        if (count > kMaxGridVoxels)
            return "grid of more than " + std::to_string(kMaxGridVoxels) +
                   " voxels is beyond the memory budget";
    }
    return {};
}

}  // namespace gridcull
