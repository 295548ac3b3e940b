// View-frustum culling (culling/baseline/vfc_culler.h): what it keeps, what it culls, and
// the over-estimation it is allowed (objects near a frustum corner, and anything
// occluded: it never looks at occlusion).
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

#include "culling/baseline/frustum_tests.h"
#include "culling/baseline/vfc_culler.h"
#include "culling/oracle/exact_oracle.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

using test::addBox;
using test::addPolygon;
using test::addSphere;
using V = std::vector<int>;

constexpr double kPi = 3.141592653589793;

V vfcIds(const Scene& scene, double t = 0.0) {
    VfcCuller vfc;
    return test::cullIds(vfc, scene, t);
}

TEST(Vfc3d, KeepsWhatTheFrustumMayContain) {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 50, 5}, {50, 50, 100}, 60.0, 0.5, 80.0);
    addSphere(scene, 1, {50, 50, 50}, 2);            // ahead
    addSphere(scene, 2, {50, 50, -20}, 2);           // behind the camera
    addSphere(scene, 3, {50, 95, 30}, 2);            // above the top plane
    addBox(scene, 4, {0, 0, 86}, {100, 100, 90});    // beyond far (depth 81..85)
    addBox(scene, 5, {49, 49, 5.1}, {51, 51, 5.4});  // between eye and near
    addBox(scene, 6, {0, 0, 60}, {100, 100, 84});    // straddles far
    scene.finalize();
    EXPECT_EQ(vfcIds(scene), (V{1, 6}));
}

// The box-plane test keeps a box that is outside the frustum but not wholly
// outside any one plane: beside the edge where the right and far planes meet,
// the two planes test different corners. The exact oracle drops it; this is the
// over-estimation vfc is allowed.
TEST(Vfc3d, KeepsABoxBesideAFrustumEdgeThatTheOracleDrops) {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 50, 5}, {50, 50, 100}, 60.0, 0.1, 60.0);
    const Camera camera = cameraAt(scene, 0.0);
    glm::dvec3 right, up, fwd;
    camera.basis(right, up, fwd);
    const double tan_x = std::tan(glm::radians(30.0)) * camera.aspect;
    // Camera space: the edge is at x = 60 tan_x, z = 60. The unit box centred 1.5
    // to the right of it and 0.5 beyond far reaches back across the far plane
    // (z from 59.5) and leftwards past the right plane's trace at its far end
    // (x from 60 tan_x + 0.5 < 61.5 tan_x), yet no point of it is inside both.
    const glm::dvec3 c = camera.position + right * (60 * tan_x + 1.5) + fwd * 60.5;
    addBox(scene, 1, c - glm::dvec3(1.0), c + glm::dvec3(1.0));
    scene.finalize();
    EXPECT_TRUE(boxMayIntersectFrustum(scene.objects[0].bounds, camera));
    EXPECT_EQ(vfcIds(scene), V{1});
    ExactOracle exact;
    EXPECT_EQ(test::cullIds(exact, scene), V{});
}

TEST(Vfc3d, CameraInsideTheBoundsKeepsTheObject) {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 50, 5}, {50, 50, 100}, 60.0, 1.0, 100.0);
    // Smaller than the near distance, so no plane test alone would keep it.
    addBox(scene, 1, {49.9, 49.9, 4.9}, {50.1, 50.1, 5.1});
    addSphere(scene, 2, {50, 50, 5.05}, 0.2);
    scene.finalize();
    EXPECT_EQ(vfcIds(scene), (V{1, 2}));
}

TEST(Vfc3d, UsesTheBoundsAtTimeT) {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 50, 5}, {50, 50, 100}, 60.0);
    addSphere(scene, 1, {50, 50, -20}, 2);  // behind the camera at t = 0
    scene.objects.back().motion.kind = MotionKind::Keyframes;
    scene.objects.back().motion.keys = {{0.0, {50, 50, -20}}, {1.0, {50, 50, 40}}};
    scene.finalize();
    EXPECT_EQ(vfcIds(scene, 0.0), V{});
    EXPECT_EQ(vfcIds(scene, 1.0), V{1});
}

