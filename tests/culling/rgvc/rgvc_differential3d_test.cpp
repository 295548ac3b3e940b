// rgvc against the exact oracle on seeded random 3D scenes
// (rgvc_random_scene3d.h): every id `exact` reports must be in rgvc's PVS, every
// frame (0 false culls). The PVS / exact ratio is printed, not asserted.
//
// Rgvc3dDifferential.*: 500 scenes x 20 frames with the default options, and
// fewer with variations. A longer sweep:
//   GRIDCULL_SWEEP_SCENES=5000 build/tests/core_tests
//       --gtest_filter='Rgvc3dDifferential.NeverCullsWhatTheOracleSees'
// (one command line).
// On failure the seed and frame are printed (replay with GRIDCULL_SEED=N).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/common/test_seeds.h"
#include "tests/culling/rgvc/rgvc_random_scene3d.h"
#include "tests/culling/rgvc/rgvc_sweep.h"

namespace gridcull {
namespace {

using Totals = test::RgvcSweepTotals;

void runScene(uint64_t seed, const RgvcOptions& options, Totals& totals) {
    test::rgvcSweepScene(test::rgvcRandomScene3d(seed), test::kRgvc3dFrames, seed, options, totals);
}

void report(const char* name, size_t scenes, const Totals& totals) {
    test::rgvcSweepReport("3D", name, scenes, test::kRgvc3dFrames, totals);
}

TEST(Rgvc3dDifferential, NeverCullsWhatTheOracleSees) {
    Totals totals;
    const int scenes = test::sweepScenes(500);
    const std::vector<uint64_t> seeds = test::seedsToRun(300000, scenes);
    for (const uint64_t seed : seeds)
        test::withSeed(seed, [&] { runScene(seed, RgvcOptions{}, totals); });
    report("default run", seeds.size(), totals);
    EXPECT_EQ(totals.false_culls, 0);
    // The occlusion must do something: fewer objects than view-frustum culling.
    if (!test::singleSeedRun()) {
        EXPECT_LT(totals.pvs, totals.vfc);
        EXPECT_GT(totals.occluded_frames, totals.frames / 10);
    }
}

TEST(Rgvc3dDifferential, FixedShortAndLongValidityAndOtherGridsStayConservative) {
    Totals totals;
    for (const double validity : {0.05, 5.0}) {
        RgvcOptions options;
        options.validity_s = validity;
        options.adaptive_validity = 0;
        SCOPED_TRACE("validity " + std::to_string(validity));
        for (const uint64_t seed : test::seedsToRun(310000, test::sweepScenes(30)))
            test::withSeed(seed, [&] { runScene(seed, options, totals); });
    }
    for (const int resolution : {2, 61}) {
        RgvcOptions options;
        options.grid_resolution = resolution;
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        for (const uint64_t seed : test::seedsToRun(320000, test::sweepScenes(30)))
            test::withSeed(seed, [&] { runScene(seed, options, totals); });
    }
    EXPECT_EQ(totals.false_culls, 0);
}

}  // namespace
}  // namespace gridcull
