// A mesh's footprint (culling/oracle/mesh_footprint.h) against brute force: a
// fan of rays through every pixel square of a small image, each tested against
// every triangle. Wherever a ray meets the mesh the footprint must mark the
// pixel, no deeper than the hit.
#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "culling/oracle/mesh_footprint.h"
#include "culling/scene/ray_intersect.h"
#include "culling/scene/seeded_random.h"
#include "tests/culling/oracle/square_pixel_view.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

constexpr int kSide = 32;  // pixels of the test image, each way
constexpr int kFan = 12;   // rays per side of a pixel square, its edges included
// The brute force's own rounding: its hit depths come from another formula
// than the footprint's corner depths, so they agree to some ulps, not exactly.
constexpr double kBruteRounding = 1e-9;

// The eye at the origin looking down +z, fov 90 each way (square_pixel_view.h).
PixelView testView() {
    return test::squarePixelView(kSide);
}

const ScreenRange kWhole{0, kSide - 1};

// The least depth at which a ray of the fan through pixel (px, py) meets the
// mesh at `offset`, within [near, far]; +infinity when none does.
double fanLeastDepth(const PixelView& view, const TriangleMesh& mesh, const glm::dvec3& offset,
                     int px, int py) {
    double least = std::numeric_limits<double>::infinity();
    for (int j = 0; j < kFan; ++j)
        for (int i = 0; i < kFan; ++i) {
            const glm::dvec3 dir = view.ray(px + double(i) / (kFan - 1), py + double(j) / (kFan - 1));
            for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
                double s;
                if (!lineTriangle(view.eye, dir, mesh.vertices[mesh.indices[t]] + offset,
                                  mesh.vertices[mesh.indices[t + 1]] + offset,
                                  mesh.vertices[mesh.indices[t + 2]] + offset, s))
                    continue;
                // dir's forward component is 1, so s is the depth.
                if (s >= view.near && s <= view.far) least = std::min(least, s);
            }
        }
    return least;
}

// Open meshes of small random triangles strewn along a random segment, some
// reaching behind the near plane.
TEST(MeshFootprint, MarksEveryPixelARayMeetsNoDeeperThanTheHit) {
    const PixelView view = testView();
    SeededRandom rng(20261203);
    int hit_pixels = 0, marked_pixels = 0;
    for (int n = 0; n < 40; ++n) {
        const glm::dvec3 from{rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-0.5, 6)};
        const glm::dvec3 to{rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(0.2, 6)};
        std::vector<glm::dvec3> vertices;
        std::vector<uint32_t> indices;
        for (int t = 0; t < 30; ++t) {
            const glm::dvec3 at = from + (to - from) * rng.uniform();
            for (int k = 0; k < 3; ++k) {
                indices.push_back(uint32_t(vertices.size()));
                vertices.push_back(at + glm::dvec3(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3),
                                                   rng.uniform(-0.3, 0.3)));
            }
        }
        const auto mesh = test::finishMesh(vertices, indices, false);
        const glm::dvec3 offset{rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), 0.0};
        MeshFootprint footprint;
        ASSERT_TRUE(footprint.build(view, *mesh, offset, kWhole, kWhole)) << "mesh " << n;
        for (int py = 0; py < kSide; ++py)
            for (int px = 0; px < kSide; ++px) {
                const double brute = fanLeastDepth(view, *mesh, offset, px, py);
                const double bound = footprint.leastDepth(px, py);
                if (bound != INFINITY) ++marked_pixels;
                if (brute == INFINITY) continue;
                ++hit_pixels;
                ASSERT_LE(bound, brute + kBruteRounding * brute)
                    << "mesh " << n << " pixel " << px << ", " << py;
            }
    }
    std::printf("[ footprint ] %d pixels met by a ray, %d marked\n", hit_pixels, marked_pixels);
    EXPECT_GT(hit_pixels, 1000);
    // Rectangles around small triangles: a little more than what the rays meet.
    EXPECT_LT(marked_pixels, 3 * hit_pixels);
}

