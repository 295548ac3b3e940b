// "Hot per-frame paths do not allocate", for the octree + hierarchical
// z-buffer family: the octree's node pool, the z-buffer, the Z-pyramid, the TBV
// manager and the per-frame lists grow to the scene's high-water mark and are
// reused, so a second pass over a scene's frames after reset() allocates
// nothing (snapshots off), for all three algorithms. The first pass may
// allocate: the octree grows nodes where objects and TBVs first go.
// Counted by tests/common/allocation_counter.h (core_tests replaces operator
// new in tests/culling/counting_new.cpp).
#include <string>

#include <gtest/gtest.h>

#include "culling/api/culler.h"
#include "culling/io/scene_loader.h"
#include "tests/common/allocation_counter.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/hzb_tbv/hzb_random_rooms.h"

namespace gridcull {
namespace {

// Allocations of the second of two passes over the scene's frames.
long secondPassAllocations(const std::string& algo, const Scene& scene, int frames) {
    KnobValues knobs;
    knobs.set("oracle-res", 256);  // the z-buffer's size; allocation does not depend on it
    auto culler = test::makeOrDie(algo, knobs);
    FrameResult result;
    result.pvs.reserve(scene.objects.size());
    long allocations = 0;
    for (int pass = 0; pass < 2; ++pass) {
        culler->reset(scene);
        for (int frame = 0; frame < frames; ++frame) {
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

TEST(HzbAllocation, SecondPassOverRandomRoomsAllocatesNothing) {
    for (const char* algo : {"hzb-tbv", "hzb-tbvi", "hzb"})
        for (uint64_t seed = 1; seed <= 6; ++seed) {
            const Scene scene = test::hzbRandomRooms(seed);
            EXPECT_EQ(secondPassAllocations(algo, scene, scene.frames), 0)
                << algo << " seed " << seed;
        }
}

TEST(HzbAllocation, SecondPassOverTheRoomsSceneAllocatesNothing) {
    const SceneLoadResult loaded =
        loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/rooms-3d.json");
    ASSERT_TRUE(loaded.scene.has_value());
    for (const char* algo : {"hzb-tbv", "hzb"})
        EXPECT_EQ(secondPassAllocations(algo, *loaded.scene, 40), 0) << algo;
}

}  // namespace
}  // namespace gridcull
