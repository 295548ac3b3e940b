// The TBV manager (culling/tbv/tbv_manager.h; Sudarsky & Gotsman sections 3.3
// to 3.7) driven by the toy culler of tbv_toy_world.h: the frame's steps, the
// objects it touches, explicit against implicit update, and the storage it
// keeps. Fuzzy TBVs and messages have their own files.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "culling/scene/seeded_random.h"
#include "culling/tbv/tbv_manager.h"
#include "tests/common/allocation_counter.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/tbv/tbv_toy_world.h"

namespace gridcull {
namespace {

bool contains(const std::vector<int>& v, int id) {
    for (const int x : v)
        if (x == id) return true;
    return false;
}

TbvManagerOptions fixedOptions(double validity, TbvUpdateMode mode = TbvUpdateMode::Explicit) {
    TbvManagerOptions o;
    o.mode = mode;
    o.validity_mode = TbvValidityMode::Fixed;
    o.initial_validity = validity;
    return o;
}

// Output sensitivity (section 3.3): 1000 objects far behind the wall and 3 in
// view. Between expiries the manager looks at the 3 visible objects only (V),
// and their state fetches are the frame's only messages; in the frame where
// the 1000 TBVs expire (all made together, fixed period 50 s) it looks at
// those too.
TEST(TbvManager, TouchesOnlyVisibleExpiringAndRevealedObjects) {
    std::vector<test::ToyObject> objects;
    for (int i = 0; i < 3; ++i) objects.push_back(test::toyStill(5.0 + i));
    for (int i = 0; i < 1000; ++i) objects.push_back(test::toyStill(-1e6 - i));
    test::ToyTbvCuller toy(objects, fixedOptions(50.0));
    int quiet_frames = 0;
    for (int f = 0; f <= 120; ++f) {
        const test::ToyFrame frame = toy.frame(double(f));
        const TbvFrameCounters& c = frame.counters;
        EXPECT_EQ(frame.shown.size(), 3u) << "frame at t = " << f;
        if (f == 0 || f == 51 || f == 102) {
            // Frame 0 makes the 1000 TBVs (expiry 50); t = 51 is the first frame
            // past it, which renews them (expiry 101), and so on.
            EXPECT_EQ(c.objects_visited, 1003) << "t = " << f;
            EXPECT_EQ(c.tbv_created, 1000) << "t = " << f;
            EXPECT_EQ(c.tbv_expired, f == 0 ? 0 : 1000) << "t = " << f;
        } else {
            EXPECT_EQ(c.objects_visited, 3) << "t = " << f;
            EXPECT_EQ(c.state_fetches, 3) << "t = " << f;
            EXPECT_EQ(c.tbv_messages, 0) << "t = " << f;
            ++quiet_frames;
        }
        EXPECT_EQ(c.naive_fetches, 1003);
    }
    EXPECT_EQ(quiet_frames, 118);
    EXPECT_EQ(toy.manager().liveObjects().size(), 3u);
    EXPECT_EQ(toy.manager().hiddenObjects().size(), 1000u);
}

// A visible object is never culled in TBVe with conservative TBVs (it is in V
// and rewritten each frame, or under a TBV that contains it and so is revealed
// when it is in view), and is omitted for at most one frame in a row in TBVi
// (section 3.6). Objects sway across the wall at no more than their declared
// speed; adaptive, spread periods with a floor.
TEST(TbvManager, RandomMotionTbveNeverHidesAVisibleObjectTbviAtMostOneFrame) {
    for (const uint64_t seed : test::seedsToRun(500, 6)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            std::vector<test::ToyObject> objects;
            for (int i = 0; i < 60; ++i) {
                const double centre = rng.uniform(-20.0, 10.0);
                const double amplitude = rng.uniform(0.0, 15.0);
                const double omega = rng.uniform(0.05, 1.0);
                const double phase = rng.uniform(0.0, 6.3);
                const double speed = amplitude * omega;  // the largest |dx/dt|
                objects.push_back({[=](double t) {
                                       return glm::dvec3(
                                           centre + amplitude * std::sin(omega * t + phase), 0.0,
                                           0.0);
                                   },
                                   rng.uniform(0.1, 1.0), speed * rng.uniform(1.0, 1.5)});
            }
            for (const TbvUpdateMode mode : {TbvUpdateMode::Explicit, TbvUpdateMode::Implicit}) {
                TbvManagerOptions o;
                o.mode = mode;
                o.validity_mode = TbvValidityMode::Adaptive;
                o.initial_validity = 2.0;
                o.validity_floor = 0.1;
                o.spread_validity = true;
                test::ToyTbvCuller toy(objects, o);
                std::vector<int> missed(objects.size(), 0);  // frames in a row
                for (int f = 0; f < 400; ++f) {
                    const double t = f * 0.1;
                    const test::ToyFrame frame = toy.frame(t);
                    ASSERT_TRUE(toy.manager().consistent()) << "frame " << f;
                    for (size_t i = 0; i < objects.size(); ++i) {
                        const bool in_view = test::toyInView(
                            test::toyDisc(objects[i].position(t), objects[i].radius));
                        const bool shown = contains(frame.shown, int(i));
                        EXPECT_FALSE(shown && !in_view) << "object " << i << " frame " << f;
                        missed[i] = in_view && !shown ? missed[i] + 1 : 0;
                        const int allowed = mode == TbvUpdateMode::Explicit ? 0 : 1;
                        ASSERT_LE(missed[i], allowed)
                            << tbvUpdateModeName(mode) << ": object " << i << " in view but not "
                            << "shown for " << missed[i] << " frames, up to frame " << f;
                    }
                }
            }
        });
    }
}

