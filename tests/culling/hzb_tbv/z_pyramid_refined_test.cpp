// ZPyramid::queryRefined, the Z query that descends as Greene's hierarchical
// z-buffer does, against brute force over level 0 on random depth images: it
// is conservative (some pixel of the rectangle at or beyond znear: visible),
// it never culls less than the one-level query(), and with a budget large
// enough to reach level 0 everywhere it is exact (hidden if and only if every
// pixel of the rectangle is nearer than znear). Tolerance: none (the same
// doubles are compared).
#include <algorithm>
#include <cstdio>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "culling/hzb_tbv/z_pyramid.h"
#include "culling/scene/seeded_random.h"

namespace gridcull {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Enough reads to reach every pixel of the largest rectangle here (64 x 64
// image: 4096 pixels, plus the texels above them).
constexpr int kUnlimited = 1 << 20;

TEST(ZPyramidRefined, ConservativeNeverLooserThanOneLevelAndExactWithoutABudget) {
    int64_t hidden_refined = 0, hidden_one_level = 0;
    for (uint64_t seed = 1; seed <= 60; ++seed) {
        SeededRandom rng(seed);
        const int w = 1 + int(rng.below(64)), h = 1 + int(rng.below(64));
        std::vector<double> depth(size_t(w) * size_t(h), kInf);
        for (int k = 0; k < 8; ++k) {  // walls, nearest wins, then noise
            const int x0 = int(rng.below(uint64_t(w))), y0 = int(rng.below(uint64_t(h)));
            const int x1 = std::min(w - 1, x0 + int(rng.below(uint64_t(w))));
            const int y1 = std::min(h - 1, y0 + int(rng.below(uint64_t(h))));
            const double z = rng.uniform(1.0, 50.0);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    depth[size_t(y) * size_t(w) + size_t(x)] =
                        std::min(depth[size_t(y) * size_t(w) + size_t(x)], z);
        }
        for (double& d : depth)
            if (rng.uniform() < 0.05) d = rng.uniform(0.5, 60.0);
        ZPyramid pyramid;
        pyramid.build(w, h, depth.data());
        for (int q = 0; q < 400; ++q) {
            PixelRect r;
            r.x0 = int(rng.below(uint64_t(w)));
            r.y0 = int(rng.below(uint64_t(h)));
            r.x1 = std::min(w - 1, r.x0 + int(rng.below(uint64_t(w))));
            r.y1 = std::min(h - 1, r.y0 + int(rng.below(uint64_t(h))));
            const double znear = rng.uniform(0.0, 55.0);
            bool all_nearer = true;
            for (int y = r.y0; y <= r.y1; ++y)
                for (int x = r.x0; x <= r.x1; ++x)
                    all_nearer = all_nearer && depth[size_t(y) * size_t(w) + size_t(x)] < znear;
            const bool one_level = pyramid.query(r, znear).may_be_visible;
            const int budget = rng.uniform() < 0.5 ? 16 : 64;
            const ZQueryResult refined = pyramid.queryRefined(r, znear, budget);
            const ZQueryResult exact = pyramid.queryRefined(r, znear, kUnlimited);
            if (!all_nearer) {
                EXPECT_TRUE(refined.may_be_visible) << "seed " << seed << " q " << q;
            }
            if (!one_level) {
                EXPECT_FALSE(refined.may_be_visible) << "seed " << seed << " q " << q;
            }
            EXPECT_LE(refined.texels_read, budget);
            EXPECT_EQ(exact.may_be_visible, !all_nearer) << "seed " << seed << " q " << q;
            hidden_refined += refined.may_be_visible ? 0 : 1;
            hidden_one_level += one_level ? 0 : 1;
        }
    }
    // The descent must cull more than the one-level query on these images.
    EXPECT_GT(hidden_refined, hidden_one_level + hidden_one_level / 10);
    std::printf("[ z-pyramid ] hidden: one level %lld, refined %lld of 24000 queries\n",
                (long long)hidden_one_level, (long long)hidden_refined);
}

}  // namespace
}  // namespace gridcull
