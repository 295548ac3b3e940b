// The box fast path of the shared rasterizer (IdDepthBuffer::forBoxHits in
// culling/raster/id_depth_buffer.cpp): its slab test takes 1 / dir[a] from
// per-frame row or column tables wherever the camera makes a direction component
// depend on the row alone or the column alone (a level camera: x and z by
// column, y by row), and divides per pixel elsewhere. Its promise is to give
// every pixel the answer and the depth of the plain per-pixel slab test
// (lineBox + solidEntry of culling/scene/ray_intersect.h) bit for bit, so the
// comparison here has no tolerance: depths must be equal as doubles.
//
// Cameras: level ones (forward.y exactly 0) at random headings, ones looking
// exactly along a world axis with odd image sides (so one column and one row
// have a zero direction component, the tables' 1 / 0 case) and with even ones
// (one axis by column, two by row, no zero), and oblique ones (every axis
// divided per pixel). Boxes: in view, across the image borders,
// across the near plane, across the eye plane, behind the eye, containing the
// eye. Each box is drawn alone, then behind or in front of a second box (the
// depth test and the tile skipping), and boxPassesDepthTest is checked against
// whether drawBox changed any pixel. The independent brute-force check of the
// slab test itself is id_depth_buffer_test.cpp. GRIDCULL_SEED=N replays one seed.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "culling/raster/id_depth_buffer.h"
#include "culling/scene/ray_intersect.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/raster/raster_brute_force.h"

namespace gridcull {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The plain per-pixel slab test at the documented pixel centres, in the
// arithmetic the buffer documents (u and v per column and row, the direction
// (forward + v up) + u right): the depth a box alone leaves in pixel (px, py).
double slabDepth(const Camera& camera, int width, int height, const Aabb& box, int px, int py) {
    glm::dvec3 right, up, forward;
    camera.basis(right, up, forward);
    if (box.contains(camera.position)) return camera.near;
    const double tan_y = std::tan(glm::radians(camera.fov_deg) * 0.5);
    const double tan_x = tan_y * camera.aspect;
    const double u = (2.0 * (px + 0.5) / width - 1.0) * tan_x;
    const double v = (1.0 - 2.0 * (py + 0.5) / height) * tan_y;
    const glm::dvec3 dir = (forward + v * up) + u * right;
    double s0, s1, s;
    if (!lineBox(camera.position, dir, box, s0, s1)) return kInf;
    if (!solidEntry(s0, s1, camera.near, camera.far, s)) return kInf;
    return s;
}

struct BoxView {
    Camera camera;
    int width = 0, height = 0;
    std::vector<Aabb> boxes;
};

// kind 0: level, 1: along a world axis (odd sides), 2: oblique, 3: along a
// world axis (even sides).
BoxView randomBoxView(uint64_t seed, int kind) {
    SeededRandom rng(seed);
    BoxView view;
    Camera& cam = view.camera;
    cam.position = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
    if (kind == 0) {
        const double heading = rng.uniform(0.0, 6.283185307179586);
        cam.target = cam.position + glm::dvec3(5.0 * std::cos(heading), 0.0, 5.0 * std::sin(heading));
    } else if (kind == 1 || kind == 3) {
        const int axis = int(rng.below(2)) * 2;  // x or z: up stays world y
        glm::dvec3 d(0.0);
        d[axis] = rng.uniform() < 0.5 ? -5.0 : 5.0;
        cam.target = cam.position + d;
    } else {
        cam.target = cam.position + glm::dvec3(rng.uniform(-5, 5), rng.uniform(-5, 5),
                                               rng.uniform(-5, 5));
    }
    cam.fov_deg = rng.uniform(20.0, 120.0);
    cam.aspect = rng.uniform(0.5, 2.5);
    cam.near = rng.uniform() < 0.5 ? 0.1 : rng.uniform(0.3, 3.0);
    cam.far = rng.uniform(20.0, 80.0);
    view.width = 24 + int(rng.below(41));
    view.height = 16 + int(rng.below(33));
    if (kind == 1) {  // odd: the middle column and row have u = 0, v = 0
        view.width |= 1;
        view.height |= 1;
    }
    if (kind == 3) {  // even: no pixel centre at u = 0 or v = 0
        view.width &= ~1;
        view.height &= ~1;
    }
    const double tan_y = std::tan(glm::radians(cam.fov_deg) / 2.0);
    const double tan_x = tan_y * cam.aspect;
    for (int k = 0; k < 6; ++k) {
        const double place = rng.uniform();
        double z = rng.uniform(0.5, cam.far * 1.1);
        if (place < 0.2) z = cam.near + rng.uniform(-0.5, 0.5);  // across the near plane
        if (place >= 0.2 && place < 0.35) z = rng.uniform(-1.0, 1.0);  // across the eye plane
        if (place >= 0.35 && place < 0.45) z = rng.uniform(-6.0, -1.0);  // behind the eye
        const double scale = std::max(std::abs(z), 1.0);
        glm::dvec3 c = test::atView(cam, rng.uniform(-1.3, 1.3) * tan_x * scale,
                                    rng.uniform(-1.3, 1.3) * tan_y * scale, z);
        glm::dvec3 half(rng.uniform(0.05, 0.6), rng.uniform(0.05, 0.6), rng.uniform(0.05, 0.6));
        half *= scale;
        if (place >= 0.95) {  // around the eye
            c = cam.position + glm::dvec3(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3),
                                          rng.uniform(-0.3, 0.3));
            half = glm::dvec3(rng.uniform(0.5, 2.0), rng.uniform(0.5, 2.0), rng.uniform(0.5, 2.0));
        }
        view.boxes.push_back(Aabb{c - half, c + half});
    }
    return view;
}

