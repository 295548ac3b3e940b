// Occluder extension and occlusion computation of regular-grid culling in 3D
// (Batagelo & Wu, section 5.3), as a direction map around the viewpoint.
//
// The paper: after a chess layer, the opaque-or-occluded voxels on each face of
// the layer's cube shell form a bitmap; it is vectorized into a cap polygon
// (with holes), extruded away from the viewer, and each cross-section of the
// extrusion is rasterized into the occlusion matrix H with the sampling
// correction of section 4.4 (only voxels wholly inside are marked).
//
// Here, for the same occlusion at a cost proportional to what the traversal
// visits: the extrusion of every cap is the set of directions from the eye that
// cross the cap, and it is recorded once in a cube map of directions around the
// eye (six faces of R x R cells; a cell is covered when every ray in it crosses
// a blocking voxel of some layer already traversed). A voxel that the traversal
// reaches later is marked in H when every direction from the eye to it is
// covered: the cross-section test of section 4.4 for all of the voxel's
// cross-sections at once, but only for voxels the traversal reaches, and no
// shadow is rasterized twice (eagerly, each layer's cap would re-extrude the
// shadows of the layers before it, which its occluded voxels carry).
//
// Departures, and why:
//  - The cap is fused over the whole layer, not per face: a cell of the map is
//    covered when each face of the layer's outer surface that its rays cross is
//    blocking wherever they cross it, so caps meet across the shell's edges.
//  - Blocking voxels are the layer's occluded voxels (H) and its opaque ones (O)
//    that lie wholly beyond the near plane: a solid cut by the near plane does
//    not hide what its clipped part would have hidden (the oracle sees through).
//  - With the eye inside the grid's box, rays that leave the layer's box
//    outside the grid count as blocked: they never come back into the grid, so
//    they cannot reach what the map is asked about (voxels of the grid). This
//    lets a wall that spans the grid hide everything behind it, up to the
//    grid's sides.
//  - Each test is made on bounding rectangles (a cell's rays where they meet a
//    face plane; a voxel's directions on a map face), supersets of the exact
//    regions, so it can only miss occlusion, never invent it.
//  - The map's resolution is finite: a cell is covered only when all its
//    directions are; kDirectionMapCellsPerVoxel cells per voxel at the grid's
//    far side bound the occlusion lost to that rounding.
// The vectorized cap polygons (grid/bitmap_vectorize.h) serve the window and the
// tests, which check this map against a brute-force extrusion of the caps.
//
// Coordinates: world; faces f = 0..5 are +x, -x, +y, -y, +z, -z; on face f with
// axis a = f / 2 and sign s, the in-face axes are b = (a + 1) % 3 and
// c = (a + 2) % 3, and cell (i, j) holds the directions (r_a, r_b, r_c) =
// (s, u, v) with u in [-1 + 2i/R, -1 + 2(i+1)/R], v likewise with j.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "grid/bit_matrix.h"

namespace gridcull {

constexpr int kDirectionMapCellsPerVoxel = 2;
constexpr int kMinDirectionMapResolution = 64;
constexpr int kMaxDirectionMapResolution = 512;

// Cells [i0, i1] x [j0, j1] of face `face` (inclusive; empty when i0 > i1).
struct DirectionRect {
    int face = 0;
    int i0 = 0, i1 = -1, j0 = 0, j1 = -1;
    bool empty() const { return i0 > i1 || j0 > j1; }
};

// A map face's cell as direction bounds: u in [u0, u1], v in [v0, v1].
struct DirectionCell {
    int face = 0;
    int i = 0, j = 0;
    double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
};

class RgvcDirectionMap {
public:
    // Cells per face side for a grid of `longest` voxels along its longest axis.
    static int resolutionFor(int longest);

    // Sizes the map (R x R cells per face) and clears it.
    void resize(int resolution);
    // Clears every cell and takes the eye of this frame. O(cells / 64).
    void begin(const glm::dvec3& eye);
    // Forgets which cells each pass tried, for when pass numbers wrap; returns
    // the first pass number to use next. O(cells).
    uint32_t restartPasses();
    int resolution() const { return resolution_; }
    const glm::dvec3& eye() const { return eye_; }

