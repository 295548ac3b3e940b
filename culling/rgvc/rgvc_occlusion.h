// Occluder extension and occlusion computation of regular-grid culling
// (Batagelo & Wu, sections 4.3 and 4.4).
//
// Occluder extension (s4.3, after Schaufler et al.'s blocker extension): from an
// opaque, non-occluded voxel found by the traversal, aggregate opaque or
// occluded voxels along the axes into a convex L-shaped extended occluder in
// four steps, with directions taken from the viewer's voxel as in the paper's
// Figure 4. Along the primary axis a and the secondary axis b, "towards" means
// towards the viewer's voxel and "away" the opposite:
//   (1) extend along a towards the viewer from the initial voxel;
//   (2) extend along b away from the viewer from the end of step 1;
//   (3) only if step 1 added nothing: extend along b towards the viewer from
//       the initial voxel (the convex variant of the paper);
//   (4) extend along a away from the viewer from the end of step 3 (or from the
//       initial voxel when step 3 did not run).
// The result is always an L: a corner voxel with one leg along x and one along
// y, both going away from the viewer, so the corner faces the viewer. a is x
// unless the viewer's voxel is on the initial voxel's row (then the column is
// the broadside and a is y). On the viewer's column or row the "towards" sign
// is -1 by convention. The paper's staircase (non-convex) variant, which runs
// step 3 always, is not implemented.
//
// Occlusion computation (s4.4): the occlusion polygon is the region hidden by
// the extended occluder from the viewpoint, a semi-infinite convex polygon: the
// wedge between the silhouette rays, beyond the occluder's edges that face the
// viewer. Departure from the paper: the paper builds the polygon from voxel
// centres in integer coordinates with the viewpoint moved to its voxel's
// centre, which amounts to a from-region polygon shrunk by (|nx| + |ny|) d / 2;
// we build it exactly from the real viewpoint and shrink each edge by the same
// (|nx| + |ny|) d / 2 (grid/polygon_raster.h), so that sampling at voxel
// centres marks exactly the voxels lying wholly inside the polygon, neither
// more (which would be wrong) nor fewer (which the from-region form gives).
// When the viewpoint lies in the quadrant the L's corner faces, one polygon
// covers the whole L (both outer edges face the viewer); otherwise each leg
// gets its own polygon (a voxel hidden only by the two together then stays
// unmarked: conservative). No polygon is made for a rectangle that contains the
// viewpoint.
//
// World coordinates, x-y plane, of a 2D RegularGrid; voxel indices for voxels.
#pragma once
#include <array>
#include <cstdint>

#include <glm/vec2.hpp>

#include "grid/polygon_raster.h"
#include "grid/regular_grid.h"

namespace gridcull {

// Extra inward margin of occlusion polygons against rounding, in voxel widths.
constexpr double kOcclusionSlack = 1e-6;

struct RgvcExtensionStep {
    glm::ivec2 from{0};       // the voxel the step starts at
    glm::ivec2 direction{0};  // unit axis direction
    int count = 0;            // voxels added: from + direction * 1 .. count
    bool run = false;         // false: step 3 skipped because step 1 added voxels
};

struct RgvcExtendedOccluder {
    glm::ivec2 initial{0};
    glm::ivec2 toward{-1, -1};  // per axis, the sign pointing to the viewer's voxel
    bool primary_is_y = false;  // axis a is y (the viewer is on the initial row)
    std::array<RgvcExtensionStep, 4> steps{};
    glm::ivec2 corner{0};  // the L's corner voxel
    int leg_x = 0;         // voxels of the x leg beyond the corner (direction -toward.x)
    int leg_y = 0;         // voxels of the y leg beyond the corner (direction -toward.y)

