// Conservative discretization of 2D shapes into a regular grid (Batagelo & Wu,
// section 4.1): for each shape, the voxels it spans (touches at all, the
// identifiers matrix I) and the voxels it makes opaque (lies wholly inside, the
// occluder matrix O). I must over-estimate and O under-estimate; the paper grows
// and shrinks the outline by d / sqrt(2) and samples at pixel centres. We test
// each voxel exactly instead, which is at least as conservative and never
// coarser: a voxel is "spanned" when the closed voxel square meets the closed
// shape, and "opaque" when the voxel square lies inside the closed shape. A
// slack of kRasterSlack voxel widths widens "spanned", so rounding errs on the
// safe side there. "Opaque" must not lose every voxel whose side lies exactly
// on a shape's edge (walls aligned with the grid are the common case), so it
// accepts a voxel that sticks out by at most kOpaqueSnap voxel widths: far below
// anything a ray or pixel can resolve, and above the rounding of the
// world-to-voxel division for coordinates up to about 10^5 voxel widths.
//
// World coordinates (x-y plane, z ignored) of a 2D RegularGrid; voxels may be
// non-square. Results are reported as row spans: touched(y, x0, x1) and
// inside(y, x0, x1) with x0 <= x1, clipped to the grid (parts of a shape outside
// the grid are dropped; callers handle them). No allocation.
// Cost: circles and boxes O(rows); polygons O(bounding-box voxels * corners).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/vec3.hpp>

#include "grid/aabb.h"
#include "grid/regular_grid.h"

