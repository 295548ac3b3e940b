// Everything regular-grid culling knows about one voxel of its last frame, for
// the panel's "voxel under the mouse" (2D and 3D): O, Os, H with the layer at
// which the voxel entered H and the occluder that put it there, I and T ids
// (3D: T by the 2-of-3 test of Txy, Txz, Tyz), and the traversal's visit.
// Reads culling/rgvc/rgvc_snapshot.h; the history rules are ui/rgvc/rgvc_history.h's.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "culling/rgvc/rgvc_snapshot.h"
#include "culling/scene/scene.h"

namespace gridcull {

// A T id at the voxel: its object id, and kRgvcNoLayer when it is still in T
// at the end of the frame, else the layer at which its TBV was revealed.
struct RgvcTbvAtVoxel {
    int id = -1;
    int32_t revealed = kRgvcNoLayer;
};

// `ids_i` / `ids_t` are object ids (Scene::objects[i].id), ascending, each once;
// their capacity is reused between calls.
struct RgvcVoxelInfo {
    bool valid = false;  // false: outside the grid or no snapshot
    int dimensions = 2;
    glm::ivec3 voxel{0};                    // z = 0 in 2D
    bool o = false, os = false, h = false;  // at the end of the frame
    int32_t h_layer = kRgvcNoLayer;         // the layer at which it entered H
    int32_t o_layer = kRgvcNoLayer;         // a reveal made it opaque at this layer
    // Why it is in H: the index of the occluder that hid it (2D: in
    // RgvcSnapshot::occluders, whose occlusion polygon marked it first; 3D: in
    // occluders3d, whose layer's pass covered the direction of its centre), -1
    // when not in H or not known.
    int32_t cause = -1;
    std::vector<int> ids_i;
    std::vector<RgvcTbvAtVoxel> ids_t;
    int64_t visit_order = -1;  // index in RgvcSnapshot::visits; -1: not visited
    int64_t layer = -1;        // chess layer of that visit
    bool visited_occluded = false;
};

// Fills `out` for voxel `v` of `snapshot` (z = 0 in 2D). Cost: O(visits) for
// the visit search plus the voxel's list lengths and the reveals; allocates
// only when the id lists outgrow `out`.
void describeRgvcVoxel(const RgvcSnapshot& snapshot, const Scene& scene, glm::ivec3 v,
                       RgvcVoxelInfo& out);
inline void describeRgvcVoxel(const RgvcSnapshot& snapshot, const Scene& scene, glm::ivec2 v,
                              RgvcVoxelInfo& out) {
    describeRgvcVoxel(snapshot, scene, glm::ivec3(v, 0), out);
}

// The occluder that hid voxel `v` (its RgvcSnapshot::h_cause), -1 when none.
int32_t rgvcCauseOf(const RgvcSnapshot& snapshot, glm::ivec3 v);

}  // namespace gridcull
