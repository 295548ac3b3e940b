// Convex polygon rasterization sampled at voxel centres, the occlusion step of
// Batagelo & Wu (section 4.4): "we consider that the center of each voxel is
// given in integer coordinates ... and discretize the occlusion polygon into the
// regular grid with an ordinary convex polygon rasterization algorithm, where the
// sampling is taken in integer coordinates at the center of the voxels".
//
// Coordinates here are voxel-centre coordinates: voxel (i, j) is the unit square
// [i - 0.5, i + 0.5] x [j - 0.5, j + 0.5] around the integer point (i, j). A
// convex region is an intersection of half-planes (possibly unbounded, e.g. the
// semi-infinite occlusion polygon); toVoxelCentreCoords maps a world half-plane
// of a 2D RegularGrid into these coordinates.
//
// Sampling a region at centres alone marks voxels that straddle its edges;
// wholeVoxelsOnly() moves each edge inwards by (|nx| + |ny|) / 2, the largest
// distance from a voxel's centre to its boundary along the edge's normal
// (Wonka et al.'s shrinking, which the paper cites), so that a voxel is sampled
// exactly when the whole voxel lies inside the region. Cost: O(rows * planes).
#pragma once
#include <algorithm>
#include <cmath>

#include "grid/regular_grid.h"

namespace gridcull {

// The closed half-plane nx * x + ny * y >= k.
struct HalfPlane2 {
    double nx = 0.0;
    double ny = 0.0;
    double k = 0.0;

    double eval(double x, double y) const { return nx * x + ny * y - k; }
};

// A world-space half-plane (x-y plane) of a 2D grid in voxel-centre coordinates:
// world p = grid.world.min + (c + 0.5) * voxelSize for centre coordinates c.
inline HalfPlane2 toVoxelCentreCoords(const HalfPlane2& world, const RegularGrid& grid) {
    const glm::dvec3 d = grid.voxelSize();
    const double ox = grid.world.min.x + 0.5 * d.x, oy = grid.world.min.y + 0.5 * d.y;
    return {world.nx * d.x, world.ny * d.y, world.k - world.nx * ox - world.ny * oy};
}

// The half-plane (voxel-centre coordinates) whose integer points are the centres
// of voxels lying wholly inside `plane`, with `slack` (voxel units, >= 0) more
// margin against rounding.
inline HalfPlane2 wholeVoxelsOnly(const HalfPlane2& plane, double slack) {
    const double norm = std::hypot(plane.nx, plane.ny);
    return {plane.nx, plane.ny,
            plane.k + 0.5 * (std::abs(plane.nx) + std::abs(plane.ny)) + slack * norm};
}

// The rows [row_lo, row_hi] in which the region (planes within the box
// [x_lo, x_hi] x [y_lo, y_hi]) may hold points: the box clipped by every plane,
// widened by a row against rounding. False when the clipped box is empty.
// Handles up to 12 planes; beyond that it returns the whole box.
bool convexRegionRows(const HalfPlane2* planes, int count, int x_lo, int x_hi, int y_lo, int y_hi,
                      int& row_lo, int& row_hi);

// Calls span(y, x0, x1) with x0 <= x1 for each row y in [y_lo, y_hi] holding the
// integer points (x, y), x in [x_lo, x_hi], that satisfy every plane. Only the
// rows the region meets are scanned (convexRegionRows). Cost: O(rows met *
// planes) plus O(planes^2) to find them.
template <typename Span>
void rasterizeConvexAtCentres(const HalfPlane2* planes, int count, int x_lo, int x_hi, int y_lo,
                              int y_hi, Span&& span) {
    if (x_lo > x_hi || y_lo > y_hi) return;
    int row_lo, row_hi;
    if (!convexRegionRows(planes, count, x_lo, x_hi, y_lo, y_hi, row_lo, row_hi)) return;
    for (int y = row_lo; y <= row_hi; ++y) {
        double lo = double(x_lo), hi = double(x_hi);
        for (int i = 0; i < count && lo <= hi; ++i) {
            const HalfPlane2& p = planes[i];
            const double rest = p.k - p.ny * double(y);  // nx * x >= rest
            if (p.nx > 0.0) {
                lo = std::max(lo, rest / p.nx);
            } else if (p.nx < 0.0) {
                hi = std::min(hi, rest / p.nx);
            } else if (rest > 0.0) {
                hi = lo - 1.0;  // the row misses a horizontal half-plane
            }
        }
        const double first = std::ceil(lo), last = std::floor(hi);
        if (first <= last) span(y, int(first), int(last));
    }
}

}  // namespace gridcull
