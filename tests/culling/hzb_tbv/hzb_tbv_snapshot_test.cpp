// The hzb family's debug snapshot (culling/hzb_tbv/hzb_tbv_snapshot.h) against
// the culler it was captured from, on seeded random room scenes
// (hzb_random_rooms.h) for hzb-tbv, hzb-tbvi and hzb: capture on or off gives
// the same PVS and counters; each object's TBV is the manager's and the box T
// holds; the states agree with the manager and the frame's TBV counters; Q's
// next events are its earliest; the node visits add up to nodes_visited, are
// octree cells of their depth, and their outcomes agree with the frustum; the
// captured Z-pyramid levels are the pyramid's; a second run of the same frames
// allocates nothing for capture (a steady state allocates nothing).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/baseline/frustum_tests.h"
#include "culling/hzb_tbv/hzb_tbv_culler.h"
#include "culling/hzb_tbv/hzb_tbv_snapshot.h"
#include "tests/common/allocation_counter.h"
#include "tests/culling/hzb_tbv/hzb_random_rooms.h"

namespace gridcull {
namespace {

constexpr int kResolution = 128;  // small and fast; every level is captured
constexpr uint64_t kSeeds = 5;

struct Algo {
    const char* name;
    bool use_tbvs;
    TbvUpdateMode mode;
};
const Algo kAlgos[] = {{"hzb-tbv", true, TbvUpdateMode::Explicit},
                       {"hzb-tbvi", true, TbvUpdateMode::Implicit},
                       {"hzb", false, TbvUpdateMode::Explicit}};

HzbTbvCuller make(const Algo& a, const HzbTbvOptions& options, int resolution = kResolution) {
    return HzbTbvCuller(a.name, a.use_tbvs, a.mode, options, resolution);
}

// Random invalidation (Fig. 14) makes violated TBVs too.
HzbTbvOptions optionsFor(uint64_t seed) {
    HzbTbvOptions options;
    if (seed % 2 == 0) options.invalidate_fraction = 0.2;
    return options;
}

bool sameBox(const Aabb& a, const Aabb& b) {
    return a.min == b.min && a.max == b.max;
}

void checkObjects(const HzbTbvCuller& culler, const Scene& scene, const FrameResult& out,
                  const HzbTbvSnapshot& s, const std::string& where) {
    const TbvManager& tbvs = culler.tbvs();
    size_t dynamic = 0;
    std::array<int64_t, kHzbObjectStatusCount> count{};
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const HzbTbvObject* o = s.objectAt(int(i));
        if (!scene.objects[i].isDynamic()) {
            EXPECT_EQ(o, nullptr) << where;
            continue;
        }
        ++dynamic;
        ASSERT_NE(o, nullptr) << where << " object " << i;
        EXPECT_EQ(o->object_index, int(i));
        EXPECT_EQ(o->object_id, scene.objects[i].id);
        EXPECT_EQ(o->in_pvs, std::binary_search(out.pvs.begin(), out.pvs.end(), o->object_id));
        ++count[size_t(o->status)];
        if (!s.uses_tbvs) {
            EXPECT_FALSE(o->has_tbv);
            EXPECT_EQ(o->status, o->in_pvs ? HzbObjectStatus::Visible : HzbObjectStatus::Culled);
            continue;
        }
        const int index = int(i);
        EXPECT_EQ(o->state, tbvs.state(index)) << where;
        EXPECT_EQ(o->has_tbv, tbvs.hasTbv(index)) << where << " object " << i;
        EXPECT_EQ(o->period, tbvs.period(index));
        EXPECT_NE(o->status, HzbObjectStatus::Culled);
        // Visible objects are seen; hidden ones sit under a TBV made earlier.
        if (o->status == HzbObjectStatus::Visible) {
            EXPECT_TRUE(o->in_pvs) << where;
        }
        if (o->status == HzbObjectStatus::Hidden) {
            EXPECT_TRUE(o->has_tbv) << where;
        }
        if (o->has_tbv) {
            EXPECT_FALSE(o->in_pvs) << where;
            const TbvRecord& r = tbvs.tbv(index);
            EXPECT_TRUE(sameBox(o->tbv, Aabb{tbvs.bounds(index).min, tbvs.bounds(index).max}))
                << where << " object " << i;
            // What T holds in the object's place.
            EXPECT_TRUE(sameBox(o->tbv, culler.octree().boxOf(index))) << where;
            EXPECT_EQ(o->created, r.created);
            EXPECT_EQ(o->expiry, r.expiry);
            EXPECT_EQ(o->remaining, tbvs.remaining(index));
            EXPECT_EQ(o->new_tbv, r.created == s.t);
        }
    }
    EXPECT_EQ(s.objects.size(), dynamic) << where;
    EXPECT_EQ(s.status_count, count) << where;
    if (!s.uses_tbvs) return;
    // A TBV ends at most once a frame, so each ended TBV is one object's status.
    const TbvFrameCounters& c = tbvs.frameCounters();
    EXPECT_EQ(s.status_count[size_t(HzbObjectStatus::Expired)], c.tbv_expired) << where;
    EXPECT_EQ(s.status_count[size_t(HzbObjectStatus::Revealed)], c.tbv_revealed) << where;
    EXPECT_EQ(s.status_count[size_t(HzbObjectStatus::Violated)], c.tbv_violated + c.tbv_invalidated)
        << where;
    EXPECT_EQ(s.tbv_counters.tbv_created, c.tbv_created);
}

void checkQueue(const HzbTbvCuller& culler, const HzbTbvSnapshot& s, const std::string& where) {
    if (!s.uses_tbvs) {
        EXPECT_EQ(s.queue_size, 0u);
        EXPECT_TRUE(s.next_expiries.empty());
        return;
    }
    const TbvManager& tbvs = culler.tbvs();
    EXPECT_EQ(s.queue_size, tbvs.queue().size()) << where;
    EXPECT_EQ(s.next_expiries.size(), std::min(s.queue_size, kHzbNextExpiries)) << where;
    double last = -INFINITY;
    for (const HzbExpiry& e : s.next_expiries) {
        EXPECT_GE(e.expiry, last) << where << ": earliest first";
        last = e.expiry;
        ASSERT_TRUE(tbvs.hasTbv(e.object_index)) << where;
        EXPECT_EQ(e.expiry, tbvs.tbv(e.object_index).expiry) << where;
        EXPECT_EQ(e.remaining, e.expiry - s.t);
    }
    if (s.next_expiries.size() < kHzbNextExpiries) return;
    // The rest of Q expires no sooner than the last one listed.
    for (const HzbTbvObject& o : s.objects) {
        if (!o.has_tbv) continue;
        bool listed = false;
        for (const HzbExpiry& e : s.next_expiries)
            listed = listed || e.object_index == o.object_index;
        if (!listed) {
            EXPECT_GE(o.expiry, last) << where << " object " << o.object_index;
        }
    }
}

void checkNodes(const HzbTbvCuller& culler, const Camera& camera, const FrameResult& out,
                const HzbTbvSnapshot& s, const std::string& where) {
    EXPECT_EQ(int64_t(s.nodes.size()), out.stats.get(Counter::NodesVisited)) << where;
    std::array<int64_t, kHzbNodeOutcomeCount> count{};
    const Aabb& root = culler.octree().params().bounds;
    for (size_t k = 0; k < s.nodes.size(); ++k) {
        const HzbNodeVisit& v = s.nodes[k];
        ++count[size_t(v.outcome)];
        if (k == 0) {
            EXPECT_EQ(v.depth, 0) << where << ": the root first";
        }
        EXPECT_LE(v.depth, s.octree_max_depth);
        const double scale = std::ldexp(1.0, -v.depth);
        for (int a = 0; a < 3; ++a)
            EXPECT_NEAR(v.box.max[a] - v.box.min[a], (root.max[a] - root.min[a]) * scale, 1e-9)
                << where << " node " << k;
        const bool in_frustum = boxMayIntersectFrustum(v.box, camera);
        if (v.outcome == HzbNodeOutcome::FrustumCulled) {
            EXPECT_FALSE(in_frustum) << where;
        }
        if (v.outcome == HzbNodeOutcome::ZCulled) {
            EXPECT_TRUE(in_frustum) << where;
        }
        // A skipped node's subtree is not walked: the next node is no deeper.
        if (v.outcome != HzbNodeOutcome::Entered && k + 1 < s.nodes.size()) {
            EXPECT_LE(s.nodes[k + 1].depth, v.depth) << where << " node " << k;
        }
    }
    EXPECT_EQ(s.node_count, count) << where;
    EXPECT_EQ(s.octree_nodes, culler.octree().nodeCount());
}

void checkPyramid(const HzbTbvCuller& culler, const HzbTbvSnapshot& s, const std::string& where) {
    const ZPyramid& p = culler.pyramid();
    EXPECT_EQ(s.pyramid_width, p.width());
    EXPECT_EQ(s.pyramid_height, p.height());
    EXPECT_EQ(s.pyramid_level_count, p.levelCount());
    size_t next = 0;
    for (int l = 0; l < p.levelCount(); ++l) {
        const ZPyramidLevel level = p.level(l);
        const bool small =
            level.width <= kHzbMaxCapturedSide && level.height <= kHzbMaxCapturedSide;
        const HzbPyramidLevel* got = s.pyramidLevel(l);
        ASSERT_EQ(got != nullptr, small) << where << " level " << l;
        if (!got) continue;
        EXPECT_EQ(got, &s.pyramid_levels[next++]) << "finest first";
        ASSERT_EQ(got->width, level.width);
        ASSERT_EQ(got->height, level.height);
        ASSERT_LE(got->offset + size_t(got->width) * size_t(got->height), s.pyramid_texels.size());
        for (int y = 0; y < level.height; ++y)
            for (int x = 0; x < level.width; ++x)
                ASSERT_EQ(s.pyramid_texels[got->offset + size_t(y * level.width + x)],
                          float(level.at(x, y)))
                    << where << " level " << l << " texel " << x << ", " << y;
    }
    EXPECT_EQ(next, s.pyramid_levels.size());
}

TEST(HzbTbvSnapshot, CaptureChangesNoCullingResult) {
    for (const Algo& a : kAlgos)
        for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
            const Scene scene = test::hzbRandomRooms(seed);
            HzbTbvCuller on = make(a, optionsFor(seed)), off = make(a, optionsFor(seed));
            on.setDebugCapture(true);
            on.reset(scene);
            off.reset(scene);
            EXPECT_EQ(on.debugSnapshot(), nullptr) << "nothing before the first frame";
            FrameResult x, y;
            for (int frame = 0; frame < scene.frames; ++frame) {
                const double t = scene.timeOfFrame(frame);
                const Camera camera = cameraAt(scene, t);
                on.cull(scene, camera, t, x);
                off.cull(scene, camera, t, y);
                const std::string where = std::string(a.name) + " seed " + std::to_string(seed) +
                                          " frame " + std::to_string(frame);
                ASSERT_EQ(x.pvs, y.pvs) << where;
                EXPECT_EQ(x.stats.values, y.stats.values) << where;
                EXPECT_EQ(x.stats.present, y.stats.present) << where;
                ASSERT_NE(on.debugSnapshot(), nullptr);
                EXPECT_EQ(on.debugSnapshot()->as<HzbTbvSnapshot>(), &on.snapshot());
                EXPECT_EQ(off.debugSnapshot(), nullptr) << "capture off: no snapshot";
            }
        }
}