// The window's read-only view: state, current period, remaining validity.
TEST(TbvManager, ViewShowsStatePeriodAndRemainingValidity) {
    TbvManagerOptions o = fixedOptions(2.0);
    o.validity_mode = TbvValidityMode::Adaptive;
    test::ToyTbvCuller toy({test::toyStill(5.0), test::toyStill(-100.0)}, o);
    toy.frame(0.0);
    toy.frame(0.5);
    const TbvManager& m = toy.manager();
    const TbvObjectView visible = m.view(0);
    EXPECT_EQ(visible.state, TbvObjectState::Visible);
    EXPECT_FALSE(visible.has_tbv);
    EXPECT_DOUBLE_EQ(visible.written_time, 0.5);
    const TbvObjectView hidden = m.view(1);
    EXPECT_EQ(hidden.state, TbvObjectState::Hidden);
    EXPECT_TRUE(hidden.has_tbv);
    EXPECT_DOUBLE_EQ(hidden.period, 2.0);
    EXPECT_DOUBLE_EQ(hidden.created, 0.0);
    EXPECT_DOUBLE_EQ(hidden.expiry, 2.0);
    EXPECT_DOUBLE_EQ(hidden.remaining, 1.5);
    EXPECT_FALSE(hidden.dropped);
    EXPECT_EQ(m.tbv(1).shape.kind, TbvShapeKind::Sphere);
    // What a structure inserts: the disc of radius 0.5 + 1 * 2 around x = -100.
    EXPECT_NEAR(m.bounds(1).min.x, -102.5, 1e-6);
    EXPECT_NEAR(m.bounds(1).max.x, -97.5, 1e-6);
    toy.frame(2.5);  // expired in step 1, renewed for 4 s (doubled) in step 4
    const TbvObjectView renewed = m.view(1);
    EXPECT_EQ(renewed.state, TbvObjectState::Hidden);
    EXPECT_TRUE(renewed.dropped);
    EXPECT_EQ(renewed.last_drop, TbvDropReason::Expired);
    EXPECT_EQ(renewed.last_drop_frame, 3);
    EXPECT_DOUBLE_EQ(renewed.period, 4.0);
    EXPECT_DOUBLE_EQ(renewed.remaining, 4.0);
    EXPECT_EQ(m.tbv(1).serial, 1u);
}

