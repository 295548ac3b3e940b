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
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/baseline/vfc_culler.h"
#include "culling/oracle/exact_oracle.h"
#include "culling/rgvc/rgvc_culler.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/rgvc/rgvc_random_scene.h"

namespace gridcull {
namespace {

struct SweepTotals {
    int64_t frames = 0;
    int64_t false_culls = 0;
    int64_t pvs = 0;
    int64_t exact = 0;
    int64_t vfc = 0;
    int64_t objects = 0;
    int64_t voxels_visited = 0;
};

std::string idList(const std::vector<int>& ids) {
    std::string s;
    for (const int id : ids) s += (s.empty() ? "" : ",") + std::to_string(id);
    return s;
}

void runScene(uint64_t seed, const RgvcOptions& options, SweepTotals& totals) {
    const Scene scene = test::rgvcRandomScene(seed);
    RgvcCuller rgvc(options);
    ExactOracle exact;
    VfcCuller vfc;
    rgvc.reset(scene);
    exact.reset(scene);
    vfc.reset(scene);
    FrameResult got, want, frustum;
    for (int frame = 0; frame < test::kRgvcFrames; ++frame) {
        const double t = scene.timeOfFrame(frame);
        const Camera camera = cameraAt(scene, t);
        rgvc.cull(scene, camera, t, got);
        exact.cull(scene, camera, t, want);
        vfc.cull(scene, camera, t, frustum);
        std::vector<int> missing;
        for (const int id : want.pvs)
            if (!std::binary_search(got.pvs.begin(), got.pvs.end(), id)) missing.push_back(id);
        if (!missing.empty()) {
            ADD_FAILURE() << "false cull: seed " << seed << " frame " << frame << " t " << t
                          << " camera (" << camera.position.x << ", " << camera.position.y
                          << ") fov " << camera.fov_deg << " far " << camera.far << " missing ids "
                          << idList(missing);
        }
        EXPECT_TRUE(std::is_sorted(got.pvs.begin(), got.pvs.end()));
        totals.frames += 1;
        totals.false_culls += int64_t(missing.size());
        totals.pvs += int64_t(got.pvs.size());
        totals.exact += int64_t(want.pvs.size());
        totals.vfc += int64_t(frustum.pvs.size());
        totals.objects += int64_t(scene.objects.size());
        totals.voxels_visited += got.stats.get(Counter::VoxelsVisited);
    }
}

void report(const char* name, int scenes, const SweepTotals& totals) {
    std::printf(
        "[ rgvc ] %s: %d scenes x %d frames: false culls %lld, mean PVS %.2f, mean exact %.2f, "
        "PVS/exact %.3f (vfc %.3f), mean objects %.1f, mean voxels visited %.0f\n",
        name, scenes, test::kRgvcFrames, (long long)totals.false_culls,
        double(totals.pvs) / double(totals.frames), double(totals.exact) / double(totals.frames),
        totals.exact > 0 ? double(totals.pvs) / double(totals.exact) : 0.0,
        totals.exact > 0 ? double(totals.vfc) / double(totals.exact) : 0.0,
        double(totals.objects) / double(totals.frames),
        double(totals.voxels_visited) / double(totals.frames));
}

TEST(RgvcDifferential, NeverCullsWhatTheOracleSees) {
    constexpr int kScenes = 100;
    SweepTotals totals;
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
        SweepTotals totals;
        const std::vector<uint64_t> seeds = test::seedsToRun(1000, kScenes);
        for (const uint64_t seed : seeds)
            test::withSeed(seed, [&] { runScene(seed, options, totals); });
        report(extension == 0 ? "extension 0 (convex L)" : "extension 1 (staircase)",
               int(seeds.size()), totals);
        EXPECT_EQ(totals.false_culls, 0);
    }
}

TEST(RgvcDifferential, ShortAndLongTbvValidityStayConservative) {
    SweepTotals totals;
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
    SweepTotals totals;
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
    int scenes = 1000;
    if (const char* count = std::getenv("GRIDCULL_SWEEP_SCENES"))
        scenes = std::max(1, std::atoi(count));
    SweepTotals totals;
    const std::vector<uint64_t> seeds = test::seedsToRun(100000, scenes);
    for (const uint64_t seed : seeds)
        test::withSeed(seed, [&] { runScene(seed, RgvcOptions{}, totals); });
    report("full sweep", int(seeds.size()), totals);
    EXPECT_EQ(totals.false_culls, 0);
}

}  // namespace
}  // namespace gridcull