TEST(Vfc3d, CountsEveryObjectTested) {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 50, 5}, {50, 50, 100}, 60.0);
    for (int i = 0; i < 7; ++i) addSphere(scene, 10 + i, {10.0 * i, 50, 50}, 1);
    scene.finalize();
    VfcCuller vfc;
    vfc.reset(scene);
    FrameResult out;
    vfc.cull(scene, cameraAt(scene, 0.0), 0.0, out);
    EXPECT_EQ(out.stats.get(Counter::ObjectsTested), 7);
    EXPECT_TRUE(std::is_sorted(out.pvs.begin(), out.pvs.end()));
}

Scene scene2dLooking(const glm::dvec3& eye, double heading, double fov, double far = 1000.0) {
    Scene scene = test::scene2d();
    test::setCamera(scene, eye, eye + glm::dvec3(std::cos(heading), std::sin(heading), 0), fov, 0.1,
                    far);
    return scene;
}

void addCircleAt(Scene& scene, int id, const glm::dvec3& eye, double angle, double distance,
                 double radius) {
    addSphere(scene, id, eye + glm::dvec3(std::cos(angle), std::sin(angle), 0) * distance, radius);
}

TEST(Vfc2d, WedgeWiderThanAHalfTurn) {
    const glm::dvec3 eye{50, 50, 0};
    Scene scene = scene2dLooking(eye, 0.0, 270.0);  // sees +-135 degrees
    addCircleAt(scene, 1, eye, 0.0, 20, 1);
    addCircleAt(scene, 2, eye, 130 * kPi / 180, 20, 1);
    addCircleAt(scene, 3, eye, -130 * kPi / 180, 20, 1);
    addCircleAt(scene, 4, eye, kPi, 20, 1);                                       // straight behind
    addBox(scene, 5, eye + glm::dvec3(-30, -2, 0), eye + glm::dvec3(-25, 2, 0));  // behind
    scene.finalize();
    EXPECT_EQ(vfcIds(scene), (V{1, 2, 3}));
}

TEST(Vfc2d, WedgeAcrossTheSeamAndFullTurn) {
    const glm::dvec3 eye{50, 50, 0};
    Scene scene = scene2dLooking(eye, kPi, 60.0, 40.0);
    addCircleAt(scene, 1, eye, 170 * kPi / 180, 20, 1);
    addCircleAt(scene, 2, eye, -170 * kPi / 180, 20, 1);
    addCircleAt(scene, 3, eye, 0.0, 20, 1);
    addCircleAt(scene, 4, eye, kPi, 45, 1);                                       // beyond far
    addBox(scene, 5, eye + glm::dvec3(-30, -1, 0), eye + glm::dvec3(-20, 1, 0));  // on the seam
    scene.finalize();
    EXPECT_EQ(vfcIds(scene), (V{1, 2, 5}));
    Scene full = scene;
    full.camera.fov_deg = 360.0;
    EXPECT_EQ(vfcIds(full), (V{1, 2, 3, 5}));
}

TEST(Vfc2d, CameraInsideAnObjectKeepsIt) {
    const glm::dvec3 eye{50, 50, 0};
    Scene scene = scene2dLooking(eye, 0.0, 30.0);
    addSphere(scene, 1, eye + glm::dvec3(-1, 0, 0), 2);  // centre behind the camera
    addBox(scene, 2, eye + glm::dvec3(-5, -1, 0), eye + glm::dvec3(0.5, 1, 0));
    addPolygon(
        scene, 3,
        {eye + glm::dvec3(-4, -1, 0), eye + glm::dvec3(1, 0, 0), eye + glm::dvec3(-4, 1, 0)});
    scene.finalize();
    EXPECT_EQ(vfcIds(scene), (V{1, 2, 3}));
}

}  // namespace
}  // namespace gridcull
