// Why regular-grid culling dropped (or kept) one object, for the panel: the
// voxels that hold it in I at the end of the frame, and for each whether the
// traversal reached it and found it occluded (and by which occluder) or open,
// or never reached it. An object is in the PVS when some voxel of it was
// reached open (and its bounds pass the frustum test); so for a culled object
// these are the voxels that hid it. A hidden moving object is not in I at all
// but under its TBV (T): then `under_tbv` is set and the list is empty.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/rgvc/rgvc_snapshot.h"
#include "culling/scene/scene.h"
#include "ui/rgvc/rgvc_frame_index.h"

namespace gridcull {

struct RgvcObjectVoxel {
    glm::ivec3 voxel{0};
    int32_t layer = -1;  // the layer of its visit; -1: not reached
    bool occluded = false;
    int32_t cause = -1;  // the occluder that hid it (RgvcVoxelInfo::cause's index), -1: none
};

struct RgvcObjectVoxels {
    int index = -1;  // object index; -1: none described
    int id = -1;
    // Reached open first, then occluded, then not reached; each by layer.
    std::vector<RgvcObjectVoxel> voxels;
    int64_t open = 0, occluded = 0, unreached = 0;
    bool under_tbv = false;           // hidden under a TBV in T during the frame's traversal
    int32_t revealed = kRgvcNoLayer;  // its TBV was revealed at this layer (-1: before)
};

// Fills `out` for object `object_index` of `scene` (-1: clears it). `index`
// must be updated for `s`. Cost: O(voxels of its bounding box * list lengths);
// allocates only when the list outgrows `out`.
void describeRgvcObject(const RgvcSnapshot& s, const Scene& scene, const RgvcFrameIndex& index,
                        int object_index, RgvcObjectVoxels& out);

}  // namespace gridcull
