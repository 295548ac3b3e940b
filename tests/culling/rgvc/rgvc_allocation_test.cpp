// "Hot per-frame paths do not allocate", for regular-grid culling: the culler's
// storage (T's node pool, each TBV's node list, the expiration queue, the
// per-frame lists) grows to the scene's high-water mark and is reused, so a
// second pass over a scene's frames after reset() allocates nothing (snapshots
// off). The first pass may allocate: TBVs grow while adaptive validity
// lengthens their periods, and a scene's peak is not known in advance.
// Counted by tests/common/allocation_counter.h (core_tests replaces operator
// new in tests/culling/counting_new.cpp).
#include <string>

#include <gtest/gtest.h>

#include "culling/api/culler.h"
#include "culling/io/scene_loader.h"
#include "tests/common/allocation_counter.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/rgvc/rgvc_random_scene.h"
#include "tests/culling/rgvc/rgvc_random_scene3d.h"

namespace gridcull {
namespace {

// Allocations of the second of two passes over the scene's frames.
long secondPassAllocations(const Scene& scene) {
    auto culler = test::makeOrDie("rgvc", KnobValues{});
    FrameResult result;
    result.pvs.reserve(scene.objects.size());
    long allocations = 0;
    for (int pass = 0; pass < 2; ++pass) {
        culler->reset(scene);
        for (int frame = 0; frame < scene.frames; ++frame) {
            const double t = scene.timeOfFrame(frame);
            const Camera camera = cameraAt(scene, t);
            if (pass == 1) test::startCounting();
            culler->cull(scene, camera, t, result);
            test::stopCounting();
            if (pass == 1) allocations += test::allocationCount();
        }
    }
    return allocations;
}

TEST(RgvcAllocation, SecondPassOverRandomScenesAllocatesNothing) {
    for (uint64_t seed = 1; seed <= 12; ++seed) {
        EXPECT_EQ(secondPassAllocations(test::rgvcRandomScene(seed)), 0) << "2D seed " << seed;
        EXPECT_EQ(secondPassAllocations(test::rgvcRandomScene3d(seed)), 0) << "3D seed " << seed;
    }
}

TEST(RgvcAllocation, SecondPassOverTheHiddenMoversAllocatesNothing) {
    for (const char* name : {"hidden-movers-2d", "hidden-movers-3d"}) {
        const SceneLoadResult loaded =
            loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/" + name + ".json");
        ASSERT_TRUE(loaded.scene.has_value()) << name;
        EXPECT_EQ(secondPassAllocations(*loaded.scene), 0) << name;
    }
}

}  // namespace
}  // namespace gridcull