// A still object's TBV may last forever: it is never queued, never expires,
// and only a reveal ends it.
TEST(TbvManager, InfiniteValidityIsNeverQueued) {
    TbvManager m;
    m.reset(1, fixedOptions(1.0));
    m.addDynamic(0);
    const double forever = std::numeric_limits<double>::infinity();
    for (int f = 0; f < 5; ++f) {
        m.beginFrame(double(f), [](int, TbvDropReason) { FAIL() << "nothing ends"; });
        for (const int id : m.objectsToUpdate()) m.updVis(id);
        m.endFrame([&](int, double& validity) {
            validity = forever;
            return sphereTbv(3, glm::dvec3(-10.0, 0.0, 0.0), 1.0, 0.0, validity);
        });
        EXPECT_TRUE(m.hasTbv(0));
        EXPECT_FALSE(m.queue().scheduled(0));
        EXPECT_EQ(m.remaining(0), forever);
        EXPECT_NEAR(m.bounds(0).max.x, -9.0, 1e-6);
        EXPECT_TRUE(m.consistent());
    }
    EXPECT_EQ(m.totals().tbv_created, 1);
    EXPECT_EQ(m.totals().state_fetches, 1);
}

// Renewal (the regular grid's way with an expired TBV): in the frame its TBV
// expires, the object gets its next one at once, with the doubled period, and
// is neither written in T (no state fetch, no object update) nor left in V.
TEST(TbvManager, RenewGivesAnExpiredObjectItsNextTbvAtOnce) {
    TbvManager m;
    TbvManagerOptions o;
    o.validity_mode = TbvValidityMode::Adaptive;
    o.initial_validity = 1.0;
    m.reset(1, o);
    m.addDynamic(0);
    auto hidden = [](int, double& validity) {
        return sphereTbv(3, glm::dvec3(-10.0, 0.0, 0.0), 1.0, 1.0, validity);
    };
    m.beginFrame(0.0, [](int, TbvDropReason) {});
    for (const int id : m.objectsToUpdate()) m.updVis(id);
    m.endFrame(hidden);  // not observed: a TBV of 1 s
    ASSERT_TRUE(m.hasTbv(0));
    EXPECT_EQ(m.tbv(0).expiry, 1.0);

    std::vector<int> expired;
    m.beginFrame(1.5, [&](int id, TbvDropReason why) {
        EXPECT_EQ(why, TbvDropReason::Expired);
        expired.push_back(id);
    });
    ASSERT_EQ(expired, std::vector<int>{0});
    EXPECT_TRUE(m.inV(0));
    for (const int id : expired) m.renew(id, hidden);
    EXPECT_TRUE(m.hasTbv(0));
    EXPECT_FALSE(m.inV(0));
    EXPECT_TRUE(m.objectsToUpdate().empty());
    EXPECT_EQ(m.tbv(0).created, 1.5);
    EXPECT_EQ(m.tbv(0).expiry, 3.5);  // the period doubled on the expiry
    EXPECT_EQ(m.state(0), TbvObjectState::Hidden);
    EXPECT_TRUE(m.consistent());
    m.endFrame(hidden);
    EXPECT_EQ(m.frameCounters().tbv_expired, 1);
    EXPECT_EQ(m.frameCounters().tbv_created, 1);
    EXPECT_EQ(m.frameCounters().state_fetches, 0);
    EXPECT_EQ(m.frameCounters().object_updates, 0);
}

