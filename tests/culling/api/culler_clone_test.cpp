// Culler::clone (culling/api/culler.h): a copy taken between two frames goes on
// exactly as the culler it was copied from would have: the same PVS and the same
// counters every later frame, for every algorithm of the registry, on seeded
// random 2D and 3D scenes (moving objects, meshes, TBVs in flight). The culler
// copied from is destroyed before its copy runs, so a copy that still points
// into its original's memory reads freed memory (AddressSanitizer reports it in
// the sanitized run). A copy of a copy is checked the same way. Debug capture is
// on, as in the window, whose checkpoints these copies are.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/api/culler.h"
#include "culling/registry/registry.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/bsp_oq/bsp_random_scenes.h"
#include "tests/culling/hzb_tbv/hzb_random_rooms.h"
#include "tests/culling/rgvc/rgvc_random_scene.h"
#include "tests/culling/rgvc/rgvc_random_scene3d.h"

namespace gridcull {
namespace {

constexpr int kSeedsPerKind = 2;

std::vector<FrameResult> runFrames(Culler& culler, const Scene& scene, int first, int last) {
    std::vector<FrameResult> results;
    for (int frame = first; frame <= last; ++frame) {
        const double t = scene.timeOfFrame(frame);
        FrameResult result;
        culler.cull(scene, cameraAt(scene, t), t, result);
        results.push_back(result);
    }
    return results;
}

// Runs `algo` straight through, and again cut at two frames: cloned at the
// first cut (the original destroyed), the clone cloned at the second.
void checkScene(const std::string& algo, const Scene& scene, const KnobValues& knobs) {
    const int last = scene.frames - 1;
    const int cut1 = scene.frames / 3, cut2 = 2 * scene.frames / 3;
    ASSERT_GT(cut1, 0);
    ASSERT_GT(cut2, cut1);

    std::unique_ptr<Culler> straight = test::makeOrDie(algo, knobs);
    straight->setDebugCapture(true);
    straight->reset(scene);
    const std::vector<FrameResult> expected = runFrames(*straight, scene, 0, last);

    std::unique_ptr<Culler> original = test::makeOrDie(algo, knobs);
    original->setDebugCapture(true);
    original->reset(scene);
    runFrames(*original, scene, 0, cut1 - 1);
    std::unique_ptr<Culler> copy = original->clone();
    ASSERT_NE(copy, nullptr) << algo << " cannot be cloned";
    original.reset();
    EXPECT_EQ(copy->debugSnapshot(), nullptr) << algo << ": a copy's snapshot is empty";
    std::vector<FrameResult> got = runFrames(*copy, scene, cut1, cut2 - 1);
    std::unique_ptr<Culler> second = copy->clone();
    ASSERT_NE(second, nullptr);
    copy.reset();
    const std::vector<FrameResult> rest = runFrames(*second, scene, cut2, last);
    got.insert(got.end(), rest.begin(), rest.end());

    for (int frame = cut1; frame <= last; ++frame) {
        const FrameResult& want = expected[size_t(frame)];
        const FrameResult& have = got[size_t(frame - cut1)];
        ASSERT_EQ(have.pvs, want.pvs) << algo << " frame " << frame;
        ASSERT_EQ(have.stats.present, want.stats.present) << algo << " frame " << frame;
        for (int c = 0; c < kCounterCount; ++c)
            ASSERT_EQ(have.stats.values[size_t(c)], want.stats.values[size_t(c)])
                << algo << " frame " << frame << ", counter " << counterName(Counter(c));
    }
    EXPECT_EQ(second->debugSnapshot() != nullptr, straight->debugSnapshot() != nullptr) << algo;
}

TEST(CullerClone, ContinuesExactlyAsTheCullerItWasCopiedFrom) {
    KnobValues knobs;
    knobs.set("oracle-res", 96);  // the image-space families follow it: small and fast
    int checked = 0;
    for (const FamilyEntry& family : families()) {
        for (const AlgorithmEntry& algorithm : family.algorithms) {
            SCOPED_TRACE(algorithm.name);
            for (const uint64_t seed : test::seedsToRun(700000, kSeedsPerKind)) {
                test::withSeed(seed, [&] {
                    std::vector<Scene> scenes;
                    if (algorithm.dimensions & kRuns2d)
                        scenes.push_back(test::rgvcRandomScene(seed));
                    if (algorithm.dimensions & kRuns3d) {
                        scenes.push_back(test::rgvcRandomScene3d(seed));
                        scenes.push_back(test::bspRandomScene(seed));
                        scenes.push_back(test::hzbRandomRooms(seed));
                    }
                    for (const Scene& scene : scenes) {
                        if (scene.frames < 3) continue;
                        std::string why;
                        if (!algorithmFits(algorithm.name, scene, why)) continue;
                        checkScene(algorithm.name, scene, knobs);
                        ++checked;
                    }
                });
            }
        }
    }
    std::printf("[clone] %d algorithm-scene runs continued identically from clones\n", checked);
    EXPECT_GT(checked, 20);
}

}  // namespace
}  // namespace gridcull
