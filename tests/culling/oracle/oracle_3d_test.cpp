// The 3D exact oracle on hand-made scenes whose visible set is known by
// construction. Unless a test says otherwise: world [0, 100]^3 in 10-unit voxels,
// camera at (50, 50, 5) looking down +z, fov 60, aspect 16:9, near 0.1, far 1000,
// oracle at its default 1024 x 576.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

#include "culling/oracle/exact_oracle.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

using test::addBox;
using test::addMesh;
using test::addSphere;
using V = std::vector<int>;

const glm::dvec3 kEye{50, 50, 5};
const glm::dvec3 kAhead{50, 50, 100};

V exactIds(const Scene& scene, double t = 0.0) {
    ExactOracle oracle;
    return test::cullIds(oracle, scene, t);
}

V vfcIds(const Scene& scene, double t = 0.0) {
    auto vfc = test::makeOrDie("vfc");
    return test::cullIds(*vfc, scene, t);
}

Scene lookingAhead() {
    Scene scene = test::scene3d();
    test::setCamera(scene, kEye, kAhead, 60.0);
    return scene;
}

TEST(Oracle3d, WallHidesTheObjectBehindItNotTheOneBeside) {
    Scene scene = lookingAhead();
    addBox(scene, 1, {30, 30, 40}, {70, 70, 42});
    addSphere(scene, 2, {50, 50, 60}, 3);  // straight behind the wall
    addSphere(scene, 3, {95, 50, 60}, 3);  // beside it, still in the frustum
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{1, 3}));
    EXPECT_EQ(vfcIds(scene), (V{1, 2, 3}));
}

TEST(Oracle3d, SeesThroughAGapNarrowerThanOneVoxel) {
    Scene scene = lookingAhead();
    ASSERT_DOUBLE_EQ(scene.grid.voxelSize().x, 10.0);
    // Two walls leave a slit 2 units wide (a fifth of a voxel) at x = 49..51.
    addBox(scene, 1, {0, 0, 40}, {49, 100, 42});
    addBox(scene, 2, {51, 0, 40}, {100, 100, 42});
    addSphere(scene, 3, {50, 50, 80}, 1);  // seen only through the slit
    addSphere(scene, 4, {20, 50, 80}, 3);  // behind the wall, away from the slit
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{1, 2, 3}));
}

// Places spheres and boxes against each side plane of the frustum: a sphere that
// reaches 0.3 units (several pixels) into the frustum is seen, one 0.01 units
// outside is not, and neither is a box whose nearest corner is 0.01 outside.
TEST(Oracle3d, ObjectsGrazingTheFrustumSides) {
    Scene base = lookingAhead();
    const Camera camera = cameraAt(base, 0.0);
    glm::dvec3 right, up, fwd;
    camera.basis(right, up, fwd);
    const double tan_y = std::tan(glm::radians(camera.fov_deg) / 2);
    const double tan_x = tan_y * camera.aspect;
    const double depth = 50.0, r = 1.0;
    struct Side {
        glm::dvec3 axis;
        double tan;
        int plane;
    };
    const Side sides[] = {{-right, tan_x, 0}, {right, tan_x, 1}, {-up, tan_y, 2}, {up, tan_y, 3}};
    for (const Side& side : sides) {
        SCOPED_TRACE(side.plane);
        // Signed distance of a centre at lateral offset x from the plane is
        // (depth * tan - x) / sqrt(1 + tan^2).
        auto centreAt = [&](double distance_in) {
            const double x = depth * side.tan - distance_in * std::sqrt(1 + side.tan * side.tan);
            return kEye + fwd * depth + side.axis * x;
        };
        Scene scene = base;
        addSphere(scene, 1, centreAt(-r + 0.3), r);   // reaches 0.3 inside
        addSphere(scene, 2, centreAt(-r - 0.01), r);  // 0.01 outside
        // A box wholly outside, its most inward corner 0.01 from the plane.
        const glm::dvec4 plane = camera.frustumPlanes()[size_t(side.plane)];
        const glm::dvec3 n{plane.x, plane.y, plane.z};
        const glm::dvec3 q = centreAt(0.0) - n * 0.01;
        glm::dvec3 lo, hi;
        for (int i = 0; i < 3; ++i) {
            lo[i] = n[i] >= 0.0 ? q[i] - 2.0 : q[i];
            hi[i] = n[i] >= 0.0 ? q[i] : q[i] + 2.0;
        }
        addBox(scene, 3, lo, hi);
        scene.finalize();
        EXPECT_EQ(exactIds(scene), (V{1}));
        const V vfc = vfcIds(scene);
        EXPECT_TRUE(std::count(vfc.begin(), vfc.end(), 1));
        EXPECT_FALSE(std::count(vfc.begin(), vfc.end(), 3));
    }
}

