#include "ui/rgvc/rgvc_voxel_info.h"

#include <algorithm>

#include "ui/rgvc/rgvc_history.h"

namespace gridcull {

int32_t rgvcCauseOf(const RgvcSnapshot& snapshot, glm::ivec3 v) {
    if (!rgvcInside(snapshot.grid, v.x, v.y, v.z)) return -1;
    const size_t i = rgvcLinear(snapshot.grid, v.x, v.y, v.z);
    return i < snapshot.h_cause.size() ? snapshot.h_cause[i] : -1;
}

void describeRgvcVoxel(const RgvcSnapshot& snapshot, const Scene& scene, glm::ivec3 v,
                       RgvcVoxelInfo& out) {
    out.valid = false;
    out.dimensions = snapshot.dimensions;
    out.voxel = v;
    out.o = out.os = out.h = false;
    out.h_layer = out.o_layer = kRgvcNoLayer;
    out.cause = -1;
    out.ids_i.clear();
    out.ids_t.clear();
    out.visit_order = -1;
    out.layer = -1;
    out.visited_occluded = false;
    if (!snapshot.valid || !snapshot.occluder) return;
    if (!rgvcInside(snapshot.grid, v.x, v.y, v.z)) return;
    out.valid = true;
    const int row = v.y + v.z * snapshot.grid.resolution.y;
    out.o = snapshot.occluder->get(v.x, row);
    out.os = rgvcOsAt(snapshot, v.x, v.y, v.z);
    out.h = snapshot.occlusion && snapshot.occlusion->get(v.x, row);
    const size_t linear = rgvcLinear(snapshot.grid, v.x, v.y, v.z);
    if (linear < snapshot.h_layer.size()) out.h_layer = snapshot.h_layer[linear];
    if (linear < snapshot.o_layer.size()) out.o_layer = snapshot.o_layer[linear];
    out.cause = out.h ? rgvcCauseOf(snapshot, v) : -1;
    const auto idOf = [&](int32_t index) {
        return index >= 0 && size_t(index) < scene.objects.size() ? scene.objects[size_t(index)].id
                                                                  : int(index);
    };
    // Every id at the end of the frame: the last layer shows them all.
    const int64_t end = INT64_MAX;
    rgvcForEachIdAt(snapshot, v.x, v.y, v.z, end,
                    [&](int32_t index) { out.ids_i.push_back(idOf(index)); });
    std::sort(out.ids_i.begin(), out.ids_i.end());
    out.ids_i.erase(std::unique(out.ids_i.begin(), out.ids_i.end()), out.ids_i.end());
    // T at the end of the frame and the TBVs revealed during the traversal (-1:
    // every reveal, whatever its layer).
    rgvcForEachTbvAt(snapshot, v.x, v.y, v.z, -2, [&](int32_t index, int32_t revealed) {
        out.ids_t.push_back({idOf(index), revealed});
    });
    std::sort(out.ids_t.begin(), out.ids_t.end(), [](const auto& a, const auto& b) {
        return a.id != b.id ? a.id < b.id : a.revealed < b.revealed;
    });
    out.ids_t.erase(std::unique(out.ids_t.begin(), out.ids_t.end(),
                                [](const auto& a, const auto& b) { return a.id == b.id; }),
                    out.ids_t.end());
    for (size_t k = 0; k < snapshot.visits.size(); ++k) {
        const RgvcVisit& visit = snapshot.visits[k];
        if (visit.voxel.x != v.x || visit.voxel.y != v.y || visit.z != v.z) continue;
        out.visit_order = int64_t(k);
        out.layer = visit.layer;
        out.visited_occluded = visit.occluded;
        break;
    }
}

}  // namespace gridcull
