// ImagePlaneDraw (ui/image_plane_draw.h): image pixels land on the plane across
// the culling camera's frustum, so they project back through that camera onto
// the same places of its image; World-space primitives pass through unchanged.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "ui/image_plane_draw.h"

namespace gridcull {
namespace {

// Where World point p falls in the camera's normalized device coordinates.
glm::dvec2 ndcOf(const Camera& camera, const glm::dvec3& p) {
    const glm::dvec4 clip = camera.projectionMatrix() * camera.viewMatrix() * glm::dvec4(p, 1.0);
    return {clip.x / clip.w, clip.y / clip.w};
}

Camera tiltedCamera() {
    Camera camera;
    camera.position = {3.0, 2.0, -4.0};
    camera.target = {10.0, 5.0, 20.0};
    camera.fov_deg = 50.0;
    camera.aspect = 4.0 / 3.0;
    camera.near = 0.5;
    camera.far = 300.0;
    return camera;
}

// The image's corners and centre project to the image's corners and centre,
// at the chosen distance along the view direction.
TEST(ImagePlaneDraw, ImagePixelsProjectBackToTheirPlaceInTheImage) {
    const Camera camera = tiltedCamera();
    DebugDrawBatch batch;
    constexpr int kW = 640, kH = 480;
    const ImagePlaneDraw plane(batch, camera, 12.0, kW, kH);
    constexpr double kNdc = 1e-9;  // floating point only
    const glm::dvec2 top_left = ndcOf(camera, plane.toWorld(0.0, 0.0));
    EXPECT_NEAR(top_left.x, -1.0, kNdc);
    EXPECT_NEAR(top_left.y, 1.0, kNdc);
    const glm::dvec2 bottom_right = ndcOf(camera, plane.toWorld(kW, kH));
    EXPECT_NEAR(bottom_right.x, 1.0, kNdc);
    EXPECT_NEAR(bottom_right.y, -1.0, kNdc);
    const glm::dvec2 quarter = ndcOf(camera, plane.toWorld(0.25 * kW, 0.75 * kH));
    EXPECT_NEAR(quarter.x, -0.5, kNdc);
    EXPECT_NEAR(quarter.y, -0.5, kNdc);
    const glm::dvec3 centre = plane.toWorld(0.5 * kW, 0.5 * kH);
    EXPECT_NEAR(glm::dot(centre - camera.position, camera.forward()), 12.0, 1e-9);
}

TEST(ImagePlaneDraw, ViewPrimitivesBecomeWorldOnesAndWorldOnesPassThrough) {
    const Camera camera = tiltedCamera();
    DebugDrawBatch batch;
    ImagePlaneDraw plane(batch, camera, 5.0, 100, 100);
    plane.fillRect(DrawSpace::View, 10, 10, 20, 20, Paint{Swatch::Orange});
    plane.line(DrawSpace::World, {1, 2, 3}, {4, 5, 6}, Paint{}, kBoldLine);
    EXPECT_TRUE(batch.layer(DrawSpace::View).fill.empty());
    const auto& world = batch.layer(DrawSpace::World);
    ASSERT_EQ(world.fill.size(), 6u);  // the rectangle's two triangles
    const glm::dvec3 corner = plane.toWorld(10, 10);
    EXPECT_NEAR(glm::length(glm::dvec3(world.fill[0].position) - corner), 0.0, 1e-5);
    size_t segments = 0;
    for (const auto& set : world.lines) segments += set.vertices.size() / 2;
    EXPECT_EQ(segments, 1u);
}

TEST(ImagePlaneDraw, ThePlaneStandsATenthOfTheWorldAwayAndPastTheNearPlane) {
    Camera camera = tiltedCamera();
    EXPECT_DOUBLE_EQ(imagePlaneDistance(camera, {300.0, 0.0, 400.0}), 50.0);
    camera.near = 40.0;
    EXPECT_DOUBLE_EQ(imagePlaneDistance(camera, {300.0, 0.0, 400.0}), 80.0);
    const ImageFrame frame = imagePixelFrame(64, 32);
    EXPECT_EQ(frame.pixelsToView(0, 0, 63, 31).x1, 64.0);
}

}  // namespace
}  // namespace gridcull
