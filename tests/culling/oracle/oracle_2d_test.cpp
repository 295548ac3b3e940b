// The 2D exact oracle (its exact angular envelope, and the sampled sweep where a
// test says so) on hand-made scenes whose visible set is known by construction.
// Unless a test says otherwise: world [0, 100]^2 in 10-unit voxels, camera at
// (5, 50) looking down +x, a 90 degree wedge, far 1000, the exact oracle (--oracle-rays 0); tests of the sampled sweep say so and use
// 16384 rays per turn (4096 over the wedge, one per 0.022 degrees).
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

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
const glm::dvec3 kEye{5, 50, 0};

V exactIds(const Scene& scene, double t = 0.0, OracleOptions options = OracleOptions{}) {
    ExactOracle oracle{options};
    return test::cullIds(oracle, scene, t);
}

V vfcIds(const Scene& scene, double t = 0.0) {
    VfcCuller vfc;
    return test::cullIds(vfc, scene, t);
}

bool has(const V& ids, int id) {
    return std::count(ids.begin(), ids.end(), id) > 0;
}

Scene lookingRight(double fov = 90.0) {
    Scene scene = test::scene2d();
    test::setCamera(scene, kEye, {100, 50, 0}, fov);
    return scene;
}

glm::dvec3 polar(const glm::dvec3& from, double angle, double distance) {
    return from + glm::dvec3(std::cos(angle), std::sin(angle), 0.0) * distance;
}

TEST(Oracle2d, WallHidesTheObjectBehindItNotTheOneBeside) {
    Scene scene = lookingRight();
    addBox(scene, 1, {40, 30, 0}, {42, 70, 0});
    addSphere(scene, 2, {60, 50, 0}, 3);  // straight behind the wall
    addSphere(scene, 3, {60, 95, 0}, 3);  // beside it, inside the wedge
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{1, 3}));
    EXPECT_EQ(vfcIds(scene), (V{1, 2, 3}));
}

TEST(Oracle2d, SeesThroughAGapNarrowerThanOneVoxel) {
    Scene scene = lookingRight();
    ASSERT_DOUBLE_EQ(scene.grid.voxelSize().y, 10.0);
    addBox(scene, 1, {40, 0, 0}, {42, 49, 0});  // a slit 2 units wide at y = 49..51
    addBox(scene, 2, {40, 51, 0}, {42, 100, 0});
    addSphere(scene, 3, {80, 50, 0}, 1);  // seen only through the slit
    addSphere(scene, 4, {80, 20, 0}, 3);  // behind the wall, away from the slit
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{1, 2, 3}));
}

// Against each edge of the wedge: a circle reaching 0.1 into the wedge (about
// five rays at distance 50) is seen, one 0.01 outside is not, and neither is a
// box whose nearest corner is 0.01 outside.
TEST(Oracle2d, ObjectsGrazingTheWedgeEdges) {
    for (int side = -1; side <= 1; side += 2) {
        SCOPED_TRACE(side);
        const double edge = side * kPi / 4;
        const glm::dvec3 out{std::cos(edge + side * kPi / 2), std::sin(edge + side * kPi / 2), 0};
        const glm::dvec3 on_edge = polar(kEye, edge, 50.0);
        Scene scene = lookingRight();
        addSphere(scene, 1, on_edge + out * (2.0 - 0.1), 2.0);
        addSphere(scene, 2, on_edge + out * (2.0 + 0.01), 2.0);
        const glm::dvec3 q = on_edge + out * 0.01;
        glm::dvec3 lo = q, hi = q;
        for (int i = 0; i < 2; ++i) (out[i] >= 0 ? hi[i] : lo[i]) += out[i] >= 0 ? 2.0 : -2.0;
        addBox(scene, 3, lo, hi);
        scene.finalize();
        EXPECT_EQ(exactIds(scene), V{1});
        EXPECT_EQ(vfcIds(scene), V{1});
    }
}

TEST(Oracle2d, ObjectsGrazingFar) {
    Scene scene = lookingRight();
    scene.camera.far = 60.0;
    addSphere(scene, 1, kEye + glm::dvec3(60 + 2 - 0.1, 0, 0), 2);  // 0.1 inside far
    addSphere(scene, 2, polar(kEye, 0.3, 60 + 2 + 0.01), 2);        // 0.01 beyond far
    // A box whose nearest point, its corner towards the camera, is 0.01 beyond far.
    const glm::dvec3 corner = polar(kEye, -0.3, 60.01);
    addBox(scene, 3, corner + glm::dvec3(0, -3, 0), corner + glm::dvec3(3, 0, 0));
    scene.finalize();
    EXPECT_EQ(exactIds(scene), V{1});
    EXPECT_EQ(vfcIds(scene), V{1});
}

