#include "culling/scene/camera.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace gridcull {
namespace {

Scene sceneWithPath() {
    Scene scene;
    scene.dimensions = 3;
    scene.camera.fov_deg = 90;
    scene.camera.aspect = 2.0;
    scene.camera.near = 1;
    scene.camera.far = 100;
    scene.camera.path = {{1.0, {0, 0, 0}, {0, 0, 10}, {0, 1, 0}},
                         {3.0, {10, 0, 0}, {10, 0, 10}, {0, 1, 0}}};
    return scene;
}

bool insideAll(const std::array<glm::dvec4, 6>& planes, const glm::dvec3& p) {
    for (const auto& pl : planes)
        if (glm::dot(glm::dvec3(pl), p) + pl.w < -1e-9) return false;
    return true;
}

TEST(Camera, PathIsHeldOutsideItsKeysAndLinearBetween) {
    const Scene scene = sceneWithPath();
    EXPECT_EQ(cameraAt(scene, 0.0).position, glm::dvec3(0, 0, 0));
    EXPECT_EQ(cameraAt(scene, 2.0).position, glm::dvec3(5, 0, 0));
    EXPECT_EQ(cameraAt(scene, 2.0).target, glm::dvec3(5, 0, 10));
    EXPECT_EQ(cameraAt(scene, 99.0).position, glm::dvec3(10, 0, 0));
}

TEST(Camera, FrustumPlanesBoundTheView) {
    const Camera cam = cameraAt(sceneWithPath(), 0.0);  // at origin looking +z
    const auto planes = cam.frustumPlanes();
    EXPECT_TRUE(insideAll(planes, {0, 0, 50}));
    EXPECT_FALSE(insideAll(planes, {0, 0, 0.5}));    // before near
    EXPECT_FALSE(insideAll(planes, {0, 0, 100.5}));  // past far
    // Vertical half-angle 45 degrees; horizontal tan = aspect * tan(45) = 2.
    EXPECT_TRUE(insideAll(planes, {0, 9.9, 10}));
    EXPECT_FALSE(insideAll(planes, {0, 10.1, 10}));
    EXPECT_TRUE(insideAll(planes, {19.9, 0, 10}));
    EXPECT_FALSE(insideAll(planes, {-20.1, 0, 10}));
}

TEST(Camera, LookingAlongUpStillHasABasis) {
    Camera cam;
    cam.position = {0, 0, 0};
    cam.target = {0, 5, 0};
    cam.up = {0, 1, 0};
    glm::dvec3 r, u, f;
    cam.basis(r, u, f);
    EXPECT_NEAR(glm::length(r), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(r, f), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(u, f), 0.0, 1e-12);
    for (const auto& pl : cam.frustumPlanes()) EXPECT_TRUE(std::isfinite(pl.w));
}

TEST(Camera, TwoDimensionalCameraStaysInThePlane) {
    Scene scene;
    scene.dimensions = 2;
    scene.camera.path = {{0.0, {1, 2, 7}, {3, 4, 9}, {0, 1, 0}}};
    const Camera cam = cameraAt(scene, 0.5);
    EXPECT_EQ(cam.position, glm::dvec3(1, 2, 0));
    EXPECT_EQ(cam.target, glm::dvec3(3, 4, 0));
    EXPECT_EQ(cam.dimensions, 2);
}

}  // namespace
}  // namespace gridcull
