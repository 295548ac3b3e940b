// The ID buffer's spheres and boxes (culling/raster/id_depth_buffer.cpp) pixel by
// pixel against an independent per-pixel ray cast (raster_brute_force.h): which
// pixels a shape covers and at what depth, which shape wins where shapes
// overlap, and seeded random scenes of every shape kind (meshes included) at
// small image sizes. Meshes and the fill rule: id_depth_buffer_mesh_test.cpp.
// GRIDCULL_SEED=N replays one random scene.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "culling/raster/id_depth_buffer.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/raster/raster_brute_force.h"

namespace gridcull {
namespace {

using test::atView;
using test::TestShape;

constexpr int kWidth = test::kRasterWidth;
constexpr int kHeight = test::kRasterHeight;
using test::obliqueCamera;

// Half the image plane at depth 1: the view-space x (y) of the left/right
// (top/bottom) image border at depth z is +-kHalfX * z (+-kHalfY * z).
const double kHalfY = std::tan(glm::radians(60.0) / 2.0);
const double kHalfX = kHalfY * 1.5;

// The slopes of pixel (px, py)'s centre ray (fractional px, py: between centres).
double pixelU(double px) {
    return (2.0 * (px + 0.5) / kWidth - 1.0) * kHalfX;
}
double pixelV(double py) {
    return (1.0 - 2.0 * (py + 0.5) / kHeight) * kHalfY;
}

struct Placed {
    const char* what;
    TestShape shape;
    bool seen;  // does the reference see it at all?
};

void expectEachMatches(const Camera& camera, const std::vector<Placed>& cases) {
    for (const Placed& c : cases) {
        const test::PixelTally tally =
            test::expectShapeMatches(camera, kWidth, kHeight, c.shape, c.what);
        EXPECT_EQ(tally.covered > 0, c.seen) << c.what << ": " << tally.covered << " pixels";
        EXPECT_LE(tally.boundary, 2) << c.what;  // a designed case is not about grazing rays
    }
}

// Every pixel at depth near exactly, as a camera inside a solid must see.
void expectAllAtNear(const Camera& camera, const TestShape& shape, const char* what) {
    const std::vector<double> drawn = test::drawnAlone(camera, kWidth, kHeight, shape);
    const long long at_near = std::count(drawn.begin(), drawn.end(), camera.near);
    EXPECT_EQ(at_near, (long long)drawn.size()) << what;
}

TEST(IdDepthBufferSphere, EveryPixelMatchesTheRayCastAtSeveralPlacesAndSizes) {
    const Camera cam = obliqueCamera();
    auto sphere = [&](double x, double y, double z, double r) {
        return test::sphereShape(atView(cam, x, y, z), r);
    };
    expectEachMatches(
        cam,
        {
            {"centred", sphere(0.0, 0.0, 10.0, 2.0), true},
            // A pixel is 2 kHalfY / 32 = 0.036 wide at depth 1: radius 0.05 at
            // depth 12 (0.004) holds a centre only when placed on its ray.
            {"smaller than a pixel, on pixel (30, 20)'s ray",
             sphere(pixelU(30) * 12.0, pixelV(20) * 12.0, 12.0, 0.05), true},
            {"smaller than a pixel, between centres",
             sphere(pixelU(30.5) * 12.0, pixelV(20.5) * 12.0, 12.0, 0.05), false},
            {"large, filling most of the view", sphere(0.2, 0.1, 8.0, 6.5), true},
            {"half off the left border", sphere(-kHalfX * 10.0, 0.3, 10.0, 2.0), true},
            {"on the top right corner", sphere(kHalfX * 12.0, kHalfY * 12.0, 12.0, 2.5), true},
            {"mostly below the bottom border", sphere(0.0, -kHalfY * 10.0 - 0.5, 10.0, 1.0), true},
            {"wholly off the right border", sphere(kHalfX * 10.0 + 5.0, 0.0, 10.0, 1.0), false},
            {"cut by the far plane", sphere(0.5, 0.0, 49.0, 3.0), true},
            {"beyond far", sphere(0.0, 0.0, 56.0, 3.0), false},
            {"behind the eye", sphere(0.0, 0.0, -6.0, 2.0), false},
            {"across the eye plane, beside the eye", sphere(1.6, 0.3, 0.2, 1.2), true},
        });
}

TEST(IdDepthBufferSphere, SphereCutByTheNearPlaneShowsItsCapAtNear) {
    const Camera cam = obliqueCamera();  // near 0.5
    // Centre at depth 0.9 with radius 1: the near plane cuts a disc of radius
    // sqrt(1 - 0.4^2) = 0.917 out of it, seen at depth near; the eye (distance
    // sqrt(0.3^2 + 0.2^2 + 0.9^2) = 0.97 from the centre) stays outside.
    const TestShape shape = test::sphereShape(atView(cam, 0.3, -0.2, 0.9), 1.0);
    const test::PixelTally tally = test::expectShapeMatches(cam, kWidth, kHeight, shape, "cut");
    EXPECT_GT(tally.covered, 0);
    const std::vector<double> drawn = test::drawnAlone(cam, kWidth, kHeight, shape);
    EXPECT_GT(std::count(drawn.begin(), drawn.end(), cam.near), 20);
    // Touching the near plane from behind it: the nearest point is at depth near.
    test::expectShapeMatches(cam, kWidth, kHeight, test::sphereShape(atView(cam, 0, 0, 1.5), 1.0),
                             "touching near");
}

TEST(IdDepthBufferSphere, CameraInsideASphereSeesItAtNearEverywhere) {
    const Camera cam = obliqueCamera();
    expectAllAtNear(cam, test::sphereShape(atView(cam, 0.4, -0.3, 1.0), 3.0), "inside sphere");
}

TEST(IdDepthBufferBox, EveryPixelMatchesTheRayCastAtSeveralPlaces) {
    const Camera cam = obliqueCamera();
    auto box = [&](double x, double y, double z, const glm::dvec3& half) {
        const glm::dvec3 c = atView(cam, x, y, z);
        return test::boxShape(c - half, c + half);
    };
    expectEachMatches(
        cam, {
                 {"cube in front", box(0.0, 0.0, 10.0, {1.5, 1.5, 1.5}), true},
                 {"flat slab, seen at a slant", box(-2.0, 1.0, 14.0, {4.0, 0.1, 3.0}), true},
                 {"thin pole", box(3.0, 0.0, 9.0, {0.05, 5.0, 0.05}), true},
                 {"half off the right border", box(kHalfX * 10.0, 0.0, 10.0, {1, 2, 1}), true},
                 {"off the top border", box(0.0, kHalfY * 10.0 + 4.0, 10.0, {1, 1, 1}), false},
                 {"cut by the far plane", box(1.0, -1.0, 49.5, {2, 2, 2}), true},
                 {"behind the eye", box(0.0, 0.0, -5.0, {1, 1, 1}), false},
                 {"wall across the whole view", box(0.0, 0.0, 30.0, {60, 60, 0.5}), true},
             });
}

TEST(IdDepthBufferBox, BoxCrossingTheNearPlaneShowsItsCutAtNear) {
    const Camera cam = obliqueCamera();  // near 0.5
    // World-axis box around view (0.5, 0.3, 0.6), half-size 0.4: the camera is
    // turned by a few degrees, so its depths span 0.6 +- 0.4 * 1.07 and the near
    // plane crosses it, while its view x spans 0.5 +- 0.4 * 1.05 > 0: the eye is
    // outside it.
    const glm::dvec3 c = atView(cam, 0.5, 0.3, 0.6);
    const TestShape shape = test::boxShape(c - glm::dvec3(0.4), c + glm::dvec3(0.4));
    const test::PixelTally tally = test::expectShapeMatches(cam, kWidth, kHeight, shape, "cut");
    EXPECT_GT(tally.covered, 100);
    const std::vector<double> drawn = test::drawnAlone(cam, kWidth, kHeight, shape);
    EXPECT_GT(std::count(drawn.begin(), drawn.end(), cam.near), 20);
}

TEST(IdDepthBufferBox, CameraInsideABoxSeesItAtNearEverywhere) {
    const Camera cam = obliqueCamera();
    expectAllAtNear(
        cam,
        test::boxShape(cam.position - glm::dvec3(0.2, 3, 1), cam.position + glm::dvec3(4, 0.1, 2)),
        "inside box");
}

TEST(IdDepthBufferOverlap, TheNearerShapeWinsEachPixelInEitherDrawOrder) {
    const Camera cam = obliqueCamera();
    const glm::dvec3 box_c = atView(cam, 1.0, 0.0, 10.0);
    const std::vector<TestShape> shapes = {
        // A sphere in front of a larger one, overlapping on screen.
        test::sphereShape(atView(cam, 0.0, 0.0, 10.0), 2.0),
        test::sphereShape(atView(cam, 1.5, 0.8, 15.0), 3.5),
        // A box that cuts through the first sphere: depth order varies by pixel.
        test::boxShape(box_c - glm::dvec3(1.2, 0.6, 2.5), box_c + glm::dvec3(1.2, 0.6, 2.5)),
    };
    for (const std::vector<int>& order :
         std::vector<std::vector<int>>{{0, 1, 2}, {2, 1, 0}, {1, 2, 0}}) {
        const int compared = test::expectSceneMatches(cam, kWidth, kHeight, shapes, order,
                                                      "order " + std::to_string(order[0]));
        EXPECT_GE(compared, kWidth * kHeight - 4);
    }
    // All three win some pixels: check it through the visible set.
    IdDepthBuffer buffer;
    buffer.resize(kWidth, kHeight);
    buffer.begin(cam);
    for (int k = 0; k < 3; ++k) test::drawShape(buffer, k, shapes[size_t(k)]);
    std::vector<char> seen(3, 0);
    buffer.markVisible(seen);
    EXPECT_EQ(seen, std::vector<char>({1, 1, 1}));
}

TEST(IdDepthBufferOverlap, AShapeHiddenBehindAnotherIsNotVisible) {
    const Camera cam = obliqueCamera();
    const glm::dvec3 wall = atView(cam, 0.0, 0.0, 8.0);
    const std::vector<TestShape> shapes = {
        test::sphereShape(atView(cam, 0.2, 0.1, 20.0), 1.5),
        test::boxShape(wall - glm::dvec3(6, 6, 0.3), wall + glm::dvec3(6, 6, 0.3)),
    };
    test::expectSceneMatches(cam, kWidth, kHeight, shapes, {0, 1}, "hidden");
    IdDepthBuffer buffer;
    buffer.resize(kWidth, kHeight);
    buffer.begin(cam);
    for (int k : {0, 1}) test::drawShape(buffer, k, shapes[size_t(k)]);
    std::vector<char> seen(2, 0);
    buffer.markVisible(seen);
    EXPECT_EQ(seen, std::vector<char>({0, 1}));
}

TEST(IdDepthBufferOverlap, OfTwoShapesAtTheSameDepthTheFirstDrawnKeepsThePixel) {
    // The header's tie rule (strict "<"): the same sphere drawn as 1 then as 0.
    const Camera cam = obliqueCamera();
    const glm::dvec3 c = atView(cam, 0.0, 0.0, 10.0);
    IdDepthBuffer buffer;
    buffer.resize(kWidth, kHeight);
    buffer.begin(cam);
    EXPECT_TRUE(buffer.drawSphere(1, c, 2.0));
    EXPECT_TRUE(buffer.drawSphere(0, c, 2.0));
    std::vector<char> seen(2, 0);
    buffer.markVisible(seen);
    EXPECT_EQ(seen, std::vector<char>({0, 1}));
}

// ---- Seeded random scenes ----

struct RandomView {
    Camera camera;
    int width = 0, height = 0;
    std::vector<TestShape> shapes;
};

RandomView randomView(uint64_t seed) {
    SeededRandom rng(seed);
    RandomView view;
    Camera& cam = view.camera;
    cam.position = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
    cam.target = cam.position + randomDirection(rng, 3) * 5.0;
    cam.fov_deg = rng.uniform(20.0, 120.0);
    cam.aspect = rng.uniform(0.5, 2.5);  // on purpose not width / height
    cam.near = rng.uniform() < 0.5 ? 0.1 : rng.uniform(0.3, 3.0);
    cam.far = rng.uniform(20.0, 80.0);
    view.width = 24 + int(rng.below(41));   // 24..64
    view.height = 16 + int(rng.below(33));  // 16..48
    const double tan_y = std::tan(glm::radians(cam.fov_deg) / 2.0);
    const double tan_x = tan_y * cam.aspect;
    const int count = 2 + int(rng.below(6));
    for (int k = 0; k < count; ++k) {
        // Mostly in the view, some across the near plane or the borders, some
        // behind the eye or beyond far.
        const double z = rng.uniform(-3.0, cam.far * 1.1);
        const double scale = std::max(std::abs(z), 1.0);
        glm::dvec3 c = atView(cam, rng.uniform(-1.3, 1.3) * tan_x * scale,
                              rng.uniform(-1.3, 1.3) * tan_y * scale, z);
        double size = rng.uniform(0.03, 0.3) * scale;
        if (rng.uniform() < 0.08) {  // around the eye
            c = cam.position +
                glm::dvec3(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5));
            size = rng.uniform(1.0, 3.0);
        }
        const double kind = rng.uniform();
        auto around = [&] {
            return glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * size;
        };
        if (kind < 0.3) {
            view.shapes.push_back(test::sphereShape(c, size));
        } else if (kind < 0.6) {
            const glm::dvec3 half = glm::abs(around()) + 0.2 * size;
            view.shapes.push_back(test::boxShape(c - half, c + half));
        } else if (kind < 0.75) {
            view.shapes.push_back(test::meshShape(
                test::boxSurfaceMesh(glm::abs(around()) + 0.2 * size, rng.uniform() < 0.8), c));
        } else if (kind < 0.9) {
            view.shapes.push_back(
                test::meshShape(test::tetrahedronOn(around(), around(), around(), around()), c));
        } else {
            view.shapes.push_back(
                test::meshShape(test::triangleOn(around(), around(), around()), c));
        }
    }
    return view;
}

// A lower bound of a shape's depth, for the front-to-back order the oracle draws in.
double nearestDepth(const Camera& cam, const TestShape& s) {
    const glm::dvec3 fwd = cam.forward();
    double z = std::numeric_limits<double>::infinity();
    if (s.kind == TestShape::Kind::Sphere) return glm::dot(s.center - cam.position, fwd) - s.radius;
    if (s.kind == TestShape::Kind::Box) {
        for (int i = 0; i < 8; ++i) z = std::min(z, glm::dot(s.box.corner(i) - cam.position, fwd));
        return z;
    }
    for (const glm::dvec3& v : s.mesh->vertices)
        z = std::min(z, glm::dot(v + s.offset - cam.position, fwd));
    return z;
}

TEST(IdDepthBufferRandom, EveryPixelMatchesTheRayCastOnSeededRandomScenes) {
    long long compared = 0, covered = 0, boundary = 0, scene_pixels = 0;
    double worst = 0.0;
    for (uint64_t seed : test::seedsToRun(1, 48)) {
        test::withSeed(seed, [&] {
            const RandomView view = randomView(seed);
            // Each shape alone: its coverage and depths.
            for (size_t k = 0; k < view.shapes.size(); ++k) {
                const test::PixelTally tally =
                    test::expectShapeMatches(view.camera, view.width, view.height, view.shapes[k],
                                             "shape " + std::to_string(k));
                compared += tally.compared;
                covered += tally.covered;
                boundary += tally.boundary;
                worst = std::max(worst, tally.worst_depth_error);
            }
            // All together, as generated and front to back: the winners' depths.
            std::vector<int> order(view.shapes.size());
            for (size_t k = 0; k < order.size(); ++k) order[k] = int(k);
            scene_pixels += test::expectSceneMatches(view.camera, view.width, view.height,
                                                     view.shapes, order, "as generated");
            std::sort(order.begin(), order.end(), [&](int a, int b) {
                return nearestDepth(view.camera, view.shapes[size_t(a)]) <
                       nearestDepth(view.camera, view.shapes[size_t(b)]);
            });
            test::expectSceneMatches(view.camera, view.width, view.height, view.shapes, order,
                                     "front to back");
        });
    }
    if (!test::singleSeedRun()) {
        std::printf(
            "[raster brute force] %lld shape pixels compared (%lld covered, %lld grazing "
            "skipped, worst relative depth difference %.1e), %lld scene pixels compared\n",
            compared, covered, boundary, worst, scene_pixels);
        EXPECT_GT(covered, 10000);                 // the scenes are not mostly empty
        EXPECT_LT(boundary, compared / 1000 + 1);  // and grazing rays are rare
    }
}

}  // namespace
}  // namespace gridcull
