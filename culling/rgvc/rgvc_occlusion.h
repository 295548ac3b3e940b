// Occluder extension and occlusion computation of regular-grid culling
// (Batagelo & Wu, sections 4.3 and 4.4).
//
// Occluder extension (s4.3, after Schaufler et al.'s blocker extension): from an
// opaque, non-occluded voxel found by the traversal, aggregate opaque or
// occluded voxels along the axes into an extended occluder in four steps, with
// directions taken from the viewer's voxel as in the paper's Figure 4. Along the
// primary axis a and the secondary axis b, "towards" means towards the viewer's
// voxel and "away" the opposite:
//   (1) extend along a towards the viewer from the initial voxel;
//   (2) extend along b away from the viewer from the end of step 1;
//   (3) extend along b towards the viewer from the initial voxel: in the convex
//       variant only if step 1 added nothing, in the staircase variant always;
//   (4) extend along a away from the viewer from the end of step 3 (or from the
//       initial voxel when step 3 did not run).
// a is x unless the viewer's voxel is on the initial voxel's row (then the
// column is the broadside and a is y). On the viewer's column or row the
// "towards" sign is -1 by convention. Both variants are the paper's; the knob
// --rgvc-extension (RgvcOptions::extension) picks one.
//
// The extended occluder is kept as one or two Ls (RgvcOccluderL): a corner voxel
// with one leg along x and one along y, both going away from the viewer, so the
// corner faces the viewer.
//  - Convex variant (RgvcExtension::ConvexL): always one L, the paper's "convex
//    L-shaped occluder": its corner is the end of step 1 (or of step 3).
//  - Staircase variant (RgvcExtension::Staircase, the paper's non-convex case):
//    when steps 1 and 3 both add voxels the occluder is a staircase, the L of
//    steps 1 and 2 (corner: the end of step 1) and the L of steps 3 and 4
//    (corner: the end of step 3), sharing the initial voxel, the concave corner
//    between them facing the viewer. When step 1 or step 3 adds nothing, it is
//    the convex variant's L. Step 4 starts at the end of step 3, as the paper
//    says, so the blocking voxels beyond the initial voxel along a, which the
//    convex L takes when step 1 extends, are left out of a staircase: neither
//    variant's occluder contains the other's in general.
//
// Occlusion computation (s4.4): the occlusion polygon is the region hidden by
// an L from the viewpoint, a semi-infinite convex polygon: the wedge between the
// silhouette rays, beyond the L's edges that face the viewer. When the viewpoint
// lies in the quadrant the L's corner faces, one polygon covers the whole L
// (both outer edges face the viewer); otherwise each leg gets its own polygon
// (the two overlap behind the corner voxel). No polygon is made for a rectangle
// that contains the viewpoint. A staircase's hidden region is not convex (the
// paper's "occlusion volume is a semi-infinite convex polygon" holds for the L
// only): we cover it with the polygons of its two Ls, at most four convex
// polygons. A point is hidden by the staircase exactly when the segment from the
// viewpoint meets one of its Ls, so the union of the Ls' polygons is the
// staircase's hidden region (less the shadow of a leg holding the viewpoint,
// which gets no polygon), and the pieces overlap (both Ls hold the initial
// voxel, whose shadow lies in both) around the ray through the concave corner.
// A voxel is marked only when it lies wholly inside one polygon, so a voxel
// hidden only by two pieces together stays unmarked (conservative). We chose
// this over an exact partition of the region into convex pieces (split along
// the ray through the concave corner: every voxel straddling that ray would be
// lost) and over rasterizing the non-convex region directly (a general
// scan-line rasterizer with edge lists, where the convex one costs
// O(rows * planes) and allocates nothing); a staircase costs at most twice an L.
//
// Departure from the paper in the rasterization: the paper builds the polygon
// from voxel centres in integer coordinates with the viewpoint moved to its
// voxel's centre, which amounts to a from-region polygon shrunk by
// (|nx| + |ny|) d / 2; we build it exactly from the real viewpoint and shrink
// each edge by the same (|nx| + |ny|) d / 2 (grid/polygon_raster.h), so that
// sampling at voxel centres marks exactly the voxels lying wholly inside the
// polygon, neither more (which would be wrong) nor fewer (which the from-region
// form gives).
//
// World coordinates, x-y plane, of a 2D RegularGrid; voxel indices for voxels.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/vec2.hpp>

#include "grid/polygon_raster.h"
#include "grid/regular_grid.h"

