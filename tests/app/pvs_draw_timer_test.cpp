// The draw half of bench --draw (app/pvs_draw_timer.h): only the PVS is drawn,
// from the culling camera, and the time covers the draw. Needs a GL context
// (the test run provides an X display, under xvfb-run when headless).
#include <gtest/gtest.h>

#include "app/pvs_draw_timer.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

// Two spheres side by side in front of the camera, apart on the image.
Scene twoSpheres() {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 20, 0}, {50, 20, 100}, 60.0);
    test::addSphere(scene, 1, {40, 20, 50}, 4);
    test::addSphere(scene, 2, {60, 20, 50}, 4);
    scene.finalize();
    return scene;
}

// Pixels that differ from the top-left one (the background: nothing is drawn
// in the image's corner here).
int drawnPixels(const PvsDrawTimer& timer) {
    std::vector<uint8_t> rgba;
    timer.readPixels(rgba);
    int count = 0;
    for (size_t p = 4; p + 3 < rgba.size(); p += 4)
        if (rgba[p] != rgba[0] || rgba[p + 1] != rgba[1] || rgba[p + 2] != rgba[2]) ++count;
    return count;
}

TEST(PvsDrawTimer, DrawsOnlyThePvs) {
    const Scene scene = twoSpheres();
    PvsDrawTimer timer;
    std::string error;
    ASSERT_TRUE(timer.init(scene, 256, error)) << error;
    const Camera camera = cameraAt(scene, 0.0);
    EXPECT_GE(timer.draw(scene, camera, 0.0, {}), 0.0);
    EXPECT_EQ(drawnPixels(timer), 0) << "an empty PVS draws nothing";
    timer.draw(scene, camera, 0.0, {1});
    const int one = drawnPixels(timer);
    EXPECT_GT(one, 100);
    timer.draw(scene, camera, 0.0, {1, 2});
    const int both = drawnPixels(timer);
    // The two spheres are alike and apart: both cover twice one, within the
    // anti-aliasing-free raster's edge pixels (a named slack of 5%).
    constexpr double kEdgeSlack = 0.05;
    EXPECT_NEAR(both, 2 * one, kEdgeSlack * 2 * one);
    timer.draw(scene, camera, 0.0, {2, 99});  // an id not in the scene is ignored
    EXPECT_NEAR(drawnPixels(timer), one, kEdgeSlack * one);
}

}  // namespace
}  // namespace gridcull
