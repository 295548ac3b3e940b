#include "ui/rgvc/rgvc_pick3d.h"

#include "ui/rgvc/rgvc_slice.h"
#include "ui/rgvc/rgvc_voxel_boxes.h"
#include "ui/rgvc/rgvc_voxel_info.h"

namespace gridcull {

bool pickRgvcVoxel3d(const RgvcSnapshot& s, const RgvcViewState& view, const RgvcFrameIndex& index,
                     int64_t layer, const glm::dvec3& origin, const glm::dvec3& direction,
                     glm::ivec3& out) {
    const RegularGrid& g = s.grid;
    if (view.mode == RgvcVoxelMode::Slice) {
        const int a = std::clamp(view.slice_axis, 0, 2);
        const int n = rgvcSliceIndex(s, view);
        if (direction[a] == 0.0) return false;
        const double t = (rgvcSlicePlane(g, a, n) - origin[a]) / direction[a];
        if (t < 0.0) return false;
        glm::ivec3 v = rgvcVoxelOfPoint(g, origin + direction * t);
        v[a] = n;
        if (!g.inside(v)) return false;
        out = v;
        return true;
    }
    if (rgvcFirstVoxelOnRay(
            g, origin, direction,
            [&](const glm::ivec3& v) {
                return rgvcBoxKindAt(s, view, index, layer, v.x, v.y, v.z) != RgvcBoxKind::None;
            },
            out))
        return true;
    return rgvcFirstVoxelOnRay(
        g, origin, direction,
        [&](const glm::ivec3& v) { return index.visitOf(v.x, v.y, v.z) >= 0; }, out);
}

int rgvcOccluder3dAt(const RgvcSnapshot& s, glm::ivec3 v) {
    for (size_t k = 0; k < s.occluders3d.size(); ++k)
        if (s.occluders3d[k].voxel == v) return int(k);
    const int32_t cause = rgvcCauseOf(s, v);
    return cause >= 0 && size_t(cause) < s.occluders3d.size() ? cause : -1;
}

}  // namespace gridcull