namespace gridcull {

// Extra inward margin of occlusion polygons against rounding, in voxel widths.
constexpr double kOcclusionSlack = 1e-6;

// The two variants of the extension (s4.3); the values are --rgvc-extension's.
enum class RgvcExtension : int {
    ConvexL = 0,    // step 3 only when step 1 added nothing: one convex L
    Staircase = 1,  // step 3 always: a staircase of two Ls when steps 1 and 3 both extend
};

struct RgvcExtensionStep {
    glm::ivec2 from{0};       // the voxel the step starts at
    glm::ivec2 direction{0};  // unit axis direction
    int count = 0;            // voxels added: from + direction * 1 .. count
    bool run = false;         // false: step 3 skipped because step 1 added voxels (convex L)
};

// An L of voxels: the corner voxel and a leg along x and one along y leaving it
// away from the viewer (direction -toward on each axis); a leg may be empty.
struct RgvcOccluderL {
    glm::ivec2 corner{0};
    int leg_x = 0;  // voxels of the x leg beyond the corner
    int leg_y = 0;  // voxels of the y leg beyond the corner
};

struct RgvcExtendedOccluder {
    glm::ivec2 initial{0};
    glm::ivec2 toward{-1, -1};  // per axis, the sign pointing to the viewer's voxel
    bool primary_is_y = false;  // axis a is y (the viewer is on the initial row)
    RgvcExtension variant = RgvcExtension::ConvexL;
    std::array<RgvcExtensionStep, 4> steps{};
    // The occluder: one L, or for a staircase two (parts[0] from steps 1 and 2,
    // parts[1] from steps 3 and 4), both holding the initial voxel.
    int part_count = 1;
    std::array<RgvcOccluderL, 2> parts{};

    bool isStaircase() const { return part_count == 2; }
    // The far voxels of part i's legs (the corner when the leg is empty).
    glm::ivec2 legXEnd(int i) const {
        const RgvcOccluderL& l = parts[size_t(i)];
        return l.corner + glm::ivec2(-toward.x * l.leg_x, 0);
    }
    glm::ivec2 legYEnd(int i) const {
        const RgvcOccluderL& l = parts[size_t(i)];
        return l.corner + glm::ivec2(0, -toward.y * l.leg_y);
    }
    // Does the occluder hold voxel v?
    bool covers(glm::ivec2 v) const;
    // Its voxels (the initial voxel once).
    int voxelCount() const;
};

// Extends from `initial` over voxels for which blocking(x, y) is true (the
// caller's "opaque or occluded") in the given variant; only voxels inside
// [0, width) x [0, height) are considered. Cost: O(voxels added).
template <typename Blocking>
RgvcExtendedOccluder extendOccluder(glm::ivec2 initial, glm::i64vec2 viewer, int width, int height,
                                    RgvcExtension variant, Blocking&& blocking) {
    RgvcExtendedOccluder occ;
    occ.initial = initial;
    occ.variant = variant;
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
    if (occ.steps[0].count == 0 || variant == RgvcExtension::Staircase) {
        occ.steps[2] = step(initial, eb * tb);
        end3 = initial + eb * (tb * occ.steps[2].count);
    } else {
        occ.steps[2].from = initial;
        occ.steps[2].direction = eb * tb;
    }
    occ.steps[3] = step(end3, ea * -ta);
    const int s1 = occ.steps[0].count, s2 = occ.steps[1].count, s3 = occ.steps[2].count,
              s4 = occ.steps[3].count;
    // Per L: corner, leg along a, leg along b.
    const auto setPart = [&](int i, glm::ivec2 corner, int leg_a, int leg_b) {
        RgvcOccluderL& l = occ.parts[size_t(i)];
        l.corner = corner;
        l.leg_x = occ.primary_is_y ? leg_b : leg_a;
        l.leg_y = occ.primary_is_y ? leg_a : leg_b;
    };
    if (s1 > 0 && s3 > 0) {
        // A staircase: the concave corner at the initial voxel.
        occ.part_count = 2;
        setPart(0, end1, s1, s2);
        setPart(1, end3, s4, s3);
    } else if (s1 > 0) {
        setPart(0, end1, s1 + s4, s2);
    } else {
        setPart(0, end3, s4, s3 + s2);
    }
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

// At most two polygons per L, two Ls per occluder.
constexpr int kRgvcMaxOcclusionPolygons = 4;
using RgvcOcclusionPolygons = std::array<RgvcOcclusionPolygon, kRgvcMaxOcclusionPolygons>;

// The occlusion polygons of `occ` seen from `apex`: fills out[0..n) and returns
// n in [0, 2] for one L, [0, 4] for a staircase.
int occlusionPolygons(const RgvcExtendedOccluder& occ, const RegularGrid& grid, glm::dvec2 apex,
                      RgvcOcclusionPolygons& out);

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
