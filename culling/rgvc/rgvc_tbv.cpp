// TBV discretization for regular-grid culling (Batagelo & Wu, section 4.1);
// see rgvc_tbv.h.
#include "culling/rgvc/rgvc_tbv.h"

#include <algorithm>
#include <cmath>

namespace gridcull {

namespace {

double smallestVoxelSide(const RegularGrid& grid) {
    const glm::dvec3 d = grid.voxelSize();
    return std::min(d.x, d.y);
}

}  // namespace

RgvcVoxelBox voxelBoxTouching(const RegularGrid& grid, const Aabb& box) {
    RgvcVoxelBox out;
    const glm::dvec3 d = grid.voxelSize();
    const int axes = grid.dimensions == 2 ? 2 : 3;
    out.lo.z = out.hi.z = 0;
    for (int a = 0; a < axes; ++a) {
        const double lo = (box.min[a] - grid.world.min[a]) / d[a] - 1e-6;
        const double hi = (box.max[a] - grid.world.min[a]) / d[a] + 1e-6;
        const double top = double(grid.resolution[a] - 1);
        out.lo[a] = int(std::clamp(std::floor(lo), 0.0, top + 1.0));
        out.hi[a] = int(std::clamp(std::floor(hi), -1.0, top));
    }
    return out;
}

RgvcTbvCurve tbvCurveFor(const RegularGrid& grid, const glm::dvec3& centre, double radius) {
    RgvcTbvCurve curve;
    const glm::ivec3 v = grid.voxelOf({centre.x, centre.y, 0.0});
    curve.centre = {v.x, v.y};
    // In voxel units the disc is an ellipse with semi-axes radius / d.x and
    // radius / d.y, inside the circle of radius / min(d.x, d.y).
    const double rho = std::ceil(std::max(0.0, radius) / smallestVoxelSide(grid) + kTbvCurveMargin);
    curve.radius = int(std::min(rho, 1.0e8));
    return curve;
}

bool tbvCurveInsideGrid(const RegularGrid& grid, const RgvcTbvCurve& curve) {
    const int64_t reach = int64_t(curve.radius) + 1;
    return curve.centre.x - reach >= 0 && curve.centre.y - reach >= 0 &&
           curve.centre.x + reach < grid.resolution.x && curve.centre.y + reach < grid.resolution.y;
}

double tbvLargestRadiusExcluding(const RegularGrid& grid, const glm::dvec3& centre,
                                 glm::i64vec2 voxel) {
    const glm::ivec3 v = grid.voxelOf({centre.x, centre.y, 0.0});
    const double dx = double(voxel.x - v.x), dy = double(voxel.y - v.y);
    const double dist = std::sqrt(dx * dx + dy * dy);
    // The largest integer rho with (rho + 1)^2 < dist^2, then the largest radius
    // whose ceil(radius / side + margin) stays at or below it (a millionth of a
    // voxel below, against rounding in that ceil).
    const double rho = std::ceil(dist) - 2.0;
    return (rho - kTbvCurveMargin - 1e-6) * smallestVoxelSide(grid);
}

}  // namespace gridcull
