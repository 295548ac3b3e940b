// What identifies one rgvc snapshot's contents for the caches the window keeps
// over it (the frame index, the voxel boxes, a picked occluder's cap): the
// snapshot object, its frame and time, and the sizes of its per-frame lists. A
// cache rebuilds when the stamp changes, so a seek, a step or a new culling run
// never shows stale matrices.
#pragma once
#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "culling/rgvc/rgvc_snapshot.h"

namespace gridcull {

struct RgvcSnapshotStamp {
    const RgvcSnapshot* snapshot = nullptr;
    int64_t frame = -1;
    double t = 0.0;
    size_t visits = 0, reveals = 0, occluders = 0;
    glm::ivec3 resolution{0};

    static RgvcSnapshotStamp of(const RgvcSnapshot& s) {
        RgvcSnapshotStamp k;
        k.snapshot = &s;
        k.frame = s.frame;
        k.t = s.t;
        k.visits = s.visits.size();
        k.reveals = s.reveals.size();
        k.occluders = s.occluders.size() + s.occluders3d.size();
        k.resolution = s.grid.resolution;
        return k;
    }
    bool operator==(const RgvcSnapshotStamp& o) const {
        return snapshot == o.snapshot && frame == o.frame && t == o.t && visits == o.visits &&
               reveals == o.reveals && occluders == o.occluders && resolution == o.resolution;
    }
    bool operator!=(const RgvcSnapshotStamp& o) const { return !(*this == o); }
};

}  // namespace gridcull
