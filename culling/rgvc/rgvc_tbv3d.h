// Cubical temporal bounding volumes in the three TBV matrices Txy, Txz and Tyz
// (Batagelo & Wu, section 5.2): a hidden dynamic object is represented by an
// axis-aligned box that surely contains it until the TBV expires (its bounds
// grown by max speed * validity on every side, cut to where the object can ever
// be), written as the orthographic projections of the box's faces' edges onto
// the coordinate planes: the outline of its x-y rectangle into Txy, of its x-z
// rectangle into Txz, of its y-z rectangle into Tyz.
//
// The existence test: voxel (x, y, z) holds the TBV when its id is in at least
// two of Txy(x, y), Txz(x, z), Tyz(y, z), i.e. (Txy or Tyz) and (Txy or Txz) and
// (Tyz or Txz). With outlines that is exactly the box's surface voxels (a voxel
// with x on the x-y outline and z in the box's range has Txy and Txz; one
// inside the box has none; one outside has at most one). Every 26-connected
// path of voxels from outside the box to inside it meets the surface, and the
// voxels a ray passes form such a path, so a ray from a viewer outside the box
// to the object meets a surface voxel first. Valid while the viewer's voxel is
// outside the box and moves 26-connected between frames, as in 2D.
// The filled form writes the three filled rectangles: the test then holds for
// every voxel of the box, found whatever the viewer does.
//
// Cost: outlines are 2 (dx + dy) + 2 (dx + dz) + 2 (dy + dz) cells for a box of
// dx x dy x dz voxels, where a filled cube (or a sphere's surface) would be
// quadratic; the filled form is quadratic.
#pragma once
#include "culling/rgvc/rgvc_tbv.h"

namespace gridcull {

enum class TbvPlane { Xy, Xz, Yz };

// Calls fn(plane, a, b) for each projection cell of `box` (a, b: the plane's
// first and second axis, x-y, x-z or y-z); outlines unless `filled`.
template <typename Fn>
void forEachTbvProjectionCell(const RgvcVoxelBox& box, bool filled, Fn&& fn) {
    auto rectangle = [&](TbvPlane plane, int a0, int a1, int b0, int b1) {
        for (int b = b0; b <= b1; ++b) {
            if (filled || b == b0 || b == b1) {
                for (int a = a0; a <= a1; ++a) fn(plane, a, b);
            } else {
                fn(plane, a0, b);
                if (a1 != a0) fn(plane, a1, b);
            }
        }
    };
    rectangle(TbvPlane::Xy, box.lo.x, box.hi.x, box.lo.y, box.hi.y);
    rectangle(TbvPlane::Xz, box.lo.x, box.hi.x, box.lo.z, box.hi.z);
    rectangle(TbvPlane::Yz, box.lo.y, box.hi.y, box.lo.z, box.hi.z);
}

// Is voxel v on the surface of `box` (what the outlines' 2-of-3 test finds)?
inline bool onTbvBoxSurface(const RgvcVoxelBox& box, const glm::i64vec3& v) {
    if (!box.contains(v)) return false;
    return v.x == box.lo.x || v.x == box.hi.x || v.y == box.lo.y || v.y == box.hi.y ||
           v.z == box.lo.z || v.z == box.hi.z;
}

}  // namespace gridcull
