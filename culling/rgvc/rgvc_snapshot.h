// What regular-grid culling (`rgvc`, culling/rgvc/rgvc_culler.h) did in its last
// frame, for the window and for tests: the matrices of Batagelo & Wu's section
// 3 as read-only views, the traversal in visit order with each voxel's chess
// layer, the seed voxels, the extended occluders with their four extension steps
// and occlusion polygons, and the TBVs.
//
// Filled only while RgvcCuller::setDebugCapture(true); otherwise only
// `valid` (false) and `memory` are kept, so culling pays nothing for it. The
// matrix pointers point into the culler and stay valid until its next cull()
// or reset(); everything else is owned by the snapshot. Ids in the matrices are
// object indices into Scene::objects (scene.objects[i].id is the id).
#pragma once
#include <array>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "culling/api/debug_snapshot.h"
#include "culling/rgvc/rgvc_occlusion.h"
#include "culling/rgvc/rgvc_occlusion3d.h"
#include "culling/rgvc/rgvc_tbv.h"
#include "grid/bit_matrix.h"
#include "grid/id_list_matrix.h"
#include "grid/regular_grid.h"

namespace gridcull {

// One voxel reached by the view-frustum traversal; its visit order is its index
// in RgvcSnapshot::visits.
struct RgvcVisit {
    glm::ivec2 voxel{0};
    int32_t z = 0;          // 3D: the voxel's z (voxel holds x and y)
    int32_t layer = 0;      // chess distance from the viewer's voxel
    bool occluded = false;  // in H when reached (then nothing else was done)
};

// 3D: a voxel that acted as an occluder (opaque, not occluded, wholly beyond
// the near plane) in its layer's extrusion into the direction map.
struct RgvcOccluder3d {
    glm::ivec3 voxel{0};
    int32_t layer = 0;
    int64_t cells_covered = 0;  // direction-map cells its layer's pass covered under it
};

// The seed voxel of one chess layer: where the layer's walk started. The
// Bresenham line of sight gives it; when that voxel does not touch the frustum
// (a narrow wedge seen from off the voxel centre) the walk starts at the nearest
// end of the layer's run instead and `moved` is set.
struct RgvcSeed {
    glm::i64vec2 voxel{0};  // may lie outside the grid
    int64_t z = 0;          // 3D
    int64_t layer = 0;
    bool moved = false;
};

struct RgvcOccluderView {
    int64_t layer = 0;  // the chess layer in which its initial voxel was reached
    RgvcExtendedOccluder occluder;
    int polygon_count = 0;
    // [0, polygon_count) are used: up to two per L, so four for a staircase.
    RgvcOcclusionPolygons polygons{};
    int64_t voxels_occluded = 0;  // voxels its polygons marked in H (some may repeat)
};

struct RgvcTbvView {
    int object_index = -1;
    int object_id = -1;
    glm::dvec3 centre{0.0};  // world
    double radius = 0.0;     // world
    double created = 0.0;    // seconds
    double expiry = 0.0;     // seconds; infinity for objects that cannot move
    glm::i64vec2 curve_centre{0};
    int curve_radius = 0;  // rho, voxels
    bool filled = false;   // written filled (the viewer could be inside)
    bool edge = false;     // may leave the grid: kept out of T, tested against the frustum
    RgvcVoxelBox cells;    // 3D: the box written into Txy, Txz, Tyz; 2D: the clip box
};

// A TBV that the traversal (or a teleport, or the frustum for an object that
// can leave the grid) revealed this frame, as it was before: TBVs at layer L
// are tbv_list plus the reveals of layers after L.
struct RgvcRevealView {
    int32_t layer = -1;  // -1: revealed before the traversal
    RgvcTbvView tbv;
};

// No layer: a voxel that never entered H (or O during the traversal).
constexpr int32_t kRgvcNoLayer = INT32_MAX;

// Bytes held by each matrix (capacities), present or not.
struct RgvcMatrixMemory {
    size_t occluder = 0;             // O
    size_t static_occluder = 0;      // Os, only with static objects
    size_t occlusion = 0;            // H
    size_t identifiers_static = 0;   // I, static objects' lists
    size_t identifiers_dynamic = 0;  // I, dynamic objects' lists
    size_t tbv = 0;                  // T (Txy, Txz and Tyz in 3D), only with dynamic objects
    size_t traversal = 0;      // scratch bits: visited and not occluded; 3D: voxels with I ids
    size_t direction_map = 0;  // 3D: the occlusion direction map

    size_t total() const {
        return occluder + static_occluder + occlusion + identifiers_static + identifiers_dynamic +
               tbv + traversal + direction_map;
    }
};

struct RgvcSnapshot final : DebugSnapshot {
    static const DebugSnapshotKind kKind;
    RgvcSnapshot() : DebugSnapshot(kKind) {}

    bool valid = false;
    int dimensions = 2;
    int64_t frame = 0;  // frames culled since reset, the first is 1
    double t = 0.0;
    RegularGrid grid;
    glm::dvec3 viewpoint{0.0};
    glm::dvec3 forward{1.0, 0.0, 0.0};
    double fov_deg = 0.0;
    double far = 0.0;
    glm::i64vec2 viewer_voxel{0};  // may lie outside the grid
    int64_t viewer_voxel_z = 0;    // 3D

    const BitMatrix* occluder = nullptr;                // O
    const BitMatrix* static_occluder = nullptr;         // Os (nullptr without static objects)
    const BitMatrix* occlusion = nullptr;               // H
    const IdListMatrix* identifiers_static = nullptr;   // I of static objects
    const IdListMatrix* identifiers_dynamic = nullptr;  // I of dynamic objects
    const IdListMatrix* tbvs = nullptr;               // T, 3D Txy (nullptr without dynamic objects)
    const IdListMatrix* tbvs_xz = nullptr;            // 3D Txz
    const IdListMatrix* tbvs_yz = nullptr;            // 3D Tyz
    const RgvcDirectionMap* direction_map = nullptr;  // 3D

    std::vector<RgvcVisit> visits;
    std::vector<RgvcSeed> seeds;
    std::vector<RgvcOccluderView> occluders;  // 2D
    std::vector<RgvcOccluder3d> occluders3d;  // 3D
    std::vector<RgvcTbvView> tbv_list;
    std::vector<RgvcRevealView> reveals;

    // Per-layer history, per voxel in RegularGrid::linearIndex order: the
    // matrices as they were at layer L are recovered from these.
    std::vector<int32_t> h_layer;  // the layer at which the voxel entered H, or kRgvcNoLayer
    std::vector<int32_t> o_layer;  // the layer at which a reveal made it opaque, or kRgvcNoLayer
                                   // (then O, if set, was set before the traversal)
    // Why a voxel is in H: 2D, the index in `occluders` of the first occluder
    // whose polygon marked it; 3D, the index in `occluders3d` of the occluder
    // whose layer pass covered the direction of the voxel's centre. -1: not in H.
    std::vector<int32_t> h_cause;
    // 3D: per direction-map cell (face-major, then row, then column), the index
    // in `occluders3d` of the occluder whose pass covered it, or -1.
    std::vector<int32_t> direction_cause;

    int64_t first_layer = 0;
    int64_t last_layer = -1;        // the last layer traversed
    bool terminated_early = false;  // stopped after a wholly occluded layer
    RgvcMatrixMemory memory;
};

}  // namespace gridcull
