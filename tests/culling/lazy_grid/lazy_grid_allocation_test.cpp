// "Hot per-frame paths do not allocate": once a lazy grid culler has seen a
// scene's first frames, cull() allocates nothing (snapshots off), moving objects,
// BVH refits and rebuilds included. Counted by tests/common/allocation_counter.h
// (core_tests replaces operator new in tests/culling/counting_new.cpp); the
// counter runs only inside the measured frames.
#include <vector>

#include <gtest/gtest.h>

#include "culling/api/culler.h"
#include "tests/common/allocation_counter.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/lazy_grid/lazy_grid_random_scene.h"

namespace gridcull {
namespace {

TEST(LazyGridAllocation, SteadyFramesAllocateNothing) {
    for (uint64_t seed : {3u, 8u, 21u, 34u}) {
        const Scene scene = test::lazyGridRandomScene(seed);
        KnobValues options;
        options.set("oracle-res", 320);
        for (const char* name : {"lazy-grid", "lazy-grid-z", "busy-grid", "busy-grid-tight"}) {
            auto culler = test::makeOrDie(name, options);
            culler->reset(scene);
            FrameResult result;
            result.pvs.reserve(scene.objects.size());
            for (int frame = 0; frame < 3; ++frame)
                culler->cull(scene, cameraAt(scene, scene.timeOfFrame(frame)),
                             scene.timeOfFrame(frame), result);
            long allocations = 0;
            for (int frame = 3; frame < scene.frames; ++frame) {
                const double t = scene.timeOfFrame(frame);
                const Camera camera = cameraAt(scene, t);
                test::startCounting();
                culler->cull(scene, camera, t, result);
                test::stopCounting();
                allocations += test::allocationCount();
            }
            EXPECT_EQ(allocations, 0) << name << " seed " << seed;
        }
    }
}

}  // namespace
}  // namespace gridcull
