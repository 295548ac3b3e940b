// 2D hover picking (app/hover_pick.h): the shape under the mouse, with the
// renderer's layering deciding between overlapping shapes.
#include "app/hover_pick.h"

#include <gtest/gtest.h>

namespace gridcull {
namespace {

Scene twoDScene() {
    Scene scene;
    scene.dimensions = 2;
    SceneObject circle;
    circle.id = 10;
    circle.shape = ShapeKind::Sphere;
    circle.center = {5, 5, 0};
    circle.radius = 2;
    circle.anchor = circle.center;
    circle.bounds = {{3, 3, 0}, {7, 7, 0}};
    SceneObject box;
    box.id = 11;
    box.shape = ShapeKind::Box;
    box.box = {{4, 4, 0}, {10, 6, 0}};
    box.bounds = box.box;
    box.anchor = box.box.center();
    SceneObject ell;  // an L: concave, so a bounds test would be wrong in its notch
    ell.id = 12;
    ell.shape = ShapeKind::Polygon;
    ell.points = {{20, 0, 0}, {26, 0, 0}, {26, 2, 0}, {22, 2, 0}, {22, 6, 0}, {20, 6, 0}};
    ell.bounds = {{20, 0, 0}, {26, 6, 0}};
    ell.anchor = ell.bounds.center();
    scene.objects = {circle, box, ell};
    scene.finalize();
    return scene;
}

TEST(HoverPick, PointInPolygonHandlesConcaveNotch) {
    const Scene scene = twoDScene();
    const auto& l = scene.objects[2].points;
    EXPECT_TRUE(pointInPolygon(l, glm::dvec3(0.0), 21, 5));
    EXPECT_TRUE(pointInPolygon(l, glm::dvec3(0.0), 25, 1));
    EXPECT_FALSE(pointInPolygon(l, glm::dvec3(0.0), 24, 4));  // the notch
    EXPECT_TRUE(pointInPolygon(l, glm::dvec3(4.0, 0.0, 0.0), 28, 1));  // moved by 4
}

TEST(HoverPick, PicksTheShapeDrawnOnTop) {
    const Scene scene = twoDScene();
    std::vector<ObjectState> states = {ObjectState::Culled, ObjectState::Visible,
                                       ObjectState::Culled};
    EXPECT_EQ(pickObject2d(scene, 0.0, {3.5, 5, 0}, states), 0);   // circle only
    EXPECT_EQ(pickObject2d(scene, 0.0, {5, 5, 0}, states), 1);     // both: visible box on top
    states[0] = ObjectState::FalseCulled;
    EXPECT_EQ(pickObject2d(scene, 0.0, {5, 5, 0}, states), 0);     // a false cull wins
    EXPECT_EQ(pickObject2d(scene, 0.0, {24, 4, 0}, states), -1);   // the L's notch
    EXPECT_EQ(pickObject2d(scene, 0.0, {21, 5, 0}, states), 2);
    const HoverInfo info = describeObject(scene, 2, 0.0, states, 0.0);
    EXPECT_EQ(info.id, 12);
    EXPECT_EQ(info.shape, ShapeKind::Polygon);
    EXPECT_EQ(info.state, ObjectState::Culled);
    EXPECT_EQ(describeObject(scene, -1, 0.0, states, 0.0).id, -1);
}

}  // namespace
}  // namespace gridcull
