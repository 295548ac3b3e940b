// The conservative interior of a closed triangle mesh as a few axis-aligned boxes,
// for regular-grid culling in 3D. Batagelo & Wu, section 5.1: opaque voxels come
// only from a simplified model that lies entirely inside the original geometry.
// Here that model is a list of boxes, each proven to lie inside the solid, so a
// voxel is never opaque unless it is wholly inside a closed mesh, and an open
// mesh is never opaque.
//
// Method (each step keeps the proof that a box is inside):
//  1. A lattice over the mesh's bounds with `resolution` cells along the longest
//     axis and near-cubic cells on the others (never longer than on the longest).
//  2. Each triangle is binned into the closed cells it touches (triangle-box
//     separating-axis test on the cells under its bounding box). The test leans
//     towards "touches" by a margin of 1e-7 of the mesh's scale, far above double
//     rounding, so a cell reported free has no surface in it or on its faces.
//  3. Free cells sharing a face form components; no surface separates the cells of
//     one component, so the whole component is inside or the whole is outside.
//     A component that reaches the lattice's outer layer is outside (a point on
//     the bounds off the surface cannot be inside). Every other component is
//     classified by ray parity (even-odd): three rays, along +x, +y and +z, from a
//     point in one of its cells, walked through the lattice row so that only the
//     triangles binned there are tested. A ray that passes within the margin of a
//     triangle's edge or vertex, or runs along its plane, is thrown away and cast
//     again from another point; the three must agree, else the component is
//     treated as outside.
//  4. Interior cells are merged greedily into boxes, largest first: from every
//     interior cell, a box grows in +x, +y and +z (all six axis orders, the best
//     kept); the largest still-free box is taken, its cells removed, and so on.
//     Lazily: a cell is grown from only when a cheap upper bound on its box tops
//     what is known, and grown again when a taken box took some of its cells.
//
// The paper asks only that the simplified model lie entirely inside the original;
// here it is made of whole lattice cells, so a box is never larger than the cells
// it is made of: where the surface crosses a cell, all of that cell is given up,
// and a face of the mesh that lies on a lattice plane (a box mesh's, always) costs
// the whole layer of cells next to it. Parity (even-odd) defines the solid, as the
// renderer's parity fill does; for a self-intersecting mesh that is a subset of
// what the surface encloses.
#pragma once
#include <vector>

#include "culling/scene/scene.h"
#include "grid/aabb.h"

namespace gridcull {

// A finer lattice gains little for a culling grid and costs memory in the cube
// of the resolution.
constexpr int kMaxMeshInteriorResolution = 64;

struct MeshInteriorOptions {
    int resolution = 24;  // cells along the longest axis, [1, kMaxMeshInteriorResolution]
    int max_boxes = 64;   // at most this many boxes are returned, >= 0
};

// Object-space boxes (the frame of TriangleMesh::vertices), each wholly inside the
// solid bounded by the closed mesh, pairwise without common volume, largest volume
// first. Empty for an open mesh (mesh.closed false), a flat or degenerate one, or
// one too thin to hold a lattice cell clear of its surface (fewer than three
// cells across on some axis). The boxes are unions of lattice cells, so how much
// of the solid they cover depends on `resolution`, finer being usually fuller.
// Preconditions (asserted): options in range, indices a multiple of three naming
// existing vertices.
// Cost: once per distinct mesh, at scene load. Binning is O(triangles x the cells
// under each one's bounding box); labelling O(cells); each ray tests only the
// triangles binned in its lattice row, three rays per enclosed component; the
// merge grows a seed in O(log resolution) table look-ups and updates the table in
// O(cells) per box taken. Memory O(cells + triangle-cell pairs).
std::vector<Aabb> meshInteriorBoxes(const TriangleMesh& mesh,
                                    const MeshInteriorOptions& options = {});

}  // namespace gridcull
