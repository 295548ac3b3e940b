// rgvc against the exact oracle on seeded random 2D scenes (rgvc_random_scene.h):
// every id `exact` reports must be in rgvc's PVS, every frame (0 false culls).
// The PVS / exact ratio is printed, not asserted: over-estimation is the price of
// conservative grids (coarse grids, the superset frustum, TBVs).
//
// RgvcDifferential.*: 100 scenes x 20 frames with variations of the options
// (each variation with both occluder extensions, --rgvc-extension 0 and 1).
// RgvcSweep.Full: the full sweep, 1000 scenes x 20 frames, part of the default
// run (a few seconds). A longer sweep:
//   GRIDCULL_SWEEP_SCENES=10000 build/tests/core_tests --gtest_filter='RgvcSweep.*' On failure the
//   seed and
// frame are printed with the command that replays it (GRIDCULL_SEED=N).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/common/test_seeds.h"
#include "tests/culling/rgvc/rgvc_random_scene.h"
#include "tests/culling/rgvc/rgvc_sweep.h"

namespace gridcull {
namespace {

using test::RgvcSweepTotals;

void runScene(uint64_t seed, const RgvcOptions& options, RgvcSweepTotals& totals) {
    test::rgvcSweepScene(test::rgvcRandomScene(seed), test::kRgvcFrames, seed, options, totals);
}

void report(const char* name, int scenes, const RgvcSweepTotals& totals) {
    test::rgvcSweepReport("2D", name, size_t(scenes), test::kRgvcFrames, totals);
}

TEST(RgvcDifferential, NeverCullsWhatTheOracleSees) {
    constexpr int kScenes = 100;
    RgvcSweepTotals totals;
    const std::vector<uint64_t> seeds = test::seedsToRun(1000, kScenes);
    for (const uint64_t seed : seeds)
        test::withSeed(seed, [&] { runScene(seed, RgvcOptions{}, totals); });
    report("default run", int(seeds.size()), totals);
    EXPECT_EQ(totals.false_culls, 0);
    // Culling must do something on these scenes: far fewer than all objects.
    if (!test::singleSeedRun()) {
        EXPECT_LT(totals.pvs, totals.objects);
    }
}

// Both occluder extensions (--rgvc-extension: the convex L, the staircase) on
// the default run's scenes.
TEST(RgvcDifferential, BothOccluderExtensionsStayConservative) {
    constexpr int kScenes = 100;
    for (const int extension : {0, 1}) {
        RgvcOptions options;
        options.extension = extension;
        SCOPED_TRACE("extension " + std::to_string(extension));
        RgvcSweepTotals totals;
        const std::vector<uint64_t> seeds = test::seedsToRun(1000, kScenes);
        for (const uint64_t seed : seeds)
            test::withSeed(seed, [&] { runScene(seed, options, totals); });
        report(extension == 0 ? "extension 0 (convex L)" : "extension 1 (staircase)",
               int(seeds.size()), totals);
        EXPECT_EQ(totals.false_culls, 0);
    }
}

TEST(RgvcDifferential, ShortAndLongTbvValidityStayConservative) {
    RgvcSweepTotals totals;
    for (const int extension : {0, 1}) {
        for (const double validity : {0.05, 5.0}) {
            RgvcOptions options;
            options.validity_s = validity;
            options.extension = extension;
            SCOPED_TRACE("validity " + std::to_string(validity) + " extension " +
                         std::to_string(extension));
            for (const uint64_t seed : test::seedsToRun(5000, 20))
                test::withSeed(seed, [&] { runScene(seed, options, totals); });
        }
    }
    EXPECT_EQ(totals.false_culls, 0);
}

TEST(RgvcDifferential, GridResolutionOverrideStaysConservative) {
    RgvcSweepTotals totals;
    for (const int extension : {0, 1}) {
        for (const int resolution : {3, 97}) {
            RgvcOptions options;
            options.grid_resolution = resolution;
            options.extension = extension;
            SCOPED_TRACE("resolution " + std::to_string(resolution) + " extension " +
                         std::to_string(extension));
            for (const uint64_t seed : test::seedsToRun(7000, 10))
                test::withSeed(seed, [&] { runScene(seed, options, totals); });
        }
    }
    EXPECT_EQ(totals.false_culls, 0);
}

TEST(RgvcSweep, Full) {
    const int scenes = test::sweepScenes(1000);
    RgvcSweepTotals totals;
    const std::vector<uint64_t> seeds = test::seedsToRun(100000, scenes);
    for (const uint64_t seed : seeds)
        test::withSeed(seed, [&] { runScene(seed, RgvcOptions{}, totals); });
    report("full sweep", int(seeds.size()), totals);
    EXPECT_EQ(totals.false_culls, 0);
}

}  // namespace
}  // namespace gridcull
