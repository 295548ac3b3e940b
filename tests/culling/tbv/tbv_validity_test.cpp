// Validity periods (Sudarsky & Gotsman section 3.4; culling/tbv/tbv_validity.h)
// on their own and as the TBV manager uses them: adaptive periods double after
// an expiry up to the ceiling, halve after a reveal down to the floor; fixed
// ones never move; a TBV gets the period its object had when it was made.
#include <vector>

#include <gtest/gtest.h>

#include "culling/tbv/tbv_manager.h"
#include "culling/tbv/tbv_validity.h"
#include "tests/culling/tbv/tbv_toy_world.h"

namespace gridcull {
namespace {

TEST(TbvValidity, AdaptiveDoublesAfterExpiryUpToTheCeiling) {
    TbvValidityPeriods v;
    v.reset(2, TbvValidityMode::Adaptive, 0.5, 0.1);
    std::vector<double> seen;
    for (int k = 0; k < 9; ++k) {
        v.expired(0);
        seen.push_back(v.period(0));
    }
    EXPECT_EQ(seen, (std::vector<double>{1, 2, 4, 8, 16, 32, 32, 32, 32}));  // 0.5 * 64 = 32
    EXPECT_DOUBLE_EQ(v.period(1), 0.5);  // the other object kept its own
}

TEST(TbvValidity, AdaptiveHalvesAfterRevealDownToTheFloor) {
    TbvValidityPeriods v;
    v.reset(1, TbvValidityMode::Adaptive, 4.0, 0.3);
    std::vector<double> seen;
    for (int k = 0; k < 6; ++k) {
        v.revealed(0, v.period(0));
        seen.push_back(v.period(0));
    }
    EXPECT_EQ(seen, (std::vector<double>{2, 1, 0.5, 0.3, 0.3, 0.3}));
    // Halved from the period the revealed TBV used, when the caller shortened it.
    v.reset(1, TbvValidityMode::Adaptive, 4.0, 0.1);
    v.revealed(0, 1.0);
    EXPECT_DOUBLE_EQ(v.period(0), 0.5);
    // A floor above the initial period is lowered to it.
    v.reset(1, TbvValidityMode::Adaptive, 1.0, 5.0);
    v.revealed(0, 1.0);
    EXPECT_DOUBLE_EQ(v.period(0), 1.0);
}

TEST(TbvValidity, FixedNeverChanges) {
    TbvValidityPeriods v;
    v.reset(1, TbvValidityMode::Fixed, 2.0, 0.1);
    v.expired(0);
    v.revealed(0, 2.0);
    v.expired(0);
    EXPECT_DOUBLE_EQ(v.period(0), 2.0);
}

// Through the manager: an object that no TBV ever exposes (far behind the wall)
// has its TBVs expire one after the other, each twice as long as the last, up
// to 64 times the initial period.
TEST(TbvValidity, ManagerDoublesAHiddenObjectsPeriodAtEachExpiry) {
    TbvManagerOptions options;
    options.validity_mode = TbvValidityMode::Adaptive;
    options.initial_validity = 1.0;
    options.validity_floor = 0.25;
    test::ToyTbvCuller toy({test::toyStill(-1e6)}, options);
    TbvManager& m = toy.manager();
    std::vector<double> made;  // validity of each TBV made, in order
    const double dt = 0.5;
    for (int f = 0; f < 800; ++f) {
        const test::ToyFrame frame = toy.frame(f * dt);
        if (frame.counters.tbv_created == 1) made.push_back(m.tbv(0).expiry - m.tbv(0).created);
        EXPECT_EQ(frame.counters.tbv_revealed, 0);
    }
    ASSERT_GE(made.size(), 8u);
    const std::vector<double> want{1, 2, 4, 8, 16, 32, 64, 64};
    for (size_t k = 0; k < want.size(); ++k) EXPECT_DOUBLE_EQ(made[k], want[k]) << "TBV " << k;
}

// An object 1 unit behind the wall whose TBVs, from a declared speed of 1, are
// visible whenever their period is 0.5 s or more: each is revealed while the
// object stays hidden, so the period halves down to the floor (0.25 s), whose
// TBV stays hidden and expires, doubling the period back to 0.5 s.
TEST(TbvValidity, ManagerHalvesARevealedObjectsPeriodDownToTheFloor) {
    TbvManagerOptions options;
    options.validity_mode = TbvValidityMode::Adaptive;
    options.initial_validity = 8.0;
    options.validity_floor = 0.25;
    test::ToyTbvCuller toy({test::toyStill(-1.0)}, options);
    TbvManager& m = toy.manager();
    std::vector<double> made;
    std::vector<TbvDropReason> ends;
    for (int f = 0; f < 12; ++f) {
        const test::ToyFrame frame = toy.frame(f * 0.1);
        EXPECT_TRUE(frame.shown.empty());
        for (const auto& d : frame.dropped) ends.push_back(d.second);          // step 1
        if (!frame.revealed.empty()) ends.push_back(TbvDropReason::Revealed);  // step 3
        if (frame.counters.tbv_created == 1) made.push_back(m.tbv(0).expiry - m.tbv(0).created);
    }
    ASSERT_GE(made.size(), 7u);
    const std::vector<double> want{8, 4, 2, 1, 0.5, 0.25, 0.5};
    for (size_t k = 0; k < want.size(); ++k) EXPECT_DOUBLE_EQ(made[k], want[k]) << "TBV " << k;
    ASSERT_GE(ends.size(), 6u);
    for (size_t k = 0; k < 5; ++k) EXPECT_EQ(ends[k], TbvDropReason::Revealed) << k;
    EXPECT_EQ(ends[5], TbvDropReason::Expired);
}

TEST(TbvValidity, ManagerFixedPeriodsNeverMove) {
    TbvManagerOptions options;
    options.validity_mode = TbvValidityMode::Fixed;
    options.initial_validity = 8.0;
    test::ToyTbvCuller toy({test::toyStill(-1.0), test::toyStill(-1e6)}, options);
    for (int f = 0; f < 200; ++f) {
        toy.frame(f * 0.1);
        EXPECT_DOUBLE_EQ(toy.manager().period(0), 8.0);
        EXPECT_DOUBLE_EQ(toy.manager().period(1), 8.0);
    }
}

}  // namespace
}  // namespace gridcull
