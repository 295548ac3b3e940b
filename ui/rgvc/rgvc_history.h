// The matrices of regular-grid culling as they stood when the traversal had
// finished chess layer L, recovered from the snapshot's per-layer history
// (culling/rgvc/rgvc_snapshot.h: h_layer, o_layer, reveals), so the layer
// stepper shows the frame as it unfolded, not its end:
//   H at L: the voxels with h_layer <= L. 2D marks H eagerly (a layer's
//           occlusion polygons may mark voxels of the same layer), so a voxel
//           may enter H at its own layer; 3D marks a voxel when the traversal
//           reaches it.
//   O at L: O less the voxels a reveal made opaque after L (o_layer > L).
//   I at L: I less the ids of the objects whose TBVs were revealed after L (a
//           reveal writes its object into O and I at once).
//   T at L: T plus the TBVs revealed after L, as they were written (2D: the
//           curve cut to its box, or the filled disc; 3D: the box's surface, or
//           the filled box, found by the 2-of-3 test of Txy, Txz and Tyz).
// At the last layer each is the matrix at the end of the frame. Voxels are
// (x, y, z) indices of the snapshot's grid, z = 0 in 2D; callers check bounds.
// Stateless: every call reads the snapshot; costs are per call.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "culling/rgvc/rgvc_snapshot.h"
#include "culling/rgvc/rgvc_tbv.h"
#include "culling/rgvc/rgvc_tbv3d.h"

namespace gridcull {

inline size_t rgvcLinear(const RegularGrid& grid, int x, int y, int z) {
    return (size_t(z) * size_t(grid.resolution.y) + size_t(y)) * size_t(grid.resolution.x) +
           size_t(x);
}
inline bool rgvcInside(const RegularGrid& grid, int x, int y, int z) {
    return x >= 0 && y >= 0 && z >= 0 && x < grid.resolution.x && y < grid.resolution.y &&
           z < grid.resolution.z;
}

// H and O at layer L. O(1).
bool rgvcHAt(const RgvcSnapshot& s, int x, int y, int z, int64_t layer);
bool rgvcOAt(const RgvcSnapshot& s, int x, int y, int z, int64_t layer);
// Os, which the traversal never changes.
bool rgvcOsAt(const RgvcSnapshot& s, int x, int y, int z);

// The layer at which this frame's traversal revealed the TBV of object `index`
// (-1: before the traversal), or kRgvcNoLayer. O(reveals).
int32_t rgvcRevealLayerOf(const RgvcSnapshot& s, int index);

// Calls fn(index) for each object index in I at voxel (x, y, z) at layer L,
// static objects first. O(list lengths * reveals).
template <typename Fn>
void rgvcForEachIdAt(const RgvcSnapshot& s, int x, int y, int z, int64_t layer, Fn&& fn) {
    const int row = y + z * s.grid.resolution.y;
    if (s.identifiers_static) s.identifiers_static->forEach(x, row, fn);
    if (!s.identifiers_dynamic) return;
    s.identifiers_dynamic->forEach(x, row, [&](int32_t index) {
        const int32_t revealed = rgvcRevealLayerOf(s, index);
        if (revealed == kRgvcNoLayer || revealed <= layer) fn(index);
    });
}

// Calls fn(index) for each TBV whose id the 2-of-3 test of section 5.2 finds at
// 3D voxel (x, y, z) in the end-of-frame Txy, Txz and Tyz, each once. O(list
// lengths squared), nothing when fewer than two of the three cells hold ids.
template <typename Fn>
void rgvcForEachTbvIdAt3d(const RgvcSnapshot& s, int x, int y, int z, Fn&& fn) {
    if (!s.tbvs || !s.tbvs_xz || !s.tbvs_yz) return;
    const bool xy = !s.tbvs->empty(x, y), xz = !s.tbvs_xz->empty(x, z),
               yz = !s.tbvs_yz->empty(y, z);
    if (int(xy) + int(xz) + int(yz) < 2) return;
    if (xy)
        s.tbvs->forEach(x, y, [&](int32_t id) {
            if ((xz && s.tbvs_xz->contains(x, z, id)) || (yz && s.tbvs_yz->contains(y, z, id)))
                fn(id);
        });
    if (xz && yz)
        s.tbvs_xz->forEach(x, z, [&](int32_t id) {
            if (!(xy && s.tbvs->contains(x, y, id)) && s.tbvs_yz->contains(y, z, id)) fn(id);
        });
}

// Calls fn(x, y, z) for each voxel of the TBV's form as written into T (2D:
// the curve cut to its box or the filled disc, z = 0, a voxel possibly twice;
// 3D: the surface of its box or the filled box). Nothing for a TBV kept out of
// T (`edge`). O(voxels of the form).
template <typename Fn>
void rgvcForEachTbvVoxel(const RgvcSnapshot& s, const RgvcTbvView& tbv, Fn&& fn) {
    if (tbv.edge) return;
    if (s.dimensions == 2) {
        const glm::ivec3 res = s.grid.resolution;
        const auto put = [&](int x, int y) {
            if (x >= 0 && y >= 0 && x < res.x && y < res.y) fn(x, y, 0);
        };
        const RgvcTbvCurve curve{tbv.curve_centre, tbv.curve_radius};
        if (tbv.filled)
            forEachTbvFilledSpanClipped(curve, tbv.cells, [&](int y, int x0, int x1) {
                for (int x = x0; x <= x1; ++x) put(x, y);
            });
        else
            forEachTbvBoundaryVoxelClipped(curve, tbv.cells, put);
        return;
    }
    const RgvcVoxelBox& b = tbv.cells;
    for (int z = b.lo.z; z <= b.hi.z; ++z)
        for (int y = b.lo.y; y <= b.hi.y; ++y) {
            // Inner rows of the box touch its surface at their two ends only.
            const bool whole =
                tbv.filled || z == b.lo.z || z == b.hi.z || y == b.lo.y || y == b.hi.y;
            if (whole) {
                for (int x = b.lo.x; x <= b.hi.x; ++x) fn(x, y, z);
            } else {
                fn(b.lo.x, y, z);
                if (b.hi.x != b.lo.x) fn(b.hi.x, y, z);
            }
        }
}

// Does the TBV's form as written into T hold voxel (x, y, z)? 3D O(1); 2D
// O(curve voxels).
bool rgvcTbvFormHolds(const RgvcSnapshot& s, const RgvcTbvView& tbv, int x, int y, int z);

// Calls fn(index, revealed_layer) for each TBV in T at voxel (x, y, z) at layer
// L: those of the end-of-frame T (revealed_layer kRgvcNoLayer; 2D: an index may
// come twice) and those revealed after L whose form holds the voxel.
template <typename Fn>
void rgvcForEachTbvAt(const RgvcSnapshot& s, int x, int y, int z, int64_t layer, Fn&& fn) {
    if (s.dimensions == 2) {
        if (s.tbvs) s.tbvs->forEach(x, y, [&](int32_t id) { fn(id, kRgvcNoLayer); });
    } else {
        rgvcForEachTbvIdAt3d(s, x, y, z, [&](int32_t id) { fn(id, kRgvcNoLayer); });
    }
    for (const RgvcRevealView& r : s.reveals)
        if (r.layer > layer && rgvcTbvFormHolds(s, r.tbv, x, y, z))
            fn(int32_t(r.tbv.object_index), r.layer);
}

}  // namespace gridcull
