// What the sweep does with a scene it cannot replay: one the loader refuses
// is a rejection (listed, not checked), one it cannot write is an error.
#include <string>

#include <gtest/gtest.h>

#include "tests/common/oracle_test_scenes.h"
#include "tests/sweep/sweep_scenes.h"

namespace gridcull {
namespace {

TEST(SweepScenes, ALoaderRefusalIsARejectionAWriteFailureAnError) {
    Scene scene = test::scene2d();
    test::setCamera(scene, {5, 5, 0}, {50, 50, 0}, 90.0);
    // Collinear corners: a polygon that encloses no area, which the loader refuses.
    test::addPolygon(scene, 0, {{10, 10, 0}, {20, 20, 0}, {30, 30, 0}});
    scene.finalize();
    Scene out;
    std::string error;
    bool rejected = false;
    const std::string file = ::testing::TempDir() + "sweep-rejected.json";
    EXPECT_FALSE(sweep::replayable(scene, file, out, error, &rejected));
    EXPECT_TRUE(rejected);
    EXPECT_NE(error.find("objects[0].points"), std::string::npos) << error;

    EXPECT_FALSE(sweep::replayable(test::sphereWallScene(), "/nonexistent-dir/s.json", out, error,
                                   &rejected));
    EXPECT_FALSE(rejected);
    EXPECT_NE(error.find("/nonexistent-dir/s.json"), std::string::npos) << error;
}

}  // namespace
}  // namespace gridcull
