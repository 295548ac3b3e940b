// The level camera's box run (culling/raster/level_box_run.h): the run that
// writes two pixels at a time must leave every depth, id and written span the
// pixel-by-pixel definition gives: lineBox's interval cut (max of the lows, min
// of the highs), solidEntry, the strict depth test, and no write at or nearer
// than the box's least depth. Compared bit for bit, no tolerance.
//
// The random runs draw their values from a small set on purpose (0, -0, near,
// far, the stored depths, z_min and values between), so that equal operands,
// signed zeros and every boundary of solidEntry are met often, not by luck;
// runs start at odd and even columns and have odd and even lengths (the SIMD
// path's single last pixel). The whole-buffer comparison against the plain slab
// test is id_depth_buffer_box_test.cpp. GRIDCULL_SEED=N replays one seed.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "culling/raster/level_box_run.h"
#include "culling/scene/ray_intersect.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/test_seeds.h"

namespace gridcull {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The definition, written as forBoxHits' general path has it.
bool definitionWins(double row_lo, double row_hi, double col_lo, double col_hi, double near, double far,
                    double z_min, double stored, double& s) {
    if (stored <= z_min) return false;
    const double lo = std::max(row_lo, col_lo), hi = std::min(row_hi, col_hi);
    if (lo > hi) return false;
    if (!solidEntry(lo, hi, near, far, s)) return false;
    return s < stored;
}

TEST(LevelBoxRun, EveryPixelIdAndSpanEqualsThePixelByPixelDefinition) {
    constexpr int kWidth = 37;
    long long pixels = 0, in_runs = 0, won = 0, lost_to_depth = 0;
    for (uint64_t seed : test::seedsToRun(1, 400)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const double near = rng.uniform() < 0.5 ? 0.1 : rng.uniform(0.2, 2.0);
            const double far = rng.uniform(5.0, 50.0);
            const double z_min = rng.uniform() < 0.3 ? near : rng.uniform(near, far);
            const double pool[] = {0.0, -0.0, near, far, z_min, -1.0, 0.5 * near,
                                   rng.uniform(-3.0, 3.0), rng.uniform(near, far),
                                   rng.uniform(near, far), 2.0 * far, kInf};
            const int pool_size = int(sizeof(pool) / sizeof(pool[0]));
            auto pick = [&] {
                return rng.uniform() < 0.6 ? pool[rng.below(uint64_t(pool_size))]
                                           : rng.uniform(-2.0, 1.2 * far);
            };
            // The high end of an interval: equal to the low end, above it (a hit
            // when the rest agrees), or anything.
            auto pickHigh = [&](double low) {
                const double u = rng.uniform();
                return u < 0.2 ? low : u < 0.6 ? low + rng.uniform(0.0, far) : pick();
            };
            std::vector<double> col_lo(kWidth), col_hi(kWidth), depth(kWidth);
            std::vector<int32_t> ids(kWidth);
            for (int px = 0; px < kWidth; ++px) {
                col_lo[size_t(px)] = pick();
                col_hi[size_t(px)] = pickHigh(col_lo[size_t(px)]);
                depth[size_t(px)] = rng.uniform() < 0.3 ? kInf : std::abs(pick());
                ids[size_t(px)] = int32_t(px % 5) - 1;
            }
            const double row_lo = pick(), row_hi = pickHigh(row_lo);
            const LevelBoxRow run{row_lo, row_hi, col_lo.data(), col_hi.data(), near, far, z_min};
            const int lo = int(rng.below(kWidth)), hi = lo + int(rng.below(uint64_t(kWidth - lo)));
            const bool with_ids = rng.uniform() < 0.5;

            std::vector<double> got_depth = depth;
            std::vector<int32_t> got_ids = ids;
            const WrittenSpan got = writeLevelBoxRun(run, lo, hi, got_depth.data(),
                                                     with_ids ? got_ids.data() : nullptr, 7);
            WrittenSpan want;
            for (int px = 0; px < kWidth; ++px) {
                const size_t p = size_t(px);
                double s = 0.0;
                const bool in_run = px >= lo && px <= hi;
                const bool wins = in_run && definitionWins(row_lo, row_hi, col_lo[p], col_hi[p], near,
                                                           far, z_min, depth[p], s);
                const double want_depth = wins ? s : depth[p];
                const int32_t want_id = wins && with_ids ? 7 : ids[p];
                ++pixels;
                in_runs += in_run;
                won += wins;
                lost_to_depth += in_run && !wins && depth[p] < kInf;
                if (wins) {
                    want.lo = std::min(want.lo, px);
                    want.hi = px;
                }
                EXPECT_EQ(got_depth[p], want_depth) << "pixel " << px;
                EXPECT_EQ(got_ids[p], want_id) << "pixel " << px;
            }
            EXPECT_EQ(got.hi, want.hi);
            if (want.hi >= 0) {
                EXPECT_EQ(got.lo, want.lo);
            }
        });
    }
    if (!test::singleSeedRun()) {
        std::printf("[level box run] %lld pixels, %lld in runs, %lld won, %lld lost to the stored depth\n",
                    pixels, in_runs, won, lost_to_depth);
        // The random runs reach both outcomes often, or the test proves little.
        EXPECT_GT(won, in_runs / 10);
        EXPECT_GT(lost_to_depth, in_runs / 10);
    }
}

}  // namespace
}  // namespace gridcull