TEST(HzbTbvSnapshot, MatchesTheCullersStructures) {
    int64_t seen[kHzbObjectStatusCount] = {}, outcomes[kHzbNodeOutcomeCount] = {};
    for (const Algo& a : kAlgos)
        for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
            const Scene scene = test::hzbRandomRooms(seed);
            HzbTbvCuller culler = make(a, optionsFor(seed));
            culler.setDebugCapture(true);
            culler.reset(scene);
            FrameResult out;
            for (int frame = 0; frame < scene.frames; ++frame) {
                const double t = scene.timeOfFrame(frame);
                const Camera camera = cameraAt(scene, t);
                culler.cull(scene, camera, t, out);
                const std::string where = std::string(a.name) + " seed " + std::to_string(seed) +
                                          " frame " + std::to_string(frame);
                const HzbTbvSnapshot& s = culler.snapshot();
                ASSERT_TRUE(s.valid) << where;
                EXPECT_EQ(s.uses_tbvs, a.use_tbvs);
                EXPECT_EQ(s.frame, frame + 1);
                EXPECT_EQ(s.t, t);
                EXPECT_EQ(s.stats.values, out.stats.values) << where;
                checkObjects(culler, scene, out, s, where);
                checkQueue(culler, s, where);
                checkNodes(culler, camera, out, s, where);
                checkPyramid(culler, s, where);
                for (int k = 0; k < kHzbObjectStatusCount; ++k)
                    seen[k] += s.status_count[size_t(k)];
                for (int k = 0; k < kHzbNodeOutcomeCount; ++k)
                    outcomes[k] += s.node_count[size_t(k)];
            }
        }
    // The scenes exercise every state and every outcome.
    for (int k = 0; k < kHzbObjectStatusCount; ++k)
        EXPECT_GT(seen[k], 0) << hzbObjectStatusName(HzbObjectStatus(k));
    for (int k = 0; k < kHzbNodeOutcomeCount; ++k)
        EXPECT_GT(outcomes[k], 0) << hzbNodeOutcomeName(HzbNodeOutcome(k));
}