TEST(Oracle2d, CameraInsideACircleOrBoxSeesOnlyIt) {
    for (int shape = 0; shape < 2; ++shape) {
        SCOPED_TRACE(shape == 0 ? "circle" : "box");
        Scene scene = lookingRight();
        if (shape == 0)
            addSphere(scene, 1, kEye + glm::dvec3(1, 0.5, 0), 1.5);
        else
            addBox(scene, 1, kEye - glm::dvec3(1, 1, 0), kEye + glm::dvec3(0.5, 2, 0));
        addSphere(scene, 2, {60, 50, 0}, 3);
        addSphere(scene, 3, kEye + glm::dvec3(0.4, 0, 0), 0.2);  // inside the first one too
        scene.finalize();
        EXPECT_EQ(exactIds(scene), V{1});
        EXPECT_TRUE(has(vfcIds(scene), 1));
    }
}

TEST(Oracle2d, CameraInsideAConcavePolygonSeesOnlyIt) {
    Scene scene = lookingRight(360.0);
    // An L whose corner holds the camera.
    addPolygon(scene, 1,
               {{0, 40, 0}, {30, 40, 0}, {30, 45, 0}, {10, 45, 0}, {10, 80, 0}, {0, 80, 0}});
    addSphere(scene, 2, {60, 50, 0}, 3);
    addSphere(scene, 3, {20, 60, 0}, 3);  // in the L's crook, but the camera is inside the L
    scene.finalize();
    test::setCamera(scene, {5, 42, 0}, {100, 42, 0}, 360.0);
    EXPECT_EQ(exactIds(scene), V{1});
}

// A U that wraps around the camera spans more than 180 degrees as seen from it;
// the camera looks out through the opening.
TEST(Oracle2d, UShapedPolygonAroundTheCamera) {
    Scene scene = test::scene2d();
    test::setCamera(scene, {50, 50, 0}, {100, 50, 0}, 360.0);
    addPolygon(scene, 1,
               {{30, 30, 0},
                {70, 30, 0},
                {70, 35, 0},
                {35, 35, 0},
                {35, 65, 0},
                {70, 65, 0},
                {70, 70, 0},
                {30, 70, 0}});
    addSphere(scene, 2, {90, 50, 0}, 3);  // out through the opening
    addSphere(scene, 3, {10, 50, 0}, 3);  // behind the U's back
    addSphere(scene, 4, {50, 85, 0}, 3);  // beyond its upper arm
    addSphere(scene, 5, {60, 45, 0}, 2);  // inside the opening with the camera
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{1, 2, 5}));
    EXPECT_EQ(vfcIds(scene), (V{1, 2, 3, 4, 5}));
}

TEST(Oracle2d, EmptyView) {
    Scene scene = test::scene2d();
    test::setCamera(scene, kEye, {-100, 50, 0}, 90.0);  // looking out of the world
    addSphere(scene, 1, {60, 50, 0}, 3);
    addBox(scene, 2, {20, 0, 0}, {30, 100, 0});
    addPolygon(scene, 3, {{50, 10, 0}, {60, 10, 0}, {55, 20, 0}});
    scene.finalize();
    EXPECT_EQ(exactIds(scene), V{});
    EXPECT_EQ(vfcIds(scene), V{});
}

TEST(Oracle2d, ConcavePolygonOccludesACircle) {
    Scene scene = lookingRight();
    addPolygon(scene, 1,
               {{40, 35, 0},
                {44, 35, 0},
                {44, 48, 0},
                {48, 50, 0},
                {44, 52, 0},
                {44, 65, 0},
                {40, 65, 0}});
    scene.objects.back().motion.kind = MotionKind::Keyframes;
    scene.objects.back().motion.keys = {{0.0, scene.objects.back().anchor},
                                        {1.0, scene.objects.back().anchor + glm::dvec3(0, 30, 0)}};
    addSphere(scene, 2, {70, 50, 0}, 3);  // behind the polygon at t = 0
    addSphere(scene, 3, {70, 90, 0}, 3);  // beside it
    scene.finalize();
    EXPECT_EQ(exactIds(scene, 0.0), (V{1, 3}));
    // At t = 1 the polygon has moved up out of the way of circle 2 and now
    // hides circle 3.
    EXPECT_EQ(exactIds(scene, 1.0), (V{1, 2}));
}