    // The directions from the eye to the closed box, per face, as cell
    // rectangles; returns how many faces it meets (their rects fill out[0..n)),
    // or -1 when the box holds points too close to the eye for the footprint to
    // be bounded (then the box is never covered).
    int footprint(const glm::dvec3& lo, const glm::dvec3& hi,
                  std::array<DirectionRect, 6>& out) const;
    // Is every direction from the eye to the closed box covered?
    bool coversBox(const glm::dvec3& lo, const glm::dvec3& hi) const;
    // False when no part of the box can be covered: its footprint misses every
    // covered cell's bounds (a quick test for whole runs of voxels).
    bool mayCoverPartOf(const glm::dvec3& lo, const glm::dvec3& hi) const;
    bool covered(int face, int i, int j) const { return cells_.get(i, cells_.row(j, face)); }
    // The index of cell (face, i, j) in face-major, row, column order.
    size_t cellIndex(int face, int i, int j) const {
        return (size_t(face) * size_t(resolution_) + size_t(j)) * size_t(resolution_) + size_t(i);
    }
    // The cell holding the direction from the eye to p (p != eye).
    void cellOfPoint(const glm::dvec3& p, int& face, int& i, int& j) const;
    DirectionCell cell(int face, int i, int j) const;

    // Takes the frustum's four edge directions: cells far outside the frustum
    // are never worth covering (clipToFrustum).
    void setFrustum(const std::array<glm::dvec3, 4>& edges);
    // Cuts `rect` to the frustum's cells on its face widened by `margin` cells;
    // false when nothing is left.
    bool clipToFrustum(DirectionRect& rect, int margin) const;

    // Covers each cell of `rect` not yet covered and not yet tried in `pass`
    // (passes number the layers; a cell that failed once in a pass would fail
    // again) for which blocked(cell) is true. Returns the cells covered.
    template <typename Blocked>
    int64_t coverCells(const DirectionRect& rect, uint32_t pass, Blocked&& blocked) {
        int64_t n = 0;
        for (int j = rect.j0; j <= rect.j1; ++j) {
            const int row = cells_.row(j, rect.face);
            if (cells_.allSet(row, rect.i0, rect.i1)) continue;
            for (int i = rect.i0; i <= rect.i1; ++i) {
                if (cells_.get(i, row)) continue;
                uint32_t& tried = tried_[size_t(row) * size_t(resolution_) + size_t(i)];
                if (tried == pass) continue;
                tried = pass;
                if (blocked(cell(rect.face, i, j))) {
                    cells_.set(i, row);
                    DirectionRect& b = covered_bounds_[size_t(rect.face)];
                    b.i0 = std::min(b.i0, i), b.i1 = std::max(b.i1, i);
                    b.j0 = std::min(b.j0, j), b.j1 = std::max(b.j1, j);
                    ++n;
                }
            }
        }
        return n;
    }
    int64_t coveredCount() const { return cells_.count(); }
    size_t memoryBytes() const {
        return cells_.memoryBytes() + tried_.capacity() * sizeof(uint32_t);
    }

private:
    // The footprint on one face: 1 with `r` filled, 0 when the box has no
    // direction there, -1 when it is unbounded (see footprint()).
    int faceFootprint(int face, const glm::dvec3& lo, const glm::dvec3& hi, DirectionRect& r) const;

    int resolution_ = 0;
    glm::dvec3 eye_{0.0};
    std::array<DirectionRect, 6> frustum_cells_{};  // per face; empty when it has none
    // Per face, the cells holding every covered one (empty when none is): most
    // boxes a traversal asks about lie outside, found without a division.
    std::array<DirectionRect, 6> covered_bounds_{};
    BitMatrix cells_;              // R x R x 6
    std::vector<uint32_t> tried_;  // per cell, the last pass that tried it
};

// The world-space rectangle, on the plane x_axis = plane, that holds every point
// where a ray from `eye` with direction in `cell` meets that plane (in the two
// other axes, (axis + 1) % 3 then (axis + 2) % 3). Returns false when no ray
// of the cell meets the plane ahead of the eye. When some rays meet it
// arbitrarily far out, the rectangle extends to infinity on that side.
struct PlaneRect {
    double lo[2] = {0.0, 0.0};
    double hi[2] = {0.0, 0.0};
};
bool cellOnPlane(const DirectionCell& cell, const glm::dvec3& eye, int axis, double plane,
                 PlaneRect& out);

}  // namespace gridcull
