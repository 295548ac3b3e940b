// Temporal bounding volumes in the TBV matrix T (Batagelo & Wu, section 4.1,
// after Sudarsky & Gotsman): a hidden dynamic object is represented by a circle
// that surely contains it until the TBV expires, centred where the object stood
// when the TBV was made, radius = the object's bounding radius + max speed *
// validity period.
//
// The circle goes into T as a digital circle around the voxel holding its
// centre, with integer radius rho (voxels) chosen so that every voxel touching
// the continuous disc lies strictly inside the curve (kTbvCurveMargin voxels of
// room; tests/culling/rgvc/rgvc_tbv_test.cpp checks this by flood fill). Two forms:
//  - boundary: the 4-connected Bresenham circle only (grid/bresenham.h). An
//    8-connected path of voxels cannot cross a 4-connected closed curve, and the
//    voxels a ray passes form such a path, so a ray from outside the curve to
//    the object meets a curve voxel first. Valid while the viewer's voxel stays
//    outside the curve and moves 8-connected from frame to frame (the paper's
//    two conditions); the viewer stepping onto the curve finds the TBV in its
//    own voxel.
//  - filled: every voxel of the digital disc x^2 + y^2 <= (rho + 1)^2, found by
//    any ray that reaches the object whatever the viewer does.
// Coordinates: voxel indices of a 2D RegularGrid; the curve's centre may lie
// outside the grid.
//
// Clipped forms: an object that can only ever be inside a box of voxels B (its
// reach, rgvc_culler.h) is written as the boundary of (disc and B): the curve's
// voxels in B plus B's border voxels in the filled disc. A path from outside
// that region to inside it either crosses the curve inside B, or enters B
// through a border voxel of B that lies in the disc, so it still meets a T voxel.
// The cubical TBVs of 3D scenes are in rgvc_tbv3d.h.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "grid/aabb.h"
#include "grid/bresenham.h"
#include "grid/regular_grid.h"