TEST(Oracle2d, WedgeAcrossTheSeam) {
    Scene scene = test::scene2d();
    const glm::dvec3 eye{50, 50, 0};
    test::setCamera(scene, eye, {0, 50, 0}, 90.0);  // heading pi: wedge [135, 225] degrees
    addSphere(scene, 1, polar(eye, 160.0 * kPi / 180, 30), 2);
    addSphere(scene, 2, polar(eye, -160.0 * kPi / 180, 30), 2);
    addSphere(scene, 3, polar(eye, 0.0, 30), 2);                // behind the camera
    addSphere(scene, 4, polar(eye, 120.0 * kPi / 180, 30), 2);  // just off the wedge
    addSphere(scene, 5, polar(eye, 179.9 * kPi / 180, 30), 2);  // on the seam
    addSphere(scene, 6, polar(eye, 179.9 * kPi / 180, 45), 2);  // hidden by 5
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{1, 2, 5}));
    EXPECT_EQ(vfcIds(scene), (V{1, 2, 5, 6}));
}

TEST(Oracle2d, FullTurnSeesAllAround) {
    Scene scene = test::scene2d();
    const glm::dvec3 eye{50, 50, 0};
    test::setCamera(scene, eye, {60, 57, 0}, 360.0);
    for (int i = 0; i < 8; ++i) addSphere(scene, i, polar(eye, i * kPi / 4, 20), 2);
    addSphere(scene, 8, polar(eye, 5 * kPi / 4, 40), 1);  // behind circle 5
    addSphere(scene, 9, polar(eye, 5 * kPi / 8, 40), 1);  // between two of the ring
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{0, 1, 2, 3, 4, 5, 6, 7, 9}));
    EXPECT_EQ(vfcIds(scene), (V{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
}

TEST(Oracle2d, ReportsItsCounters) {
    Scene scene = lookingRight();
    addSphere(scene, 1, {60, 50, 0}, 3);
    addSphere(scene, 2, {-60, 50, 0}, 3);  // behind the camera
    addSphere(scene, 3, {5, 2000, 0}, 3);  // beyond far
    scene.finalize();
    OracleOptions sampled;
    sampled.rays_per_turn = 16384;
    ExactOracle oracle{sampled};
    oracle.reset(scene);
    FrameResult result;
    oracle.cull(scene, cameraAt(scene, 0.0), 0.0, result);
    EXPECT_EQ(result.pvs, V{1});
    EXPECT_EQ(result.stats.get(Counter::PixelsSampled), 4096);
    EXPECT_EQ(result.stats.get(Counter::ObjectsTested), 1);
    // The exact default casts one ray per elementary interval: the circle's
    // interval widened by a margin each side, cut at its two tangents.
    ExactOracle exact;
    exact.reset(scene);
    exact.cull(scene, cameraAt(scene, 0.0), 0.0, result);
    EXPECT_EQ(result.pvs, V{1});
    EXPECT_EQ(result.stats.get(Counter::PixelsSampled), 3);
    EXPECT_EQ(result.stats.get(Counter::ObjectsTested), 1);
    EXPECT_EQ(ExactOracle::rayCount(16384, 360.0), 16384);
    EXPECT_EQ(ExactOracle::rayCount(16384, 1.0), 64);
}

// The exact default sees a circle 0.1 across at distance 90, and so does the sweep
// at 16384 rays per turn (about three rays on it); 64 rays over the wedge
// straddle it, which is the sweep's documented sampling limit.
TEST(Oracle2d, TinyFarObjectFoundAtDefaultResolution) {
    Scene scene = lookingRight();
    addSphere(scene, 1, kEye + glm::dvec3(90, 0, 0), 0.05);  // on the boundary of two coarse bins
    scene.finalize();
    EXPECT_EQ(exactIds(scene), V{1});
    OracleOptions fine;
    fine.rays_per_turn = 16384;
    EXPECT_EQ(exactIds(scene, 0.0, fine), V{1});
    OracleOptions coarse;
    coarse.rays_per_turn = 256;  // 64 rays over 90 degrees
    EXPECT_EQ(exactIds(scene, 0.0, coarse), V{});
}

}  // namespace
}  // namespace gridcull
