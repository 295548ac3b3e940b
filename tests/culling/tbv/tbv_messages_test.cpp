// Message accounting (Sudarsky & Gotsman section 3.7, Fig. 15b) and explicit
// against implicit update (section 3.6) on one hand-computed scenario, run by
// the toy culler of tbv_toy_world.h (visible half-plane x >= 0). Fixed validity
// 2 s, frames at t = 0, 1, ..., 5; discs of radius 0.5 declared at speed 1:
//   A (id 0) stands at x = 5, always in view;
//   B (id 1) stands at x = -100, never in view, its TBVs never either;
//   C (id 2) walks from x = -3 at speed 1: hidden up to t = 2 (x = -1, disc up
//     to -0.5), in view from t = 3 (x = 0).
// B's and C's first TBVs are made at t = 0 for 2 s (C's disc of radius 2.5
// around -3 reaches -0.5: hidden), and expire at t = 3, the first frame past 2.
#include <vector>

#include <gtest/gtest.h>

#include "culling/tbv/tbv_manager.h"
#include "tests/culling/tbv/tbv_toy_world.h"

namespace gridcull {
namespace {

constexpr int kA = 0, kB = 1, kC = 2;

struct Column {
    std::vector<int64_t> fetches, tbvs, visited;
    std::vector<std::vector<int>> shown, revealed;
};

Column run(TbvUpdateMode mode) {
    TbvManagerOptions o;
    o.mode = mode;
    o.validity_mode = TbvValidityMode::Fixed;
    o.initial_validity = 2.0;
    test::ToyTbvCuller toy(
        {test::toyStill(5.0), test::toyStill(-100.0), test::toyMoving(-3.0, 1.0)}, o);
    Column c;
    for (int f = 0; f <= 5; ++f) {
        const test::ToyFrame frame = toy.frame(double(f));
        c.fetches.push_back(frame.counters.state_fetches);
        c.tbvs.push_back(frame.counters.tbv_messages);
        c.visited.push_back(frame.counters.objects_visited);
        c.shown.push_back(frame.shown);
        c.revealed.push_back(frame.revealed);
        EXPECT_EQ(frame.counters.naive_fetches, 3);
        EXPECT_EQ(frame.counters.violation_messages, 0);
    }
    const TbvFrameCounters& total = toy.manager().totals();
    EXPECT_EQ(total.naive_fetches, 18);
    int64_t fetches = 0, tbvs = 0;
    for (size_t f = 0; f < c.fetches.size(); ++f) {
        fetches += c.fetches[f];
        tbvs += c.tbvs[f];
    }
    EXPECT_EQ(total.state_fetches, fetches);
    EXPECT_EQ(total.tbv_messages, tbvs);
    EXPECT_EQ(total.messages(), fetches + tbvs);
    return c;
}

// TBVe, frame by frame:
//   t=0: V = {A, B, C}: 3 fetches (step 2); B and C out of sight: 2 TBVs.
//   t=1, t=2: V = {A}: 1 fetch; B and C cost nothing.
//   t=3: B's and C's TBVs expire: 3 fetches; C is in view; B gets a TBV: 1.
//   t=4, t=5: V = {A, C}: 2 fetches (B's TBV, made at 3, lasts to 5).
// 12 state fetches and 3 TBVs, against 18 fetches for updating every object.
TEST(TbvMessages, HandComputedScenarioExplicitUpdate) {
    const Column c = run(TbvUpdateMode::Explicit);
    EXPECT_EQ(c.fetches, (std::vector<int64_t>{3, 1, 1, 3, 2, 2}));
    EXPECT_EQ(c.tbvs, (std::vector<int64_t>{2, 0, 0, 1, 0, 0}));
    EXPECT_EQ(c.visited, (std::vector<int64_t>{3, 1, 1, 3, 2, 2}));
}

// TBVi, frame by frame:
//   t=0: the first frame writes V = {A, B, C} (3 fetches); 2 TBVs.
//   t=1, t=2: A is drawn from where it was written: 1 fetch.
//   t=3: B's and C's TBVs expire, but step 2 is omitted: C is in no node of T
//     and is not shown; A: 1 fetch; B and C get TBVs: 2 (C's around x = 0, in view).
//   t=4: C's TBV is revealed: its state fetched and written; A: 2 fetches.
//   t=5: A and C drawn from where they were written: 2 fetches.
// 10 state fetches and 4 TBVs.
TEST(TbvMessages, HandComputedScenarioImplicitUpdate) {
    const Column c = run(TbvUpdateMode::Implicit);
    EXPECT_EQ(c.fetches, (std::vector<int64_t>{3, 1, 1, 1, 2, 2}));
    EXPECT_EQ(c.tbvs, (std::vector<int64_t>{2, 0, 0, 2, 0, 0}));
    EXPECT_EQ(c.visited, (std::vector<int64_t>{3, 1, 1, 3, 2, 2}));
}

// C comes into view at t = 3 in the frame its TBV expires. TBVe writes it in
// step 2 and shows it at t = 3; TBVi (no step 2) shows it one frame late, at
// t = 4, when the TBV made for it at t = 3 is revealed (section 3.6: "a visible
// dynamic object can be wrongly omitted from the display for at most one
// frame").
TEST(TbvUpdateModes, ImplicitShowsAnObjectWhoseTbvExpiredOneFrameLate) {
    const Column e = run(TbvUpdateMode::Explicit);
    const Column i = run(TbvUpdateMode::Implicit);
    const std::vector<int> a{kA}, ac{kA, kC};
    EXPECT_EQ(e.shown, (std::vector<std::vector<int>>{a, a, a, ac, ac, ac}));
    EXPECT_EQ(i.shown, (std::vector<std::vector<int>>{a, a, a, a, ac, ac}));
    EXPECT_TRUE(e.revealed[4].empty());
    EXPECT_EQ(i.revealed[4], std::vector<int>{kC});
    (void)kB;
}

// An object that walks into view under a valid TBV shows up in the frame it
// does, in both modes: its TBV, which holds it, is in view then and revealed.
// D walks from x = -3 at speed 1 (declared 1), TBVs of 1.5 s: the one made at
// t = 0 (radius 2 around -3) stays hidden and expires at t = 2; the one made at
// t = 2 (around -1, to 3.5) reaches x = 1; at t = 3 D is at 0, in view, and
// that TBV is revealed in the same frame.
TEST(TbvUpdateModes, ObjectUnderAValidTbvShowsInTheSameFrameInBothModes) {
    for (const TbvUpdateMode mode : {TbvUpdateMode::Explicit, TbvUpdateMode::Implicit}) {
        TbvManagerOptions o;
        o.mode = mode;
        o.validity_mode = TbvValidityMode::Fixed;
        o.initial_validity = 1.5;
        test::ToyTbvCuller toy({test::toyMoving(-3.0, 1.0)}, o);
        std::vector<int> shown_at, revealed_at;
        for (int f = 0; f <= 5; ++f) {
            const test::ToyFrame frame = toy.frame(double(f));
            if (!frame.shown.empty()) shown_at.push_back(f);
            if (!frame.revealed.empty()) revealed_at.push_back(f);
        }
        EXPECT_EQ(shown_at, (std::vector<int>{3, 4, 5})) << tbvUpdateModeName(mode);
        EXPECT_EQ(revealed_at, std::vector<int>{3}) << tbvUpdateModeName(mode);
    }
}

}  // namespace
}  // namespace gridcull
