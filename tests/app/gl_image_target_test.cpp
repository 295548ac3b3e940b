// The OpenGL image target (app/gl_image_target.h) behind the -gl algorithms of
// app/app_cullers.h: the lazy grids on it cull as on the software target on a
// scene whose answer is plain, and the read-back queries themselves. Needs a GL
// context (the test run provides an X display, under xvfb-run when headless).
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "app/app_cullers.h"
#include "app/gl_image_target.h"
#include "culling/raster/screen_mapping.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

// The wall of tests/culling/lazy_grid/lazy_grid_traversal_test.cpp: five spheres hidden
// behind it, one peeking over its top edge, one beside it.
Scene wallScene() {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 20, 0}, {50, 20, 100}, 60.0);
    test::addBox(scene, 1, {30, 0, 30}, {70, 30, 31});
    for (int k = 0; k < 5; ++k) test::addSphere(scene, 10 + k, {35 + 7.5 * k, 15, 60}, 3);
    test::addSphere(scene, 20, {50, 38, 60}, 3.2);
    test::addSphere(scene, 21, {100, 15, 60}, 3);
    scene.finalize();
    return scene;
}

TEST(GlImageTarget, LazyGridsCullWhatTheWallHidesLikeOnTheSoftwareTarget) {
    const Scene scene = wallScene();
    KnobValues options;
    options.set("oracle-res", 320);
    for (const char* name :
         {"lazy-grid-gl", "lazy-grid-z-gl", "busy-grid-gl", "busy-grid-tight-gl"}) {
        std::string error;
        auto culler = makeAppCuller(name, options, error);
        ASSERT_TRUE(culler) << name << ": " << error;
        EXPECT_EQ(std::string(culler->name()), name);
        culler->reset(scene);
        FrameResult result;
        culler->cull(scene, cameraAt(scene, 0.0), 0.0, result);
        EXPECT_EQ(result.pvs, (std::vector<int>{1, 20, 21})) << name;
        EXPECT_GT(result.stats.get(Counter::PixelQueries), 0) << name;
    }
}

TEST(GlImageTarget, ReadBackQueriesSeeWhatWasDrawn) {
    std::string error;
    ASSERT_TRUE(makeAppCuller("lazy-grid-gl", {}, error)) << error;  // the context
    GlImageTarget target;
    ASSERT_TRUE(target.init(error)) << error;
    Camera camera;
    camera.position = {0, 0, 0};
    camera.target = {0, 0, 1};
    camera.fov_deg = 90.0;
    camera.aspect = 2.0;
    camera.near = 0.5;
    camera.far = 100.0;
    Scene empty;
    target.prepare(empty);
    target.begin(camera, 64, 32, true);
    const PixelRect all{0, 0, 63, 31};
    EXPECT_EQ(target.countFree(all), 64 * 32);
    EXPECT_TRUE(std::isinf(target.farthestDepth(all)));
    // A wall at depth 10 across the image's left half (world +x is the image's left).
    Scene scene = test::scene3d();
    test::addBox(scene, 0, {0, -50, 10}, {50, 50, 11});
    const SceneObject& wall = scene.objects[0];
    ScreenMapping mapping;
    mapping.set(camera, 64, 32);
    PixelRect written;
    ASSERT_TRUE(target.draw(wall, 0, {0, 0, 0}, mapping.project(wall.box).rect, written));
    target.end();
    EXPECT_EQ(target.countFree({0, 0, 30, 31}), 0);
    EXPECT_EQ(target.countFree({33, 0, 63, 31}), 31 * 32);
    const double depth = target.farthestDepth({0, 0, 30, 31});
    EXPECT_GE(depth, 10.0);  // never nearer than drawn
    EXPECT_LT(depth, 10.05);
}

// Every algorithm of a family that draws an image gets a -gl twin; the others do not.
TEST(GlImageTarget, BenchAndCullKnowTheGlNamesTheWindowDoesNot) {
    const std::vector<std::string> all = appAlgorithmNames();
    const std::vector<std::string> core = algorithmNames();
    EXPECT_EQ(all.size(), core.size() + 4);
    EXPECT_NE(std::find(all.begin(), all.end(), "busy-grid-gl"), all.end());
    EXPECT_EQ(std::find(all.begin(), all.end(), "vfc-gl"), all.end());
    EXPECT_EQ(std::find(core.begin(), core.end(), "busy-grid-gl"), core.end());
    EXPECT_EQ(registryAlgorithmOf("busy-grid-gl"), "busy-grid");
    EXPECT_EQ(registryAlgorithmOf("rgvc"), "rgvc");
    EXPECT_EQ(registryAlgorithmOf("rgvc-gl"), "");
}

}  // namespace
}  // namespace gridcull
