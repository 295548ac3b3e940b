// What octree + hierarchical z-buffer culling with temporal bounding volumes
// (`hzb-tbv`, `hzb-tbvi`, `hzb`; culling/hzb_tbv/hzb_tbv_culler.h) did in its
// last frame, for the window and for tests, in Sudarsky & Gotsman's terms
// ("Dynamic scene occlusion culling", sections 3.3 to 3.7 and 4):
//  - per dynamic object (D) its state after the frame and what happened to its
//    TBV in it (expired, revealed, violated), and its TBV: the box T holds for
//    it, creation time, expiration date, time left, validity period;
//  - the next expiration events of Q, earliest first;
//  - the octree nodes the front-to-back traversal reached, each with its box,
//    depth and outcome (outside the frustum, hidden by the Z-pyramid, entered);
//  - the coarse levels of the Z-pyramid as the frame left them, as floats;
//  - the frame's counters.
//
// Filled only while HzbTbvCuller::setDebugCapture(true), at the end of cull()
// (the node visits during the traversal), from the culler's structures: capture
// reads them and changes nothing, so the PVS is the same with it on or off, and
// off it costs one branch per node. Everything is owned by the snapshot; its
// vectors keep their capacity across frames, so a steady state allocates
// nothing. Object indices index Scene::objects (scene.objects[i].id is the id).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "culling/api/counters.h"
#include "culling/api/debug_snapshot.h"
#include "culling/tbv/tbv_manager.h"
#include "grid/aabb.h"

namespace gridcull {

// A dynamic object's standing in the frame, as the window names it: its state
// after step 4, unless its TBV ended in this frame, which is what the frame did
// to it (the manager's Expired, Revealed and Violated last only until step 4).
enum class HzbObjectStatus : uint8_t {
    Visible,   // in V, seen in step 3 (and no TBV of its ended this frame)
    Hidden,    // under a valid TBV (HzbTbvObject::new_tbv: made in this frame's step 4)
    Expired,   // its TBV's validity period ran out in step 1 (seen or given a new TBV since)
    Revealed,  // its TBV was found visible in step 3 (the object was then tested itself)
    Violated,  // its fuzzy TBV was reported violated, or invalidated at random (Fig. 14)
    Culled,    // `hzb` only (no TBVs): written in T this frame, not seen
};
constexpr int kHzbObjectStatusCount = 6;

struct HzbTbvObject {
    int32_t object_index = -1;
    int32_t object_id = -1;
    HzbObjectStatus status = HzbObjectStatus::Visible;
    TbvObjectState state = TbvObjectState::Visible;  // the manager's, after step 4
    bool in_pvs = false;
    bool has_tbv = false;    // hidden under a TBV at the end of the frame
    bool new_tbv = false;    // that TBV was made in this frame's step 4
    Aabb tbv;                // the TBV's box, what T holds in the object's place (has_tbv)
    double created = 0.0;    // seconds (has_tbv)
    double expiry = 0.0;     // the expiration date, seconds; +infinity: never (has_tbv)
    double remaining = 0.0;  // expiry - t (has_tbv)
    double period = 0.0;     // the validity period its next TBV gets, seconds
};

// One expiration event of Q.
struct HzbExpiry {
    int32_t object_index = -1;
    int32_t object_id = -1;
    double expiry = 0.0;     // seconds
    double remaining = 0.0;  // expiry - t
};
// How many of Q's next events the snapshot keeps.
constexpr size_t kHzbNextExpiries = 16;

// What the traversal did at an octree node.
enum class HzbNodeOutcome : uint8_t {
    FrustumCulled,  // its box lies outside the view frustum: skipped with its subtree
    ZCulled,        // its box is hidden by the Z-pyramid: skipped with its subtree
    Entered,        // its entries were visited and its children traversed
};
constexpr int kHzbNodeOutcomeCount = 3;

struct HzbNodeVisit {
    Aabb box;             // the node's cell (world units)
    int32_t node = 0;     // DynamicOctree node index
    int32_t depth = 0;    // the root is 0
    int32_t entries = 0;  // objects and TBVs associated with the node
    HzbNodeOutcome outcome = HzbNodeOutcome::Entered;
};

// One captured level of the Z-pyramid: `width` x `height` texels from
// HzbTbvSnapshot::pyramid_texels[offset], row-major, top row first, each the
// farthest view-space depth of its footprint (world units; +infinity: empty).
struct HzbPyramidLevel {
    int32_t level = 0;  // the pyramid's own level number (0: the z-buffer)
    int32_t width = 0;
    int32_t height = 0;
    size_t offset = 0;
};
// Levels with at most this many texels on each side are captured.
constexpr int kHzbMaxCapturedSide = 256;

struct HzbTbvSnapshot final : DebugSnapshot {
    static const DebugSnapshotKind kKind;
    HzbTbvSnapshot() : DebugSnapshot(kKind) {}

    bool valid = false;
    bool uses_tbvs = true;                         // false: `hzb`
    TbvUpdateMode mode = TbvUpdateMode::Explicit;  // TBVe or TBVi (uses_tbvs)
    int64_t frame = 0;                             // frames culled since reset, the first is 1
    double t = 0.0;

    // D: every dynamic object, in scene order, and where each sits in it.
    std::vector<HzbTbvObject> objects;
    std::vector<int32_t> slot_of_object;  // by object index: index in `objects`, or -1
    std::array<int64_t, kHzbObjectStatusCount> status_count{};
    const HzbTbvObject* objectAt(int object_index) const {
        if (object_index < 0 || size_t(object_index) >= slot_of_object.size()) return nullptr;
        const int32_t slot = slot_of_object[size_t(object_index)];
        return slot < 0 ? nullptr : &objects[size_t(slot)];
    }

    // Q: its size and its next events, earliest first (at most kHzbNextExpiries).
    size_t queue_size = 0;
    std::vector<HzbExpiry> next_expiries;

    // T: the nodes the traversal reached, in visit order (front to back).
    std::vector<HzbNodeVisit> nodes;
    std::array<int64_t, kHzbNodeOutcomeCount> node_count{};
    int octree_nodes = 0;      // live nodes of T after the frame
    int octree_max_depth = 0;  // the depth bound (--hzb-octree-depth)

    // The Z-pyramid: its level-0 size, how many levels it has, and the levels
    // of at most kHzbMaxCapturedSide texels a side, finest first.
    int pyramid_width = 0;
    int pyramid_height = 0;
    int pyramid_level_count = 0;
    std::vector<HzbPyramidLevel> pyramid_levels;
    std::vector<float> pyramid_texels;
    const HzbPyramidLevel* pyramidLevel(int level) const {
        for (const HzbPyramidLevel& l : pyramid_levels)
            if (l.level == level) return &l;
        return nullptr;
    }

    // The frame's counters (the culler's FrameResult::stats) and the TBV
    // manager's own (messages, violations).
    CullStats stats;
    TbvFrameCounters tbv_counters;
};

const char* hzbObjectStatusName(HzbObjectStatus status);
const char* hzbNodeOutcomeName(HzbNodeOutcome outcome);

}  // namespace gridcull
