// rgvc against the exact oracle on seeded random 3D scenes
// (rgvc_random_scene3d.h): every id `exact` reports must be in rgvc's PVS, every
// frame (0 false culls). The PVS / exact ratio is printed, not asserted.
//
// Rgvc3dDifferential.*: 500 scenes x 20 frames with the default options, and
// fewer with variations. A longer sweep:
//   GRIDCULL_SWEEP_SCENES=5000 build/tests/core_tests \
//       --gtest_filter='Rgvc3dDifferential.NeverCullsWhatTheOracleSees'
// On failure the seed and frame are printed (replay with GRIDCULL_SEED=N).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/baseline/vfc_culler.h"
#include "culling/oracle/exact_oracle.h"
#include "culling/rgvc/rgvc_culler.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/rgvc/rgvc_random_scene3d.h"

namespace gridcull {
namespace {

struct Totals {
    int64_t frames = 0;
    int64_t false_culls = 0;
    int64_t pvs = 0;
    int64_t exact = 0;
    int64_t vfc = 0;
    int64_t voxels_visited = 0;
    int64_t occluded_frames = 0;  // frames where rgvc kept fewer than vfc
};

void runScene(uint64_t seed, const RgvcOptions& options, Totals& totals) {
    const Scene scene = test::rgvcRandomScene3d(seed);
    RgvcCuller rgvc(options);
    ExactOracle exact;
    VfcCuller vfc;
    rgvc.reset(scene);
    exact.reset(scene);
    vfc.reset(scene);
    FrameResult got, want, frustum;
    for (int frame = 0; frame < test::kRgvc3dFrames; ++frame) {
        const double t = scene.timeOfFrame(frame);
        const Camera camera = cameraAt(scene, t);
        rgvc.cull(scene, camera, t, got);
        exact.cull(scene, camera, t, want);
        vfc.cull(scene, camera, t, frustum);
        std::string missing;
        int64_t missed = 0;
        for (const int id : want.pvs)
            if (!std::binary_search(got.pvs.begin(), got.pvs.end(), id)) {
                missing += (missing.empty() ? "" : ",") + std::to_string(id);
                ++missed;
            }
        if (missed > 0)
            ADD_FAILURE() << "false cull: seed " << seed << " frame " << frame << " t " << t
                          << " camera (" << camera.position.x << ", " << camera.position.y << ", "
                          << camera.position.z << ") fov " << camera.fov_deg << " near "
                          << camera.near << " far " << camera.far << " missing ids " << missing;
        totals.frames += 1;
        totals.false_culls += missed;
        totals.pvs += int64_t(got.pvs.size());
        totals.exact += int64_t(want.pvs.size());
        totals.vfc += int64_t(frustum.pvs.size());
        totals.voxels_visited += got.stats.get(Counter::VoxelsVisited);
        totals.occluded_frames += got.pvs.size() < frustum.pvs.size() ? 1 : 0;
    }
}

void report(const char* name, size_t scenes, const Totals& t) {
    std::printf(
        "[ rgvc 3D ] %s: %zu scenes x %d frames: false culls %lld, PVS/exact %.3f (vfc %.3f), "
        "frames culling more than vfc %.1f%%, mean voxels visited %.0f\n",
        name, scenes, test::kRgvc3dFrames, (long long)t.false_culls,
        t.exact > 0 ? double(t.pvs) / double(t.exact) : 0.0,
        t.exact > 0 ? double(t.vfc) / double(t.exact) : 0.0,
        100.0 * double(t.occluded_frames) / double(std::max<int64_t>(1, t.frames)),
        double(t.voxels_visited) / double(std::max<int64_t>(1, t.frames)));
}

TEST(Rgvc3dDifferential, NeverCullsWhatTheOracleSees) {
    Totals totals;
    int scenes = 500;
    if (const char* count = std::getenv("GRIDCULL_SWEEP_SCENES"))
        scenes = std::max(1, std::atoi(count));
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
        for (const uint64_t seed : test::seedsToRun(310000, 30))
            test::withSeed(seed, [&] { runScene(seed, options, totals); });
    }
    for (const int resolution : {2, 61}) {
        RgvcOptions options;
        options.grid_resolution = resolution;
        SCOPED_TRACE("resolution " + std::to_string(resolution));
        for (const uint64_t seed : test::seedsToRun(320000, 30))
            test::withSeed(seed, [&] { runScene(seed, options, totals); });
    }
    EXPECT_EQ(totals.false_culls, 0);
}

}  // namespace
}  // namespace gridcull