// "Hot per-frame paths allocate nothing after reset()": frames with every kind
// of event (expiries, reveals, violations, random invalidations, adaptive and
// spread periods, both update modes) make no allocation, counted by
// tests/common/allocation_counter.h (core_tests replaces operator new in
// tests/culling/counting_new.cpp). The toy culler's own lists are reserved, so
// the count is the manager's. Also: no array of the manager grows
// (reservedBytes() stays what reset() reserved), and the invariants hold.
TEST(TbvManager, SteadyFramesAllocateNothing) {
    SeededRandom rng(77);
    std::vector<test::ToyObject> objects;
    for (int i = 0; i < 200; ++i) {
        const double centre = rng.uniform(-30.0, 10.0);
        const double amplitude = rng.uniform(0.0, 10.0);
        const double omega = rng.uniform(0.1, 1.0);
        // Every tenth object jumps 20 units every 3 seconds: violations.
        const bool jumps = i % 10 == 0;
        objects.push_back({[=](double t) {
                               const double jump = jumps ? 20.0 * std::floor(t / 3.0) : 0.0;
                               return glm::dvec3(
                                   centre + amplitude * std::sin(omega * t) - std::fmod(jump, 60.0),
                                   0.0, 0.0);
                           },
                           0.5, amplitude * omega});
    }
    for (const TbvUpdateMode mode : {TbvUpdateMode::Explicit, TbvUpdateMode::Implicit}) {
        TbvManagerOptions o;
        o.mode = mode;
        o.validity_mode = TbvValidityMode::Adaptive;
        o.initial_validity = 1.0;
        o.validity_floor = 0.1;
        o.spread_validity = true;
        o.invalidate_fraction = 0.1;
        test::ToyTbvCuller toy(objects, o);
        toy.report_violations = true;
        const size_t reserved = toy.manager().reservedBytes();
        test::ToyFrame frame;
        frame.reserve(objects.size());
        TbvFrameCounters all;
        long allocations = 0;
        int grown_at = -1;  // the first frame after which reservedBytes() changed
        for (int f = 0; f < 600; ++f) {
            test::startCounting();
            toy.frame(f * 0.1, frame);
            test::stopCounting();
            allocations += test::allocationCount();
            accumulate(all, toy.manager().frameCounters());
            if (grown_at < 0 && toy.manager().reservedBytes() != reserved) grown_at = f;
            ASSERT_TRUE(toy.manager().consistent()) << "frame " << f;
        }
        EXPECT_EQ(allocations, 0) << tbvUpdateModeName(mode);
        EXPECT_EQ(grown_at, -1) << tbvUpdateModeName(mode) << ": storage grew";
        // Every kind of event happened.
        EXPECT_GT(all.tbv_expired, 0);
        EXPECT_GT(all.tbv_revealed, 0);
        EXPECT_GT(all.tbv_violated, 0);
        EXPECT_GT(all.tbv_invalidated, 0);
        EXPECT_EQ(all.tbv_created, toy.manager().totals().tbv_created);
    }
}

TEST(TbvManager, OutOfRangeIdsAndOutOfOrderCallsFailAnAssert) {
    auto manager = [] {
        TbvManager m;
        m.reset(3, TbvManagerOptions{});
        m.addDynamic(0);
        return m;
    };
    EXPECT_DEATH(manager().addDynamic(3), "out of range");
    EXPECT_DEATH(manager().state(-1), "out of range");
    EXPECT_DEATH(manager().reportViolation(7), "out of range");
    EXPECT_DEATH(manager().updVis(0), "outside a frame");
    EXPECT_DEATH(
        {
            TbvManager m = manager();
            m.beginFrame(0.0, [](int, TbvDropReason) {});
            m.observe(1);  // static: never in V
        },
        "reveal it first");
    EXPECT_DEATH(
        {
            TbvManager m = manager();
            m.beginFrame(1.0, [](int, TbvDropReason) {});
            m.endFrame([](int, double&) { return TbvShape{}; });
            m.beginFrame(0.5, [](int, TbvDropReason) {});
        },
        "frames go in order");
}

}  // namespace
}  // namespace gridcull