TEST(Oracle3d, ObjectsGrazingTheFarAndNearPlanes) {
    Scene scene = test::scene3d();
    test::setCamera(scene, kEye, kAhead, 60.0, 0.5, 60.0);
    addSphere(scene, 1, kEye + glm::dvec3(0, 0, 60 + 2 - 0.2), 2);          // 0.2 inside far
    addSphere(scene, 2, kEye + glm::dvec3(10, 0, 60 + 2 + 0.01), 2);        // 0.01 beyond far
    addSphere(scene, 3, kEye + glm::dvec3(0, 0, 0.25), 0.1);                // before near
    addSphere(scene, 4, kEye + glm::dvec3(0.4, 0, 0.5 + 0.2 - 0.05), 0.2);  // crosses near
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{1, 4}));
    EXPECT_EQ(vfcIds(scene), (V{1, 4}));
}

// Objects beside the camera that cross the eye plane show only their part beyond
// the near plane, at the edge of the screen; they still hide what is behind it.
TEST(Oracle3d, ObjectsCrossingTheEyePlane) {
    for (int shape = 0; shape < 2; ++shape) {
        SCOPED_TRACE(shape == 0 ? "sphere" : "box");
        Scene scene = lookingAhead();
        // The camera looks down +z with right = -x, so x < 50 is the right side.
        if (shape == 0)
            addSphere(scene, 1, {47, 50, 5}, 2.5);
        else
            addBox(scene, 1, {44.5, 40, 0}, {49.5, 60, 8});
        addSphere(scene, 2, {50 - 1.02 * 60, 50, 65}, 3);  // behind it, at the right edge
        addSphere(scene, 3, {50 + 0.9 * 60, 50, 65}, 3);   // at the left edge
        scene.finalize();
        EXPECT_EQ(exactIds(scene), (V{1, 3}));
        EXPECT_EQ(vfcIds(scene), (V{1, 2, 3}));
    }
}

TEST(Oracle3d, CameraInsideASphereSeesOnlyIt) {
    Scene scene = lookingAhead();
    test::setCamera(scene, {50, 50, 50}, {50, 50, 100}, 60.0);
    addSphere(scene, 1, {50, 50, 52}, 5);
    addSphere(scene, 2, {50, 50, 80}, 3);
    addBox(scene, 3, {0, 0, 90}, {100, 100, 95});
    addSphere(scene, 4, {51, 50, 53}, 1);  // inside the first sphere too
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{1}));
    EXPECT_EQ(vfcIds(scene), (V{1, 2, 3, 4}));
}

TEST(Oracle3d, CameraInsideABoxSeesOnlyIt) {
    Scene scene = lookingAhead();
    addBox(scene, 1, {45, 45, 4}, {55, 55, 5.05});  // ends before the near plane
    addSphere(scene, 2, {50, 50, 80}, 3);
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{1}));
    const V vfc = vfcIds(scene);
    EXPECT_TRUE(std::count(vfc.begin(), vfc.end(), 1));
}

TEST(Oracle3d, CameraInsideAClosedMeshSeesOnlyIt) {
    Scene scene = lookingAhead();
    addMesh(scene, 1, kEye + glm::dvec3(0, 0, 1), test::cubeMesh(4));
    addSphere(scene, 2, {50, 50, 80}, 3);
    addSphere(scene, 3, kEye + glm::dvec3(1, 0, 2), 0.5);  // inside the cube
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{1}));
}

// The near plane cuts a solid's front off: the camera stands 0.05 in front of it
// with near = 0.1. The solid still hides what is inside and behind it.
TEST(Oracle3d, NearPlaneInsideASolidStillOccludes) {
    for (int shape = 0; shape < 2; ++shape) {
        SCOPED_TRACE(shape == 0 ? "box" : "closed mesh");
        Scene scene = lookingAhead();
        if (shape == 0)
            addBox(scene, 1, {40, 40, 5.05}, {60, 60, 25.05});
        else
            addMesh(scene, 1, {50, 50, 15.05}, test::cubeMesh(10));
        addSphere(scene, 2, {50, 50, 15}, 2);  // inside the solid
        addSphere(scene, 3, {50, 50, 60}, 2);  // behind it
        scene.finalize();
        EXPECT_EQ(exactIds(scene), (V{1}));
    }
}