namespace gridcull {

constexpr double kRasterSlack = 1e-9;  // voxel widths
constexpr double kOpaqueSnap = 1e-10;  // voxel widths

// A voxel index as an int, clamped on both sides (and NaN to the low side) so
// that an object billions of voxels away never overflows the conversion.
inline int clampedVoxelIndex(double v) {
    return int(!(v >= -2.0e9) ? -2.0e9 : v > 2.0e9 ? 2.0e9 : v);
}

// Voxel index range [lo, hi] along one axis of the voxels whose closed extent
// meets the closed interval [a, b] (world units), unclipped.
inline void touchedRange(double a, double b, double origin, double size, int& lo, int& hi) {
    const double ua = (a - origin) / size, ub = (b - origin) / size;
    lo = clampedVoxelIndex(std::ceil(ua - kRasterSlack) - 1.0);
    hi = clampedVoxelIndex(std::floor(ub + kRasterSlack));
}

// Voxel index range [lo, hi] of the voxels whose extent lies inside [a, b]
// (up to kOpaqueSnap).
inline void insideRange(double a, double b, double origin, double size, int& lo, int& hi) {
    const double ua = (a - origin) / size, ub = (b - origin) / size;
    lo = clampedVoxelIndex(std::ceil(ua - kOpaqueSnap));
    hi = clampedVoxelIndex(std::floor(ub + kOpaqueSnap) - 1.0);
}

template <typename Touched, typename Inside>
void rasterizeBox(const RegularGrid& grid, const Aabb& box, Touched&& touched, Inside&& inside) {
    const glm::dvec3 d = grid.voxelSize();
    const glm::dvec3& o = grid.world.min;
    const int w = grid.resolution.x, h = grid.resolution.y;
    int x0, x1, y0, y1;
    touchedRange(box.min.x, box.max.x, o.x, d.x, x0, x1);
    touchedRange(box.min.y, box.max.y, o.y, d.y, y0, y1);
    x0 = std::max(x0, 0), x1 = std::min(x1, w - 1);
    y0 = std::max(y0, 0), y1 = std::min(y1, h - 1);
    if (x0 <= x1)
        for (int y = y0; y <= y1; ++y) touched(y, x0, x1);
    insideRange(box.min.x, box.max.x, o.x, d.x, x0, x1);
    insideRange(box.min.y, box.max.y, o.y, d.y, y0, y1);
    x0 = std::max(x0, 0), x1 = std::min(x1, w - 1);
    y0 = std::max(y0, 0), y1 = std::min(y1, h - 1);
    if (x0 <= x1)
        for (int y = y0; y <= y1; ++y) inside(y, x0, x1);
}

template <typename Touched, typename Inside>
void rasterizeCircle(const RegularGrid& grid, const glm::dvec3& center, double radius,
                     Touched&& touched, Inside&& inside) {
    const glm::dvec3 d = grid.voxelSize();
    const glm::dvec3& o = grid.world.min;
    const int w = grid.resolution.x, h = grid.resolution.y;
    int y0, y1;
    touchedRange(center.y - radius, center.y + radius, o.y, d.y, y0, y1);
    y0 = std::max(y0, 0), y1 = std::min(y1, h - 1);
    const double r2 = radius * radius;
    for (int y = y0; y <= y1; ++y) {
        const double lo_y = o.y + y * d.y, hi_y = lo_y + d.y;
        // Touched: the widest chord of the circle within the row's closed strip.
        const double gap = std::max({0.0, lo_y - center.y, center.y - hi_y});
        const double half = std::sqrt(std::max(0.0, r2 - gap * gap));
        int x0, x1;
        touchedRange(center.x - half, center.x + half, o.x, d.x, x0, x1);
        x0 = std::max(x0, 0), x1 = std::min(x1, w - 1);
        if (x0 <= x1) touched(y, x0, x1);
        // Inside: the narrowest chord, at the strip's edge farther from the centre;
        // a voxel whose corners all lie within the circle lies wholly inside it.
        const double far_y = std::max(std::abs(lo_y - center.y), std::abs(hi_y - center.y));
        if (far_y >= radius) continue;
        const double inner = std::sqrt(r2 - far_y * far_y);
        insideRange(center.x - inner, center.x + inner, o.x, d.x, x0, x1);
        x0 = std::max(x0, 0), x1 = std::min(x1, w - 1);
        if (x0 <= x1) inside(y, x0, x1);
    }
}

// Does the closed segment [a, b] meet the closed box [lo, hi] (x-y)? Exact up to
// rounding (Liang-Barsky clipping).
bool segmentMeetsRect(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& lo,
                      const glm::dvec3& hi);

// Is p inside the polygon points[i] + offset (even-odd rule)? Points on the
// boundary may go either way; callers that care test the edges too.
bool pointInPolygonXY(const glm::dvec3& p, const glm::dvec3* points, size_t count,
                      const glm::dvec3& offset);

// Classifies the closed voxel square [lo, hi] against the simple polygon
// points[i] + offset: touches (meets the closed polygon, the square grown by
// kRasterSlack) and inside (lies within the closed polygon, the square shrunk
// by kOpaqueSnap). voxel: the voxel's size, which scales both.
void classifyVoxelAgainstPolygon(const glm::dvec3& lo, const glm::dvec3& hi,
                                 const glm::dvec3& voxel, const glm::dvec3* points, size_t count,
                                 const glm::dvec3& offset, bool& touches, bool& inside);

// Simple polygons of any shape (convex or not), counter-clockwise or not.
template <typename Touched, typename Inside>
void rasterizePolygon(const RegularGrid& grid, const glm::dvec3* points, size_t count,
                      const glm::dvec3& offset, Touched&& touched, Inside&& inside) {
    if (count < 3) return;
    const glm::dvec3 d = grid.voxelSize();
    const glm::dvec3& o = grid.world.min;
    const int w = grid.resolution.x, h = grid.resolution.y;
    double min_x = points[0].x, max_x = min_x, min_y = points[0].y, max_y = min_y;
    for (size_t i = 1; i < count; ++i) {
        min_x = std::min(min_x, points[i].x), max_x = std::max(max_x, points[i].x);
        min_y = std::min(min_y, points[i].y), max_y = std::max(max_y, points[i].y);
    }
    int x0, x1, y0, y1;
    touchedRange(min_x + offset.x, max_x + offset.x, o.x, d.x, x0, x1);
    touchedRange(min_y + offset.y, max_y + offset.y, o.y, d.y, y0, y1);
    x0 = std::max(x0, 0), x1 = std::min(x1, w - 1);
    y0 = std::max(y0, 0), y1 = std::min(y1, h - 1);
    for (int y = y0; y <= y1; ++y) {
        int touch_start = -1, inside_start = -1;
        for (int x = x0; x <= x1 + 1; ++x) {
            bool t = false, in = false;
            if (x <= x1) {
                const glm::dvec3 lo{o.x + x * d.x, o.y + y * d.y, 0.0};
                const glm::dvec3 hi{lo.x + d.x, lo.y + d.y, 0.0};
                classifyVoxelAgainstPolygon(lo, hi, d, points, count, offset, t, in);
            }
            if (t && touch_start < 0) touch_start = x;
            if (!t && touch_start >= 0) touched(y, touch_start, x - 1), touch_start = -1;
            if (in && inside_start < 0) inside_start = x;
            if (!in && inside_start >= 0) inside(y, inside_start, x - 1), inside_start = -1;
        }
    }
}

}  // namespace gridcull