namespace gridcull {

// Voxels between the continuous disc (radius / smallest voxel side) and rho.
// A voxel touching the disc has its centre within radius / side + sqrt(2) of the
// centre of the curve's centre voxel, and the curve's voxels have
// x^2 + y^2 > (rho - 1)^2 (grid/bresenham.h), so 1 + sqrt(2) < 2.5 leaves room;
// the flood-fill test finds no leak down to a margin of 1.
constexpr double kTbvCurveMargin = 2.5;

// A box of voxel indices, [lo, hi] inclusive per axis (2D uses x and y).
struct RgvcVoxelBox {
    glm::ivec3 lo{0};
    glm::ivec3 hi{-1};
    bool empty() const { return hi.x < lo.x || hi.y < lo.y || hi.z < lo.z; }
    bool contains(const glm::i64vec3& v) const {
        return v.x >= lo.x && v.y >= lo.y && v.z >= lo.z && v.x <= hi.x && v.y <= hi.y &&
               v.z <= hi.z;
    }
};

// The voxels of `grid` (clamped to it) that the closed world box `box` touches,
// leaning outwards by a millionth of a voxel against rounding.
RgvcVoxelBox voxelBoxTouching(const RegularGrid& grid, const Aabb& box);

struct RgvcTbvCurve {
    glm::i64vec2 centre{0};  // the voxel holding the disc's centre
    int radius = 0;          // rho, in voxels
};

// The digital circle for a disc of `radius` world units around `centre`.
RgvcTbvCurve tbvCurveFor(const RegularGrid& grid, const glm::dvec3& centre, double radius);

// Does every voxel of the filled form lie inside the grid? (Then so does the curve.)
bool tbvCurveInsideGrid(const RegularGrid& grid, const RgvcTbvCurve& curve);

// May `voxel` lie on the curve or inside it? False guarantees it lies outside
// both forms: every voxel of either satisfies x^2 + y^2 <= (rho + 1)^2.
inline bool tbvCurveMayEnclose(const RgvcTbvCurve& curve, glm::i64vec2 voxel) {
    const double dx = double(voxel.x - curve.centre.x), dy = double(voxel.y - curve.centre.y);
    const double reach = double(curve.radius) + 1.0;
    return dx * dx + dy * dy <= reach * reach;
}

// The largest radius (world units) whose curve leaves `voxel` outside, i.e. for
// which tbvCurveMayEnclose is false around a disc centred at `centre`; negative
// when no radius does.
double tbvLargestRadiusExcluding(const RegularGrid& grid, const glm::dvec3& centre,
                                 glm::i64vec2 voxel);

// Calls fn(x, y) for each voxel of the boundary form, 8 * rho voxels.
template <typename Fn>
void forEachTbvBoundaryVoxel(const RgvcTbvCurve& curve, Fn&& fn) {
    bresenhamCircle4(curve.radius, [&](int64_t x, int64_t y) {
        fn(int(curve.centre.x + x), int(curve.centre.y + y));
    });
}

// Calls fn(x, y) for each voxel of the boundary form cut to `clip` (see above).
// A voxel may come twice (on the curve and on the clip box's border); adding and
// removing use the same calls, so T stays consistent.
template <typename Fn>
void forEachTbvBoundaryVoxelClipped(const RgvcTbvCurve& curve, const RgvcVoxelBox& clip, Fn&& fn) {
    forEachTbvBoundaryVoxel(curve, [&](int x, int y) {
        if (x >= clip.lo.x && x <= clip.hi.x && y >= clip.lo.y && y <= clip.hi.y) fn(x, y);
    });
    const int64_t reach = curve.radius + 1;
    const int64_t cx = curve.centre.x, cy = curve.centre.y;
    // The clip box's border voxels within the filled disc: two rows, two columns.
    auto span = [&](int64_t offset, int64_t& lo, int64_t& hi) {
        if (offset * offset > reach * reach) return false;
        const int64_t half =
            int64_t(std::floor(std::sqrt(double(reach * reach - offset * offset))));
        lo = -half, hi = half;
        return true;
    };
    int64_t lo, hi;
    const int rows[2] = {clip.lo.y, clip.hi.y};
    for (int r = 0; r < (clip.lo.y == clip.hi.y ? 1 : 2); ++r) {
        const int y = rows[r];
        if (!span(y - cy, lo, hi)) continue;
        for (int64_t x = std::max<int64_t>(cx + lo, clip.lo.x);
             x <= std::min<int64_t>(cx + hi, clip.hi.x); ++x)
            fn(int(x), y);
    }
    const int columns[2] = {clip.lo.x, clip.hi.x};
    for (int c = 0; c < (clip.lo.x == clip.hi.x ? 1 : 2); ++c) {
        const int x = columns[c];
        if (!span(x - cx, lo, hi)) continue;
        // The corners came with the rows.
        for (int64_t y = std::max<int64_t>(cy + lo, clip.lo.y + 1);
             y <= std::min<int64_t>(cy + hi, clip.hi.y - 1); ++y)
            fn(x, int(y));
    }
}

// Calls fn(y, x0, x1) for each row of the filled form.
template <typename Fn>
void forEachTbvFilledSpan(const RgvcTbvCurve& curve, Fn&& fn) {
    const int64_t reach = curve.radius + 1;
    for (int64_t y = -reach; y <= reach; ++y) {
        const int64_t half = int64_t(std::floor(std::sqrt(double(reach * reach - y * y))));
        fn(int(curve.centre.y + y), int(curve.centre.x - half), int(curve.centre.x + half));
    }
}

// The filled form cut to `clip`: fn(y, x0, x1) for each non-empty row.
template <typename Fn>
void forEachTbvFilledSpanClipped(const RgvcTbvCurve& curve, const RgvcVoxelBox& clip, Fn&& fn) {
    forEachTbvFilledSpan(curve, [&](int y, int x0, int x1) {
        if (y < clip.lo.y || y > clip.hi.y) return;
        x0 = std::max(x0, clip.lo.x);
        x1 = std::min(x1, clip.hi.x);
        if (x0 <= x1) fn(y, x0, x1);
    });
}

}  // namespace gridcull