TEST(Oracle3d, EmptyView) {
    Scene scene = test::scene3d();
    test::setCamera(scene, kEye, {50, 50, -100}, 60.0);  // looking out of the world
    addSphere(scene, 1, {50, 50, 60}, 3);
    addBox(scene, 2, {0, 0, 20}, {100, 100, 30});
    addMesh(scene, 3, {50, 50, 40}, test::cubeMesh(5));
    scene.finalize();
    EXPECT_EQ(exactIds(scene), V{});
    EXPECT_EQ(vfcIds(scene), V{});
    Scene far_away = lookingAhead();
    far_away.camera.far = 30.0;
    addSphere(far_away, 1, {50, 50, 60}, 3);
    far_away.finalize();
    EXPECT_EQ(exactIds(far_away), V{});
}

TEST(Oracle3d, ClosedMeshesOccludeASphere) {
    for (int shape = 0; shape < 2; ++shape) {
        SCOPED_TRACE(shape == 0 ? "cube" : "tetrahedron");
        Scene scene = lookingAhead();
        addMesh(scene, 1, {50, 50, 40},
                shape == 0 ? test::cubeMesh(10) : test::tetrahedronMesh(12));
        addSphere(scene, 2, {50, 50, 70}, 3);  // behind the mesh
        addSphere(scene, 3, {90, 50, 70}, 3);  // beside it
        scene.finalize();
        EXPECT_EQ(exactIds(scene), (V{1, 3}));
        EXPECT_EQ(vfcIds(scene), (V{1, 2, 3}));
    }
}

TEST(Oracle3d, OpenMeshOccludesWithItsTriangles) {
    Scene scene = lookingAhead();
    addMesh(scene, 1, {50, 50, 30}, test::quadMesh(8));  // facing the camera
    addSphere(scene, 2, {50, 50, 60}, 3);
    // Seen edge-on a quad hides nothing: its plane y = 50 contains the eye, so it
    // projects onto a line between two pixel rows.
    auto edge_on = test::finishMesh({{-8, 0, -8}, {8, 0, -8}, {8, 0, 8}, {-8, 0, 8}},
                                    {0, 1, 2, 0, 2, 3}, false);
    addMesh(scene, 3, {80, 50, 40}, edge_on);
    addSphere(scene, 4, {80, 50, 60}, 3);
    scene.finalize();
    const V ids = exactIds(scene);
    EXPECT_EQ(ids, (V{1, 4}));
}

TEST(Oracle3d, MovingMeshUncoversTheSphere) {
    Scene scene = lookingAhead();
    addMesh(scene, 1, {50, 50, 40}, test::cubeMesh(10));
    scene.objects.back().motion.kind = MotionKind::Keyframes;
    scene.objects.back().motion.keys = {{0.0, {50, 50, 40}}, {1.0, {85, 50, 40}}};
    addSphere(scene, 2, {50, 50, 70}, 3);
    scene.finalize();
    EXPECT_EQ(exactIds(scene, 0.0), (V{1}));
    EXPECT_EQ(exactIds(scene, 1.0), (V{1, 2}));
}

TEST(Oracle3d, ReportsItsCountersAndSize) {
    Scene scene = lookingAhead();
    addSphere(scene, 1, {50, 50, 60}, 3);
    addSphere(scene, 2, {50, 50, -60}, 3);  // behind the camera: rejected whole
    scene.finalize();
    ExactOracle oracle;
    oracle.reset(scene);
    FrameResult result;
    timedCull(oracle, scene, cameraAt(scene, 0.0), 0.0, result);
    EXPECT_EQ(result.pvs, V{1});
    EXPECT_EQ(result.stats.get(Counter::PixelsSampled), 1024 * 576);
    EXPECT_EQ(result.stats.get(Counter::ObjectsTested), 1);
    EXPECT_GE(result.stats.cull_ms, 0.0);
    int w, h;
    ExactOracle::imageSize(1024, 0.5, w, h);
    EXPECT_EQ(w, 512);
    EXPECT_EQ(h, 1024);
}

// The default resolution resolves a far object about 2.5 pixels across; a coarse
// one misses it, which is the sampling limit the header documents.
TEST(Oracle3d, TinyFarObjectFoundAtDefaultResolution) {
    Scene scene = lookingAhead();
    test::setCamera(scene, {50, 50, 0}, {50, 50, 100}, 60.0);
    // One pixel spans 2 tan(30 deg) / 576 = 0.002 per unit depth: r = 0.25 at
    // depth 100 is 2.5 pixels across, wherever it falls on the pixel grid.
    addSphere(scene, 1, {50.37, 49.81, 100}, 0.25);
    scene.finalize();
    EXPECT_EQ(exactIds(scene), V{1});
    OracleOptions coarse;
    coarse.resolution = 16;
    ExactOracle low{coarse};
    EXPECT_EQ(test::cullIds(low, scene), V{});
}

}  // namespace
}  // namespace gridcull
