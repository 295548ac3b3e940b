// Per-voxel lookups the rgvc window derives from one snapshot and the layer it
// shows, built once and reused while neither changes: which visit reached each
// voxel (the snapshot lists visits in order, one per voxel), and which voxels
// TBVs revealed after the shown layer still held (T at that layer is T plus
// those, ui/rgvc/rgvc_history.h). The overlay, the voxel under the mouse and
// the culled object's voxels read it instead of searching the visit list.
//
// A snapshot is recognized by its address, frame, time and list sizes: the
// culler refills the same snapshot each frame, so update() after every cull.
// Memory: 5 bytes per grid voxel, kept; a steady state allocates nothing.
// Cost of an update that rebuilds: O(voxels + visits + revealed TBV voxels).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/rgvc/rgvc_snapshot_stamp.h"

namespace gridcull {

class RgvcFrameIndex {
public:
    // Indexes `snapshot` for `layer` (rgvcShownLayer's), unless it is indexed already.
    void update(const RgvcSnapshot& snapshot, int64_t layer);
    // The index in snapshot.visits of the visit of voxel (x, y, z), or -1.
    int32_t visitOf(int x, int y, int z) const {
        const size_t v = linear(x, y, z);
        return v < visit_.size() ? visit_[v] : -1;
    }
    // Was the voxel in T at the layer only through a TBV revealed after it?
    bool revealedTbvAt(int x, int y, int z) const {
        const size_t v = linear(x, y, z);
        return v < revealed_tbv_.size() && revealed_tbv_[v] != 0;
    }
    int64_t layer() const { return layer_; }

private:
    size_t linear(int x, int y, int z) const {
        return (size_t(z) * size_t(res_.y) + size_t(y)) * size_t(res_.x) + size_t(x);
    }

    RgvcSnapshotStamp key_;
    int64_t layer_ = -2;  // the layer revealed_tbv_ is for
    glm::ivec3 res_{0};
    std::vector<int32_t> visit_;
    std::vector<uint8_t> revealed_tbv_;
};

}  // namespace gridcull
