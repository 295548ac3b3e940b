#include "ui/rgvc/rgvc_frame_index.h"

#include <algorithm>

#include "ui/rgvc/rgvc_history.h"

namespace gridcull {

void RgvcFrameIndex::update(const RgvcSnapshot& s, int64_t layer) {
    const RgvcSnapshotStamp key = RgvcSnapshotStamp::of(s);
    const bool same = key == key_;
    if (same && layer == layer_) return;
    res_ = s.grid.resolution;
    const size_t voxels = size_t(s.grid.voxelCount());
    if (!same) {
        key_ = key;
        visit_.assign(voxels, -1);
        for (size_t k = 0; k < s.visits.size(); ++k) {
            const RgvcVisit& v = s.visits[k];
            if (!rgvcInside(s.grid, v.voxel.x, v.voxel.y, v.z)) continue;
            int32_t& slot = visit_[linear(v.voxel.x, v.voxel.y, v.z)];
            if (slot < 0) slot = int32_t(k);
        }
    }
    layer_ = layer;
    revealed_tbv_.assign(voxels, 0);
    for (const RgvcRevealView& r : s.reveals) {
        if (r.layer <= layer) continue;
        rgvcForEachTbvVoxel(s, r.tbv, [&](int x, int y, int z) {
            if (rgvcInside(s.grid, x, y, z)) revealed_tbv_[linear(x, y, z)] = 1;
        });
    }
}

}  // namespace gridcull
