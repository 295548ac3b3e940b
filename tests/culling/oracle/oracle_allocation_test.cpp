// "Hot per-frame paths do not allocate", for the exact 2D oracle
// (culling/oracle/exact_oracle_2d.h): reset() reserves the envelope's pieces,
// events and per-object shapes, so no frame after it allocates, on every frame of
// the shipped 2D scenes. Counted by tests/common/allocation_counter.h (core_tests
// replaces operator new in tests/culling/counting_new.cpp).
#include <string>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"
#include "culling/oracle/exact_oracle.h"
#include "tests/common/allocation_counter.h"

namespace gridcull {
namespace {

TEST(OracleAllocation, NoFrameAfterResetAllocatesIn2d) {
    for (const char* name : {"figure1-2d", "walls-2d", "rooms-2d", "hidden-movers-2d"}) {
        SCOPED_TRACE(name);
        const SceneLoadResult loaded =
            loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/" + name + ".json");
        ASSERT_TRUE(loaded.scene.has_value());
        const Scene& scene = *loaded.scene;
        ExactOracle oracle;  // the exact envelope, --oracle-rays 0
        FrameResult result;
        result.pvs.reserve(scene.objects.size());
        oracle.reset(scene);
        long allocations = 0;
        for (int frame = 0; frame < scene.frames; ++frame) {
            const double t = scene.timeOfFrame(frame);
            const Camera camera = cameraAt(scene, t);
            test::startCounting();
            oracle.cull(scene, camera, t, result);
            test::stopCounting();
            allocations += test::allocationCount();
        }
        EXPECT_EQ(allocations, 0);
    }
}

}  // namespace
}  // namespace gridcull
