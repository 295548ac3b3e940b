// The lazy grid's box projection (culling/raster/screen_mapping.h) against brute
// force: every pixel centre whose ray (the oracle's convention) meets the box at
// depth >= near lies in the box's rectangle, the box's znear is below every such
// depth, and a box around the eye covers the whole image.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "culling/raster/screen_mapping.h"
#include "culling/scene/ray_intersect.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/lazy_grid/lazy_grid_random_scene.h"

namespace gridcull {
namespace {

TEST(LazyGridScreen, RectangleHoldsEveryPixelCentreThatSeesTheBox) {
    long long hits = 0;
    for (uint64_t seed : test::seedsToRun(1, 300)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            Camera camera;
            camera.position = test::randomPoint3(rng, -20, 20);
            camera.target = camera.position + test::randomPoint3(rng, -1, 1);
            camera.fov_deg = rng.uniform(5.0, 150.0);
            camera.aspect = rng.uniform(0.3, 3.0);
            camera.near = rng.uniform() < 0.3 ? rng.uniform(0.5, 5.0) : 0.1;
            camera.far = 1000.0;
            const int width = 16 + int(rng.below(80)), height = 16 + int(rng.below(80));
            ScreenMapping mapping;
            mapping.set(camera, width, height);
            // Boxes mostly in front of the camera, some around or behind it.
            const glm::dvec3 c =
                camera.position +
                glm::normalize(camera.target - camera.position) * rng.uniform(-5.0, 30.0) +
                test::randomPoint3(rng, -8, 8);
            const glm::dvec3 half = test::randomPoint3(rng, 0.01, 12.0);
            const Aabb box{c - half, c + half};
            const BoxOnScreen on_screen = mapping.project(box);
            if (box.contains(camera.position)) {
                EXPECT_EQ(on_screen.rect.area(), (long long)width * height);
            }
            glm::dvec3 right, up, fwd;
            camera.basis(right, up, fwd);
            const double tan_y = std::tan(glm::radians(camera.fov_deg) * 0.5);
            const double tan_x = tan_y * camera.aspect;
            for (int py = 0; py < height; ++py)
                for (int px = 0; px < width; ++px) {
                    const double u = (2.0 * (px + 0.5) / width - 1.0) * tan_x;
                    const double v = (1.0 - 2.0 * (py + 0.5) / height) * tan_y;
                    const glm::dvec3 dir = fwd + u * right + v * up;
                    double s0, s1, s;
                    if (!lineBox(camera.position, dir, box, s0, s1)) continue;
                    if (!solidEntry(s0, s1, camera.near, camera.far, s)) continue;
                    EXPECT_TRUE(px >= on_screen.rect.x0 && px <= on_screen.rect.x1 &&
                                py >= on_screen.rect.y0 && py <= on_screen.rect.y1)
                        << "pixel " << px << "," << py << " sees the box outside its rectangle";
                    ++hits;
                    EXPECT_LE(on_screen.znear, s);
                    EXPECT_GE(on_screen.zfar, s1);
                }
        });
    }
    // Enough boxes are seen (many from inside or across the near plane) to mean something.
    if (!test::singleSeedRun()) {
        EXPECT_GT(hits, 20000) << hits;
        std::printf("[lazy-grid screen] %lld pixel centres saw a box\n", hits);
    }
}

TEST(LazyGridScreen, BoxWhollyBehindTheNearPlaneHasNoPixels) {
    Camera camera;
    camera.position = {0, 0, 0};
    camera.target = {0, 0, 1};
    camera.near = 1.0;
    ScreenMapping mapping;
    mapping.set(camera, 64, 36);
    EXPECT_TRUE(mapping.project({{-1, -1, 0.2}, {1, 1, 0.9}}).rect.empty());
    EXPECT_TRUE(mapping.project({{-1, -1, -5}, {1, 1, -2}}).rect.empty());
    EXPECT_FALSE(mapping.project({{-1, -1, 0.2}, {1, 1, 1.1}}).rect.empty());
    // Far to the side but in front: off the image.
    EXPECT_TRUE(mapping.project({{-500, -1, 5}, {-400, 1, 6}}).rect.empty());
}

}  // namespace
}  // namespace gridcull
