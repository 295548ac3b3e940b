#include "ui/rgvc/rgvc_object_voxels.h"

#include <algorithm>

#include "culling/rgvc/rgvc_tbv.h"
#include "ui/rgvc/rgvc_history.h"
#include "ui/rgvc/rgvc_voxel_info.h"

namespace gridcull {

void describeRgvcObject(const RgvcSnapshot& s, const Scene& scene, const RgvcFrameIndex& index,
                        int object_index, RgvcObjectVoxels& out) {
    out.index = -1;
    out.id = -1;
    out.voxels.clear();
    out.open = out.occluded = out.unreached = 0;
    out.under_tbv = false;
    out.revealed = kRgvcNoLayer;
    if (!s.valid || !s.occluder || object_index < 0 || size_t(object_index) >= scene.objects.size())
        return;
    const SceneObject& object = scene.objects[size_t(object_index)];
    out.index = object_index;
    out.id = object.id;
    for (const RgvcTbvView& tbv : s.tbv_list)
        out.under_tbv = out.under_tbv || tbv.object_index == object_index;
    out.revealed = rgvcRevealLayerOf(s, object_index);
    // Its voxels in I: within the voxels its bounds touch at the frame's time.
    const RgvcVoxelBox box = voxelBoxTouching(s.grid, scene.boundsAt(object, s.t));
    const IdListMatrix* lists[2] = {s.identifiers_static, s.identifiers_dynamic};
    const IdListMatrix* list = lists[object.isDynamic() ? 1 : 0];
    if (!list) return;
    for (int z = box.lo.z; z <= box.hi.z; ++z)
        for (int y = box.lo.y; y <= box.hi.y; ++y)
            for (int x = box.lo.x; x <= box.hi.x; ++x) {
                if (!list->contains(x, y + z * s.grid.resolution.y, int32_t(object_index)))
                    continue;
                RgvcObjectVoxel v;
                v.voxel = {x, y, z};
                const int32_t visit = index.visitOf(x, y, z);
                if (visit >= 0) {
                    v.layer = s.visits[size_t(visit)].layer;
                    v.occluded = s.visits[size_t(visit)].occluded;
                    if (v.occluded) v.cause = rgvcCauseOf(s, v.voxel);
                }
                (v.layer < 0 ? out.unreached : v.occluded ? out.occluded : out.open) += 1;
                out.voxels.push_back(v);
            }
    const auto rank = [](const RgvcObjectVoxel& v) { return v.layer < 0 ? 2 : v.occluded ? 1 : 0; };
    std::sort(out.voxels.begin(), out.voxels.end(),
              [&](const RgvcObjectVoxel& a, const RgvcObjectVoxel& b) {
                  return rank(a) != rank(b) ? rank(a) < rank(b) : a.layer < b.layer;
              });
}

}  // namespace gridcull