const char* kKindName[] = {"level", "axis", "oblique", "axis-even"};

TEST(IdDepthBufferBoxFastPath, EveryPixelEqualsThePerPixelSlabTestBitForBit) {
    long long pixels = 0, covered = 0, table_frames = 0;
    for (uint64_t seed : test::seedsToRun(1, 60)) {
        test::withSeed(seed, [&] {
            for (int kind = 0; kind < 4; ++kind) {
                const BoxView view = randomBoxView(seed * 4 + uint64_t(kind), kind);
                glm::dvec3 right, up, forward;
                view.camera.basis(right, up, forward);
                if (kind != 2) {
                    // The case under test: x and z by column, y by row.
                    EXPECT_EQ(right.y, 0.0) << kKindName[kind];
                    EXPECT_EQ(up.x, 0.0) << kKindName[kind];
                    EXPECT_EQ(up.z, 0.0) << kKindName[kind];
                    ++table_frames;
                }
                IdDepthBuffer buffer;
                buffer.resize(view.width, view.height);
                for (size_t k = 0; k < view.boxes.size(); ++k) {
                    // Alone.
                    buffer.begin(view.camera);
                    buffer.drawBox(0, view.boxes[k]);
                    int wrong = 0;
                    for (int py = 0; py < view.height; ++py)
                        for (int px = 0; px < view.width; ++px) {
                            const double want =
                                slabDepth(view.camera, view.width, view.height, view.boxes[k], px, py);
                            const double got = buffer.depthRow(py)[px];
                            ++pixels;
                            if (want < kInf) ++covered;
                            if (got != want && ++wrong <= 3)
                                ADD_FAILURE() << kKindName[kind] << " box " << k << " pixel (" << px
                                              << ", " << py << "): drawn " << got
                                              << ", slab test " << want;
                        }
                    // After another box: the per-pixel minimum, and the query agrees
                    // with whether the draw changes anything.
                    const Aabb& other = view.boxes[(k + 1) % view.boxes.size()];
                    buffer.begin(view.camera);
                    buffer.drawBox(1, other);
                    const std::vector<double> before = test::depthImage(buffer);
                    const bool passes = buffer.boxPassesDepthTest(view.boxes[k]);
                    buffer.drawBox(0, view.boxes[k]);
                    const std::vector<double> after = test::depthImage(buffer);
                    // (A box containing the eye passes by definition, even where
                    // everything is already at near.)
                    if (!view.boxes[k].contains(view.camera.position)) {
                        EXPECT_EQ(passes, before != after) << kKindName[kind] << " box " << k;
                    }
                    for (int py = 0; py < view.height; ++py)
                        for (int px = 0; px < view.width; ++px) {
                            const size_t p = size_t(py) * size_t(view.width) + size_t(px);
                            const double want = std::min(
                                before[p],
                                slabDepth(view.camera, view.width, view.height, view.boxes[k], px, py));
                            if (after[p] != want && ++wrong <= 3)
                                ADD_FAILURE() << kKindName[kind] << " box " << k << " over box "
                                              << (k + 1) % view.boxes.size() << " pixel (" << px
                                              << ", " << py << "): " << after[p] << ", want " << want;
                        }
                }
            }
        });
    }
    if (!test::singleSeedRun()) {
        std::printf("[box fast path] %lld pixels compared, %lld covered, %lld level/axis views\n",
                    pixels, covered, table_frames);
        EXPECT_GT(covered, pixels / 20);  // the boxes are not mostly off screen
    }
}

