#include "ui/rgvc/rgvc_overlay3d.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "ui/rgvc/rgvc_slice.h"

namespace gridcull {

namespace {

constexpr int kDashes = 120;  // over the line of sight's length
// How far out, in grid diagonals, a camera at infinity is put.
constexpr double kFarEye = 1e4;

glm::dvec3 cornerOf(const RegularGrid& g, const glm::i64vec3& v) {
    return g.world.min + glm::dvec3(v) * g.voxelSize();
}

// The shell of layer k: the box of voxels at chess distance <= k from the
// viewer's voxel, cut to the grid, as voxel-corner indices [lo, hi).
void shellBox(const RgvcSnapshot& s, int64_t k, glm::i64vec3& lo, glm::i64vec3& hi) {
    const glm::i64vec3 e(s.viewer_voxel.x, s.viewer_voxel.y, s.viewer_voxel_z);
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::clamp<int64_t>(e[a] - k, 0, s.grid.resolution[a]);
        hi[a] = std::clamp<int64_t>(e[a] + k + 1, 0, s.grid.resolution[a]);
    }
}

void drawShell(const RgvcSnapshot& s, const RgvcViewState& view, int64_t k, DebugDraw& draw) {
    glm::i64vec3 lo, hi;
    shellBox(s, k, lo, hi);
    if (lo.x >= hi.x || lo.y >= hi.y || lo.z >= hi.z) return;
    const Paint paint{rgvcLayerSwatch(RgvcLayer::CurrentLayer), 1.0f};
    if (view.mode == RgvcVoxelMode::Boxes) {
        draw.wireBox(cornerOf(s.grid, lo), cornerOf(s.grid, hi), paint, kBoldLine);
        return;
    }
    // The shell's cross-section with the slice, on the slice's plane.
    const int a = std::clamp(view.slice_axis, 0, 2), b = (a + 1) % 3, c = (a + 2) % 3;
    const int n = rgvcSliceIndex(s, view);
    if (n < lo[a] || n >= hi[a]) return;
    const double plane = rgvcSlicePlane(s.grid, a, n);
    const glm::dvec3 p0 = cornerOf(s.grid, lo), p1 = cornerOf(s.grid, hi);
    glm::dvec3 q[4];
    for (int i = 0; i < 4; ++i) {
        q[i][a] = plane;
        q[i][b] = (i == 1 || i == 2) ? p1[b] : p0[b];
        q[i][c] = i >= 2 ? p1[c] : p0[c];
    }
    draw.outlinePolygon(DrawSpace::World, q, 4, paint, kBoldLine);
}

void drawSeed(const RgvcSnapshot& s, int64_t k, DebugDraw& draw) {
    const Paint white{rgvcLayerSwatch(RgvcLayer::Seed), 1.0f};
    for (const RgvcSeed& seed : s.seeds) {
        if (seed.layer != k) continue;
        const glm::i64vec3 v(seed.voxel.x, seed.voxel.y, seed.z);
        const glm::dvec3 lo = cornerOf(s.grid, v), hi = cornerOf(s.grid, v + int64_t(1));
        draw.wireBox(lo, hi, white, kHeavyLine);
        // A box two voxels out, so the seed is findable when a voxel is a few pixels.
        const glm::dvec3 d = s.grid.voxelSize();
        draw.wireBox(lo - 2.0 * d, hi + 2.0 * d, white, kFineLine);
    }
}

void drawLineOfSight(const RgvcSnapshot& s, DebugDraw& draw) {
    const Aabb& w = s.grid.world;
    const glm::dvec3 dir = glm::normalize(s.forward);
    // To where the line leaves the grid's box (or as far as the box is wide).
    double t_out = std::numeric_limits<double>::infinity(), t_in = 0.0;
    for (int a = 0; a < 3; ++a) {
        if (dir[a] == 0.0) continue;
        double ta = (w.min[a] - s.viewpoint[a]) / dir[a], tb = (w.max[a] - s.viewpoint[a]) / dir[a];
        if (ta > tb) std::swap(ta, tb);
        t_in = std::max(t_in, ta);
        t_out = std::min(t_out, tb);
    }
    double length =
        t_in <= t_out && std::isfinite(t_out) ? t_out : 1.5 * glm::length(w.max - w.min);
    length = std::min(length, s.far);
    const double dash = length / kDashes;
    const Paint paint{rgvcLayerSwatch(RgvcLayer::LineOfSight), 1.0f};
    for (int k = 0; k < kDashes; k += 2)
        draw.line(DrawSpace::World, s.viewpoint + dir * (dash * k),
                  s.viewpoint + dir * (dash * (k + 1)), paint, kFineLine);
}

}  // namespace

glm::dvec3 rgvcViewEye(const glm::dmat4& view_projection, const RegularGrid& grid) {
    // The eye is the point that clip space maps to w = 0 with x = y = 0: the
    // inverse maps the clip-space direction (0, 0, 1, 0) to it (homogeneous).
    const glm::dvec3 centre = grid.world.center();
    const double diagonal = std::max(glm::length(grid.world.max - grid.world.min), 1e-9);
    const double det = glm::determinant(view_projection);
    if (!std::isfinite(det) || std::abs(det) < 1e-300) return centre + glm::dvec3(0, 0, kFarEye);
    const glm::dmat4 inv = glm::inverse(view_projection);
    const glm::dvec4 h = inv * glm::dvec4(0.0, 0.0, 1.0, 0.0);
    const glm::dvec3 xyz(h);
    if (std::abs(h.w) > 1e-12 * std::max(1.0, glm::length(xyz))) return xyz / h.w;
    // At infinity: the viewing direction is towards -xyz or xyz; take the side
    // the near plane (clip z = -1) lies on.
    const glm::dvec4 n = inv * glm::dvec4(0.0, 0.0, -1.0, 1.0);
    const glm::dvec4 f = inv * glm::dvec4(0.0, 0.0, 1.0, 1.0);
    glm::dvec3 back = glm::dvec3(n) / n.w - glm::dvec3(f) / f.w;
    if (!(glm::length(back) > 0.0)) back = glm::dvec3(0, 0, 1);
    return centre + glm::normalize(back) * (kFarEye * diagonal);
}

void drawRgvcOverlay3d(const RgvcSnapshot& s, const RgvcViewState& view, double near,
                       const glm::dvec3& eye, DebugDraw& draw, RgvcOverlay3dScratch& scratch) {
    if (!s.valid || s.dimensions != 3 || !s.occluder) return;
    const int64_t shown = rgvcShownLayer(s, view.layer);
    scratch.index.update(s, shown);
    if (view.mode == RgvcVoxelMode::Boxes)
        scratch.boxes.draw(s, view, scratch.index, shown, eye, draw);
    else
        drawRgvcSlice(s, view, scratch.index, shown, draw);
    if (shown >= 0 && view.shown(RgvcLayer::CurrentLayer)) drawShell(s, view, shown, draw);
    if (shown >= 0 && view.shown(RgvcLayer::Seed)) drawSeed(s, shown, draw);
    if (view.shown(RgvcLayer::LineOfSight)) drawLineOfSight(s, draw);
    if (view.occluder >= 0 && size_t(view.occluder) < s.occluders3d.size()) {
        buildRgvcCap3d(s, near, view.occluder, scratch.cap);
        drawRgvcCap3d(s, view, scratch.cap, draw);
    }
}

}  // namespace gridcull