    glm::ivec2 legXEnd() const { return corner + glm::ivec2(-toward.x * leg_x, 0); }
    glm::ivec2 legYEnd() const { return corner + glm::ivec2(0, -toward.y * leg_y); }
    // Does the L hold voxel v?
    bool covers(glm::ivec2 v) const;
};

// Extends from `initial` over voxels for which blocking(x, y) is true (the
// caller's "opaque or occluded"); only voxels inside [0, width) x [0, height)
// are considered. Cost: O(voxels added).
template <typename Blocking>
RgvcExtendedOccluder extendOccluder(glm::ivec2 initial, glm::i64vec2 viewer, int width, int height,
                                    Blocking&& blocking) {
    RgvcExtendedOccluder occ;
    occ.initial = initial;
    occ.toward = {viewer.x > initial.x ? 1 : -1, viewer.y > initial.y ? 1 : -1};
    occ.primary_is_y = viewer.y == initial.y && viewer.x != initial.x;
    const glm::ivec2 ea = occ.primary_is_y ? glm::ivec2(0, 1) : glm::ivec2(1, 0);
    const glm::ivec2 eb = occ.primary_is_y ? glm::ivec2(1, 0) : glm::ivec2(0, 1);
    const int ta = occ.primary_is_y ? occ.toward.y : occ.toward.x;
    const int tb = occ.primary_is_y ? occ.toward.x : occ.toward.y;
    auto step = [&](glm::ivec2 from, glm::ivec2 dir) {
        RgvcExtensionStep s;
        s.from = from;
        s.direction = dir;
        s.run = true;
        for (glm::ivec2 v = from + dir;
             v.x >= 0 && v.y >= 0 && v.x < width && v.y < height && blocking(v.x, v.y); v += dir)
            ++s.count;
        return s;
    };
    occ.steps[0] = step(initial, ea * ta);
    const glm::ivec2 end1 = initial + ea * (ta * occ.steps[0].count);
    occ.steps[1] = step(end1, eb * -tb);
    glm::ivec2 end3 = initial;
    if (occ.steps[0].count == 0) {
        occ.steps[2] = step(initial, eb * tb);
        end3 = initial + eb * (tb * occ.steps[2].count);
    } else {
        occ.steps[2].from = initial;
        occ.steps[2].direction = eb * tb;
    }
    occ.steps[3] = step(end3, ea * -ta);
    int leg_a, leg_b;
    if (occ.steps[0].count > 0) {
        occ.corner = end1;
        leg_a = occ.steps[0].count + occ.steps[3].count;
        leg_b = occ.steps[1].count;
    } else {
        occ.corner = end3;
        leg_a = occ.steps[3].count;
        leg_b = occ.steps[2].count + occ.steps[1].count;
    }
    occ.leg_x = occ.primary_is_y ? leg_b : leg_a;
    occ.leg_y = occ.primary_is_y ? leg_a : leg_b;
    return occ;
}

// A semi-infinite convex occlusion polygon: the intersection of its half-planes
// (world coordinates, unit normals). `outline` is its finite boundary from one
// silhouette point to the other for drawing; the polygon continues from the
// ends of the outline to infinity along the rays from the apex.
struct RgvcOcclusionPolygon {
    int plane_count = 0;
    std::array<HalfPlane2, 4> planes{};
    glm::dvec2 apex{0.0};
    int outline_count = 0;
    std::array<glm::dvec2, 3> outline{};

    // Is the world point strictly inside by more than `margin` (world units)?
    bool containsPoint(glm::dvec2 p, double margin) const;
};

// The occlusion polygons of `occ` seen from `apex`: fills out[0..n) and returns
// n in [0, 2].
int occlusionPolygons(const RgvcExtendedOccluder& occ, const RegularGrid& grid, glm::dvec2 apex,
                      std::array<RgvcOcclusionPolygon, 2>& out);

// Marks in the caller's matrix, through mark(y, x0, x1), every voxel with
// x in [x_lo, x_hi], y in [y_lo, y_hi] that lies wholly inside `polygon`
// (voxel-centre sampling of the shrunk polygon, s4.4). Returns the number marked.
template <typename Mark>
int64_t rasterizeOcclusionPolygon(const RgvcOcclusionPolygon& polygon, const RegularGrid& grid,
                                  int x_lo, int x_hi, int y_lo, int y_hi, Mark&& mark) {
    std::array<HalfPlane2, 4> planes;
    for (int i = 0; i < polygon.plane_count; ++i)
        planes[size_t(i)] =
            wholeVoxelsOnly(toVoxelCentreCoords(polygon.planes[size_t(i)], grid), kOcclusionSlack);
    int64_t marked = 0;
    rasterizeConvexAtCentres(planes.data(), polygon.plane_count, x_lo, x_hi, y_lo, y_hi,
                             [&](int y, int x0, int x1) {
                                 mark(y, x0, x1);
                                 marked += x1 - x0 + 1;
                             });
    return marked;
}

}  // namespace gridcull
