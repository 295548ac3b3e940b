// Every image-space culler (each algorithm of a family that draws an image:
// today the lazy occlusion grids) against the brute-force reference
// (tests/culling/oracle/oracle_brute_force.h), not only against the exact oracle:
// the reference casts every pixel centre's ray against every object with no
// screen bounds, no ordering and no skipping, so a bug that the oracle and an
// image-space culler share through their common ID buffer
// (culling/raster/id_depth_buffer.h) cannot hide here. Frame by frame, every id
// the reference requires (the unique nearest object at some pixel centre) must
// be in each culler's PVS, at the same image size (--oracle-res, which an
// image-space family follows by default).
// Small images and a modest number of scenes keep it fast; GRIDCULL_SEED=N
// replays one scene.
#include <algorithm>
#include <cstdio>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/api/culler.h"
#include "culling/oracle/oracle_options.h"
#include "culling/registry/registry.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/lazy_grid/lazy_grid_random_scene.h"
#include "tests/culling/oracle/oracle_brute_force.h"

namespace gridcull {
namespace {

constexpr int kScenes = 60;
constexpr int kResolution = 64;  // pixels on the long side, for the reference's sake

struct Totals {
    long long frames = 0, required = 0, pvs = 0, misses = 0;
};

TEST(ImageSpaceBruteForce, EveryCullerKeepsEveryObjectTheRayCastRequires) {
    std::vector<std::string> names;
    for (const FamilyEntry& family : families())
        if (family.draws_image)
            for (const AlgorithmEntry& a : family.algorithms)
                if (a.dimensions & kRuns3d) names.push_back(a.name);
    ASSERT_FALSE(names.empty());
    KnobValues knobs;
    knobs.set("oracle-res", kResolution);
    OracleOptions reference_options;
    reference_options.resolution = kResolution;
    std::vector<Totals> totals(names.size());
    for (uint64_t seed : test::seedsToRun(30001, kScenes)) {
        test::withSeed(seed, [&] {
            const Scene scene = test::lazyGridRandomScene(seed);
            std::vector<std::unique_ptr<Culler>> cullers;
            for (const std::string& name : names) {
                cullers.push_back(test::makeOrDie(name, knobs));
                cullers.back()->reset(scene);
            }
            FrameResult result;
            for (int frame = 0; frame < scene.frames; ++frame) {
                const double t = scene.timeOfFrame(frame);
                const test::Reference ref = test::bruteForce(scene, t, reference_options);
                const Camera camera = cameraAt(scene, t);
                for (size_t k = 0; k < cullers.size(); ++k) {
                    cullers[k]->cull(scene, camera, t, result);
                    std::vector<int> missed;
                    std::set_difference(ref.required.begin(), ref.required.end(),
                                        result.pvs.begin(), result.pvs.end(),
                                        std::back_inserter(missed));
                    EXPECT_TRUE(missed.empty())
                        << names[k] << " frame " << frame << ": " << missed.size()
                        << " required objects culled, first " << (missed.empty() ? -1 : missed[0]);
                    Totals& sum = totals[k];
                    ++sum.frames;
                    sum.required += (long long)ref.required.size();
                    sum.pvs += (long long)result.pvs.size();
                    sum.misses += (long long)missed.size();
                }
            }
        });
    }
    for (size_t k = 0; k < names.size(); ++k) {
        std::printf(
            "[lazy-grid brute force] %s: %lld frames, required %lld, pvs %lld, missed %lld\n",
            names[k].c_str(), totals[k].frames, totals[k].required, totals[k].pvs,
            totals[k].misses);
        EXPECT_EQ(totals[k].misses, 0) << names[k];
        // The scenes show something: the check is not vacuous.
        if (!test::singleSeedRun()) {
            EXPECT_GT(totals[k].required, totals[k].frames) << names[k];
        }
    }
}

}  // namespace
}  // namespace gridcull
