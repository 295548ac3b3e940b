// The geometry of a regular grid (Batagelo & Wu, section 3): a world box cut into
// resolution.x * resolution.y * resolution.z equal voxels. Voxel (i,j,k) covers
// [min + i*d, min + (i+1)*d) per axis with d = (max - min) / resolution.
// A 2D grid has resolution.z == 1 and a world box with min.z == max.z == 0.
#pragma once
#include <cstdint>
#include <string>

#include <glm/vec3.hpp>

#include "grid/aabb.h"

namespace gridcull {

// The memory budget of one grid: the largest voxel count that the scene format
// accepts. The regular-grid culler keeps a few bits per voxel plus sparse lists,
// so 2^26 voxels (1024x1024 in 2D is 2^20, 256^3 in 3D is 2^24) stays under a
// few hundred MiB with every matrix allocated.
constexpr int64_t kMaxGridVoxels = int64_t(1) << 26;

struct RegularGrid {
    int dimensions = 3;             // 2 or 3
    Aabb world;                     // the box the voxels tile
    glm::ivec3 resolution{1, 1, 1}; // voxels per axis, z == 1 in 2D

    glm::dvec3 voxelSize() const;
    int64_t voxelCount() const;
    // The voxel that contains p; may lie outside [0, resolution) when p is outside.
    glm::ivec3 voxelOf(const glm::dvec3& p) const;
    bool inside(const glm::ivec3& v) const;
    Aabb voxelBounds(const glm::ivec3& v) const;
    // Row-major index of an inside voxel: x fastest, then y, then z.
    int64_t linearIndex(const glm::ivec3& v) const;
};

// Checks a resolution against kMaxGridVoxels before anything is allocated.
// Returns an empty string when it fits, else why it does not.
std::string checkResolution(int dimensions, const glm::ivec3& resolution);

}  // namespace gridcull
