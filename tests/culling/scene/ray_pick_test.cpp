// Ray picking (culling/scene/ray_pick.h): nearest object along a ray, as the GUI hovers.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "culling/scene/ray_pick.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

Scene pickScene3d() {
    Scene scene = test::scene3d();
    test::addSphere(scene, 1, {50, 50, 60}, 3);
    test::addSphere(scene, 2, {50, 50, 30}, 2);
    test::addBox(scene, 3, {70, 40, 40}, {80, 60, 50});
    test::addMesh(scene, 4, {20, 50, 50}, test::quadMesh(5));  // the plane z = 50
    scene.objects.back().motion.kind = MotionKind::Keyframes;
    scene.objects.back().motion.keys = {{0.0, {20, 50, 50}}, {1.0, {20, 50, 40}}};
    scene.finalize();
    return scene;
}

TEST(RayPick, NearestObjectAndItsDistance3d) {
    const Scene scene = pickScene3d();
    double d = -1;
    EXPECT_EQ(pickObject(scene, 0.0, {50, 50, 0}, {0, 0, 1}, &d), 2);
    EXPECT_NEAR(d, 28.0, 1e-9);
    // Direction length does not matter; the distance is in world units.
    EXPECT_EQ(pickObject(scene, 0.0, {50, 50, 0}, {0, 0, 7}, &d), 2);
    EXPECT_NEAR(d, 28.0, 1e-9);
    EXPECT_EQ(pickObject(scene, 0.0, {50, 50, 45}, {0, 0, 1}, &d), 1);
    EXPECT_NEAR(d, 12.0, 1e-9);
    EXPECT_EQ(pickObject(scene, 0.0, {0, 50, 45}, {1, 0, 0}, &d), 3);
    EXPECT_NEAR(d, 70.0, 1e-9);
    EXPECT_EQ(pickObject(scene, 0.0, {50, 50, 0}, {0, 1, 0}, &d), -1);
    EXPECT_EQ(pickObject(scene, 0.0, {50, 50, 0}, {0, 0, 0}, &d), -1);
}

TEST(RayPick, InsideASolidIsDistanceZero) {
    const Scene scene = pickScene3d();
    double d = -1;
    EXPECT_EQ(pickObject(scene, 0.0, {50, 51, 60}, {0, 0, -1}, &d), 1);
    EXPECT_EQ(d, 0.0);
    EXPECT_EQ(pickObject(scene, 0.0, {75, 50, 45}, {1, 0, 0}, &d), 3);
    EXPECT_EQ(d, 0.0);
}

TEST(RayPick, MeshTrianglesFromBothSidesAndAtTimeT) {
    const Scene scene = pickScene3d();
    double d = -1;
    EXPECT_EQ(pickObject(scene, 0.0, {21, 51, 0}, {0, 0, 1}, &d), 4);
    EXPECT_NEAR(d, 50.0, 1e-9);
    EXPECT_EQ(pickObject(scene, 0.0, {21, 51, 90}, {0, 0, -1}, &d), 4);
    EXPECT_NEAR(d, 40.0, 1e-9);
    EXPECT_EQ(pickObject(scene, 1.0, {21, 51, 0}, {0, 0, 1}, &d), 4);
    EXPECT_NEAR(d, 40.0, 1e-9);
    EXPECT_EQ(pickObject(scene, 0.0, {30, 51, 0}, {0, 0, 1}, nullptr), -1);  // beside the quad
}

TEST(RayPick, CirclesBoxesAndPolygons2d) {
    Scene scene = test::scene2d();
    test::addSphere(scene, 1, {50, 50, 0}, 5);
    test::addBox(scene, 2, {70, 45, 0}, {75, 55, 0});
    test::addPolygon(scene, 3, {{20, 40, 0}, {30, 50, 0}, {20, 60, 0}, {25, 50, 0}});  // concave
    scene.finalize();
    double d = -1;
    EXPECT_EQ(pickObject(scene, 0.0, {0, 50, 0}, {1, 0, 0}, &d), 3);
    EXPECT_NEAR(d, 25.0, 1e-9);  // the polygon's notch at (25, 50)
    EXPECT_EQ(pickObject(scene, 0.0, {60, 50, 0}, {1, 0, 0}, &d), 2);
    EXPECT_NEAR(d, 10.0, 1e-9);
    EXPECT_EQ(pickObject(scene, 0.0, {60, 50, 0}, {-1, 0, 0}, &d), 1);
    EXPECT_NEAR(d, 5.0, 1e-9);
    EXPECT_EQ(pickObject(scene, 0.0, {27, 50, 0}, {0, 1, 0}, &d), 3);  // inside the polygon
    EXPECT_EQ(d, 0.0);
    EXPECT_EQ(pickObject(scene, 0.0, {60, 50, 0}, {0, 1, 0}, &d), -1);
}

}  // namespace
}  // namespace gridcull