// A triangle reaching from depth 2 to behind the eye: its corners in front
// project near the image's centre, yet it shows up to the top right corner,
// where it comes near the near plane. The points where its edges cross the near
// plane bound that.
TEST(MeshFootprint, ATriangleCutByTheNearPlaneReachesWhereItsCutShows) {
    const PixelView view = testView();
    const auto mesh = test::finishMesh({{0, 0, 2}, {0.2, 0, 2}, {1, 1, -1}}, {0, 1, 2}, false);
    MeshFootprint footprint;
    ASSERT_TRUE(footprint.build(view, *mesh, {0, 0, 0}, kWhole, kWhole));
    int hit = 0;
    for (int py = 0; py < kSide; ++py)
        for (int px = 0; px < kSide; ++px) {
            const double brute = fanLeastDepth(view, *mesh, {0, 0, 0}, px, py);
            if (brute == INFINITY) continue;
            ++hit;
            EXPECT_LE(footprint.leastDepth(px, py), brute + kBruteRounding * brute)
                << "pixel " << px << ", " << py;
        }
    EXPECT_GT(hit, kSide);
}

// A thin diagonal strip marks a band, not its bounding box.
TEST(MeshFootprint, MarksFarFewerPixelsThanTheBoundingBox) {
    const PixelView view = testView();
    std::vector<glm::dvec3> vertices;
    std::vector<uint32_t> indices;
    for (int t = 0; t < 64; ++t) {
        const double x = -4.5 + 9.0 * t / 64, step = 9.0 / 64;
        for (const glm::dvec3& p : {glm::dvec3(x, x, 5), glm::dvec3(x + step, x + step, 5),
                                    glm::dvec3(x, x + 0.1, 5)}) {
            indices.push_back(uint32_t(vertices.size()));
            vertices.push_back(p);
        }
    }
    const auto mesh = test::finishMesh(vertices, indices, false);
    MeshFootprint footprint;
    ASSERT_TRUE(footprint.build(view, *mesh, {0, 0, 0}, kWhole, kWhole));
    int marked = 0;
    for (int py = 0; py < kSide; ++py)
        for (int px = 0; px < kSide; ++px) marked += footprint.leastDepth(px, py) != INFINITY;
    EXPECT_GT(marked, kSide);
    EXPECT_LT(marked, kSide * kSide / 8);
}

// The rasterizer fills the inside of a closed mesh that the near plane cuts at
// depth near, where no triangle projects: the footprint declines.
TEST(MeshFootprint, DeclinesAClosedMeshTheNearPlaneCuts) {
    const PixelView view = testView();
    const auto cube = test::cubeMesh(1.0);
    MeshFootprint footprint;
    EXPECT_FALSE(footprint.build(view, *cube, {0, 0, 0.5}, kWhole, kWhole));
    EXPECT_TRUE(footprint.build(view, *cube, {0, 0, 5}, kWhole, kWhole));
    // Open, it has no inside: built.
    const auto quad = test::quadMesh(1.0);
    EXPECT_TRUE(footprint.build(view, *quad, {0, 0, 0.1}, kWhole, kWhole));
}

// Triangles much larger than the rectangle asked for would cost their whole
// area each: past kMaxWork times the rectangle it declines.
TEST(MeshFootprint, DeclinesWhenTheTrianglesCostTooMuch) {
    const PixelView view = testView();
    std::vector<glm::dvec3> vertices;
    std::vector<uint32_t> indices;
    for (int t = 0; t <= MeshFootprint::kMaxWork; ++t)
        for (const glm::dvec3& p : {glm::dvec3(-9, -9, 5), glm::dvec3(9, -9, 5), glm::dvec3(0, 9, 5)}) {
            indices.push_back(uint32_t(vertices.size()));
            vertices.push_back(p);
        }
    const auto mesh = test::finishMesh(vertices, indices, false);
    MeshFootprint footprint;
    EXPECT_FALSE(footprint.build(view, *mesh, {0, 0, 0}, kWhole, kWhole));
    indices.resize(3 * MeshFootprint::kMaxWork);
    vertices.resize(3 * MeshFootprint::kMaxWork);
    EXPECT_TRUE(footprint.build(view, *test::finishMesh(vertices, indices, false), {0, 0, 0},
                                kWhole, kWhole));
}

}  // namespace
}  // namespace gridcull
