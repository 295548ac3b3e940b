// The voxel under the pointer in a 3D scene, for the rgvc view: the pointer's
// ray (ui/family_view.h's ViewPointer) walked voxel by voxel through the grid
// (Amanatides & Woo's traversal), and the occluder a click on a voxel picks.
//
// Which voxel: what the overlay shows under the pointer.
//  - Boxes: the first voxel along the ray drawn as a box (rgvcBoxKindAt); when
//    the ray meets none, the first voxel the traversal visited.
//  - Slice: the voxel of the slice where the ray crosses the slice's plane.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec3.hpp>

#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/rgvc/rgvc_frame_index.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {

// Calls hit(voxel) for each grid voxel the ray from `origin` along `direction`
// passes, in order, until it returns true; returns whether one did (its voxel
// in `out`). O(voxels passed).
template <typename Hit>
bool rgvcFirstVoxelOnRay(const RegularGrid& grid, const glm::dvec3& origin,
                         const glm::dvec3& direction, Hit&& hit, glm::ivec3& out) {
    const Aabb& w = grid.world;
    const glm::dvec3 d = grid.voxelSize();
    // Where the ray enters the world box (slabs), if it does.
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (direction[a] == 0.0) {
            if (origin[a] < w.min[a] || origin[a] > w.max[a]) return false;
            continue;
        }
        double ta = (w.min[a] - origin[a]) / direction[a];
        double tb = (w.max[a] - origin[a]) / direction[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (t0 > t1) return false;
    const glm::dvec3 start = origin + direction * t0;
    glm::ivec3 v, step;
    glm::dvec3 next, delta;
    for (int a = 0; a < 3; ++a) {
        step[a] = direction[a] > 0.0 ? 1 : (direction[a] < 0.0 ? -1 : 0);
        // On a voxel boundary, the voxel the ray goes into.
        double f = (start[a] - w.min[a]) / d[a];
        if (step[a] < 0 && f == std::floor(f)) f -= 0.5;
        v[a] = std::clamp(int(std::floor(f)), 0, grid.resolution[a] - 1);
        const double edge = w.min[a] + (v[a] + (step[a] > 0 ? 1 : 0)) * d[a];
        next[a] = step[a] == 0 ? std::numeric_limits<double>::infinity()
                               : (edge - origin[a]) / direction[a];
        delta[a] =
            step[a] == 0 ? std::numeric_limits<double>::infinity() : d[a] / std::abs(direction[a]);
    }
    while (true) {
        if (hit(v)) {
            out = v;
            return true;
        }
        const int a = next.x < next.y ? (next.x < next.z ? 0 : 2) : (next.y < next.z ? 1 : 2);
        v[a] += step[a];
        if (v[a] < 0 || v[a] >= grid.resolution[a]) return false;
        next[a] += delta[a];
    }
}

// The voxel under the pointer as above; false when the ray misses.
bool pickRgvcVoxel3d(const RgvcSnapshot& s, const RgvcViewState& view, const RgvcFrameIndex& index,
                     int64_t layer, const glm::dvec3& origin, const glm::dvec3& direction,
                     glm::ivec3& out);

// The occluder a click on 3D voxel `v` picks: the occluders3d entry of that
// voxel, else the one whose pass hid it (RgvcSnapshot::h_cause), else -1.
// O(occluders).
int rgvcOccluder3dAt(const RgvcSnapshot& s, glm::ivec3 v);

}  // namespace gridcull
