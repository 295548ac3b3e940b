// The expiration queue Q (culling/tbv/tbv_expiry_queue.h, Sudarsky & Gotsman
// section 3.3): pops earliest first, only what is past, ties the same way on
// every run, cancel and reschedule leave no ghost entries, and compaction of
// stale entries changes nothing.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "culling/scene/seeded_random.h"
#include "culling/tbv/tbv_expiry_queue.h"
#include "tests/common/test_seeds.h"

namespace gridcull {
namespace {

std::vector<int> popAll(TbvExpiryQueue& q, double t) {
    std::vector<int> out;
    q.popExpired(t, [&](int object) { out.push_back(object); });
    return out;
}

TEST(TbvExpiryQueue, PopsEarliestFirstAndOnlyWhatIsPast) {
    for (const uint64_t seed : test::seedsToRun(1, 8)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const int n = 300;
            TbvExpiryQueue q;
            q.reset(n);
            std::vector<double> expiry(n);
            for (int i = 0; i < n; ++i) {
                expiry[size_t(i)] = rng.uniform(0.0, 100.0);
                q.schedule(i, expiry[size_t(i)]);
            }
            EXPECT_EQ(q.size(), size_t(n));
            // Pop in slices: each slice holds exactly the expiries < its time, in order.
            double last = -1.0;
            size_t popped = 0;
            for (double t = 5.0; t <= 105.0; t += 5.0) {
                const std::vector<int> out = popAll(q, t);
                for (const int i : out) {
                    EXPECT_LT(expiry[size_t(i)], t);
                    EXPECT_GE(expiry[size_t(i)], last) << "popped out of order";
                    last = expiry[size_t(i)];
                }
                popped += out.size();
                const size_t due = size_t(
                    std::count_if(expiry.begin(), expiry.end(), [&](double e) { return e < t; }));
                EXPECT_EQ(popped, due) << "at t = " << t;
                EXPECT_EQ(q.size(), size_t(n) - popped);
            }
        });
    }
}

TEST(TbvExpiryQueue, AnExpiryEqualToTheTimeIsNotPast) {
    TbvExpiryQueue q;
    q.reset(2);
    q.schedule(0, 2.0);
    EXPECT_TRUE(popAll(q, 2.0).empty());
    EXPECT_EQ(popAll(q, std::nextafter(2.0, 3.0)), std::vector<int>{0});
}

TEST(TbvExpiryQueue, TiesPopTogetherAndInTheSameOrderOnEveryRun) {
    // Ten objects on three expiry times, scheduled in a scrambled order, some
    // rescheduled: two queues fed the same calls pop the same sequence, and a
    // tie pops whole in the first frame past it.
    auto run = [] {
        TbvExpiryQueue q;
        q.reset(10);
        const int order[10] = {7, 2, 9, 0, 4, 1, 8, 3, 6, 5};
        for (const int i : order) q.schedule(i, 1.0 + double(i % 3));
        q.schedule(4, 1.0);  // moved onto the first tie
        q.cancel(6);
        std::vector<std::vector<int>> frames;
        for (const double t : {1.0, 1.5, 2.5, 3.5}) frames.push_back(popAll(q, t));
        return frames;
    };
    const auto a = run();
    const auto b = run();
    EXPECT_EQ(a, b);
    EXPECT_TRUE(a[0].empty());
    auto sorted = [](std::vector<int> v) {
        std::sort(v.begin(), v.end());
        return v;
    };
    EXPECT_EQ(sorted(a[1]), (std::vector<int>{0, 3, 4, 9}));  // expiry 1 (4 moved there)
    EXPECT_EQ(sorted(a[2]), (std::vector<int>{1, 7}));        // expiry 2
    EXPECT_EQ(sorted(a[3]), (std::vector<int>{2, 5, 8}));     // expiry 3, 6 cancelled
    // The window's list breaks ties by id.
    TbvExpiryQueue q;
    q.reset(4);
    for (const int i : {3, 1, 2, 0}) q.schedule(i, 5.0);
    std::vector<std::pair<int, double>> next;
    q.nextExpiries(4, next);
    ASSERT_EQ(next.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(next[size_t(i)].first, i);
}

TEST(TbvExpiryQueue, CancelAndRescheduleLeaveNoGhosts) {
    TbvExpiryQueue q;
    q.reset(4);
    q.schedule(0, 1.0);
    q.schedule(1, 2.0);
    q.schedule(2, 3.0);
    q.cancel(1);
    q.cancel(1);  // twice is harmless
    EXPECT_FALSE(q.scheduled(1));
    EXPECT_EQ(q.size(), 2u);
    q.schedule(0, 5.0);  // later: the old entry at 1.0 is stale
    q.schedule(2, 0.5);  // earlier
    EXPECT_DOUBLE_EQ(q.expiryOf(0), 5.0);
    EXPECT_EQ(popAll(q, 4.0), std::vector<int>{2});
    EXPECT_EQ(popAll(q, 10.0), std::vector<int>{0});
    EXPECT_EQ(q.size(), 0u);
    EXPECT_TRUE(popAll(q, 100.0).empty());
    // A callback may schedule the popped object again, later.
    q.schedule(3, 1.0);
    int pops = 0;
    q.popExpired(2.0, [&](int object) {
        ++pops;
        q.schedule(object, 7.0);
    });
    EXPECT_EQ(pops, 1);
    EXPECT_TRUE(q.scheduled(3));
    EXPECT_EQ(popAll(q, 8.0), std::vector<int>{3});
}

TEST(TbvExpiryQueue, ManyReschedulesCompactWithoutChangingTheOrder) {
    for (const uint64_t seed : test::seedsToRun(11, 4)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const int n = 50;  // reset reserves 2n + 16 entries: 5000 moves compact often
            TbvExpiryQueue q;
            q.reset(n);
            std::vector<double> expiry(n, std::numeric_limits<double>::infinity());
            for (int k = 0; k < 5000; ++k) {
                const int i = int(rng.below(n));
                if (rng.uniform() < 0.2) {
                    q.cancel(i);
                    expiry[size_t(i)] = std::numeric_limits<double>::infinity();
                } else {
                    expiry[size_t(i)] = rng.uniform(0.0, 10.0);
                    q.schedule(i, expiry[size_t(i)]);
                }
            }
            std::vector<std::pair<double, int>> want;
            for (int i = 0; i < n; ++i)
                if (expiry[size_t(i)] < 11.0) want.push_back({expiry[size_t(i)], i});
            std::sort(want.begin(), want.end());
            EXPECT_EQ(q.size(), want.size());
            std::vector<std::pair<double, int>> got;
            q.popExpired(11.0, [&](int i) { got.push_back({expiry[size_t(i)], i}); });
            ASSERT_EQ(got.size(), want.size());
            for (size_t k = 0; k < got.size(); ++k) EXPECT_EQ(got[k].first, want[k].first);
        });
    }
}

}  // namespace
}  // namespace gridcull