// At a larger image the fine levels are left out: only levels of at most
// kHzbMaxCapturedSide texels a side are copied.
TEST(HzbTbvSnapshot, CapturesOnlyTheCoarseLevels) {
    const Scene scene = test::hzbRandomRooms(3);
    HzbTbvCuller culler = make(kAlgos[0], HzbTbvOptions{}, 640);
    culler.setDebugCapture(true);
    culler.reset(scene);
    FrameResult out;
    const double t = scene.timeOfFrame(0);
    culler.cull(scene, cameraAt(scene, t), t, out);
    const HzbTbvSnapshot& s = culler.snapshot();
    EXPECT_EQ(s.pyramid_width, 640);
    ASSERT_FALSE(s.pyramid_levels.empty());
    EXPECT_EQ(s.pyramid_levels.front().level, 2) << "640 and 320 wide levels are left out";
    EXPECT_EQ(s.pyramid_levels.back().level, s.pyramid_level_count - 1);
    checkPyramid(culler, s, "640 px");
}

// Capture reuses its vectors: on a second run of the same frames, cull() with
// capture on allocates no more than with capture off (nothing, once warm), and
// the snapshot's storage stays where it was.
long allocationsOfSecondRun(HzbTbvCuller& culler, const Scene& scene,
                            std::vector<const void*>* storage) {
    const auto where = [&] {
        const HzbTbvSnapshot& s = culler.snapshot();
        return std::vector<const void*>{s.objects.data(),        s.slot_of_object.data(),
                                        s.next_expiries.data(),  s.nodes.data(),
                                        s.pyramid_levels.data(), s.pyramid_texels.data()};
    };
    FrameResult out;
    long allocations = 0;
    std::vector<const void*> warm;
    for (int run = 0; run < 2; ++run) {
        culler.reset(scene);
        for (int frame = 0; frame < scene.frames; ++frame) {
            const double t = scene.timeOfFrame(frame);
            const Camera camera = cameraAt(scene, t);
            if (run == 1) test::startCounting();
            culler.cull(scene, camera, t, out);
            if (run == 1) {
                test::stopCounting();
                allocations += test::allocationCount();
                if (storage) {
                    EXPECT_EQ(where(), warm) << "frame " << frame;
                }
            }
        }
        if (run == 0 && storage) warm = where();
    }
    if (storage) *storage = warm;
    return allocations;
}

TEST(HzbTbvSnapshot, SecondRunAllocatesNothingForCapture) {
    for (const Algo& a : kAlgos) {
        const Scene scene = test::hzbRandomRooms(2);
        HzbTbvCuller on = make(a, optionsFor(2)), off = make(a, optionsFor(2));
        on.setDebugCapture(true);
        std::vector<const void*> storage;
        const long with = allocationsOfSecondRun(on, scene, &storage);
        const long without = allocationsOfSecondRun(off, scene, nullptr);
        EXPECT_EQ(with, without) << a.name;
        EXPECT_EQ(with, 0) << a.name;
    }
}

}  // namespace
}  // namespace gridcull