// Spheres likewise: drawSphere's pixel loop skips the far root when the near
// one is the answer, and must still give the depth solveSphereQuadratic +
// solidEntry give, bit for bit, in the documented view-space arithmetic.
double sphereDepth(const Camera& camera, int width, int height, const glm::dvec3& center,
                   double radius, int px, int py) {
    glm::dvec3 right, up, forward;
    camera.basis(right, up, forward);
    const glm::dvec3 rel = center - camera.position;
    const glm::dvec3 c{glm::dot(rel, right), glm::dot(rel, up), glm::dot(rel, forward)};
    const double k = glm::dot(c, c) - radius * radius;
    if (k <= 0.0) return camera.near;
    const double tan_y = std::tan(glm::radians(camera.fov_deg) * 0.5);
    const double tan_x = tan_y * camera.aspect;
    const double u = (2.0 * (px + 0.5) / width - 1.0) * tan_x;
    const double v = (1.0 - 2.0 * (py + 0.5) / height) * tan_y;
    double s0, s1, s;
    if (!solveSphereQuadratic(u * u + (v * v + 1.0), u * c.x + (v * c.y + c.z), k, s0, s1))
        return kInf;
    if (!solidEntry(s0, s1, camera.near, camera.far, s)) return kInf;
    return s;
}

TEST(IdDepthBufferSphereDepth, EveryPixelEqualsTheQuadraticBitForBit) {
    long long pixels = 0, covered = 0;
    for (uint64_t seed : test::seedsToRun(1, 60)) {
        test::withSeed(seed, [&] {
            for (int kind = 0; kind < 4; ++kind) {
                const BoxView view = randomBoxView(seed * 4 + uint64_t(kind), kind);
                IdDepthBuffer buffer;
                buffer.resize(view.width, view.height);
                for (size_t k = 0; k < view.boxes.size(); ++k) {
                    const glm::dvec3 center = view.boxes[k].center();
                    const double radius = view.boxes[k].max.x - center.x;
                    buffer.begin(view.camera);
                    buffer.drawSphere(0, center, radius);
                    int wrong = 0;
                    for (int py = 0; py < view.height; ++py)
                        for (int px = 0; px < view.width; ++px) {
                            const double want = sphereDepth(view.camera, view.width, view.height,
                                                            center, radius, px, py);
                            const double got = buffer.depthRow(py)[px];
                            ++pixels;
                            if (want < kInf) ++covered;
                            if (got != want && ++wrong <= 3)
                                ADD_FAILURE() << kKindName[kind] << " sphere " << k << " pixel ("
                                              << px << ", " << py << "): drawn " << got
                                              << ", quadratic " << want;
                        }
                }
            }
        });
    }
    if (!test::singleSeedRun()) {
        std::printf("[sphere depth] %lld pixels compared, %lld covered\n", pixels, covered);
        EXPECT_GT(covered, pixels / 20);
    }
}

// A draw hidden whole behind what is already drawn (rejected at tile level)
// reports an empty written rectangle, for boxes, spheres and meshes alike, so
// the image-space cullers' per-draw updates (lazy grid cells, occlusion bits,
// z pyramid) see nothing written.
TEST(IdDepthBufferHiddenDraw, AHiddenDrawLeavesTheWrittenRectangleEmpty) {
    Camera cam;
    cam.position = {0.0, 0.0, 0.0};
    cam.target = {0.0, 0.0, 1.0};
    cam.fov_deg = 90.0;
    cam.aspect = 1.5;
    cam.near = 0.1;
    cam.far = 100.0;
    IdDepthBuffer buffer;
    buffer.resize(test::kRasterWidth, test::kRasterHeight);
    for (int kind = 0; kind < 3; ++kind) {
        buffer.begin(cam);
        // A wall filling the view at depth 5..6: it writes every pixel.
        ASSERT_TRUE(buffer.drawBox(0, Aabb{{-100.0, -100.0, 5.0}, {100.0, 100.0, 6.0}}));
        EXPECT_EQ(buffer.lastDrawCols().lo, 0);
        EXPECT_EQ(buffer.lastDrawCols().hi, test::kRasterWidth - 1);
        EXPECT_EQ(buffer.lastDrawRows().hi, test::kRasterHeight - 1);
        // Something wholly behind it, in view: accepted, nothing written.
        bool accepted = false;
        if (kind == 0) accepted = buffer.drawBox(1, Aabb{{-1.0, -1.0, 10.0}, {1.0, 1.0, 11.0}});
        if (kind == 1) accepted = buffer.drawSphere(1, {0.5, 0.0, 20.0}, 2.0);
        const auto mesh = test::boxSurfaceMesh({1.0, 1.0, 1.0});
        if (kind == 2) accepted = buffer.drawMesh(1, *mesh, {0.0, 0.5, 30.0});
        EXPECT_TRUE(accepted) << kind;
        EXPECT_TRUE(buffer.lastDrawCols().empty()) << kind;
        EXPECT_TRUE(buffer.lastDrawRows().empty()) << kind;
    }
}

}  // namespace
}  // namespace gridcull
