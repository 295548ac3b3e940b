// Extremes of the grid, every algorithm against the exact
// oracle (extremes_harness.h): grids of 1 x 1 (x 1), 1 x N and N x 1, odd and
// non-power-of-two sizes (so voxels are far from square), typical working
// sizes (1024 x 1024 in 2D, 256^3 in 3D) and the largest the scene format
// allows, kMaxGridVoxels = 2^26 voxels (8192 x 8192 in 2D; 406^3, 407 x 406 x
// 406 or 8192 x 8192 x 1 in 3D). A
// resolution beyond the budget is rejected before anything is allocated, by
// checkResolution and by the loader (which would otherwise die allocating 2^93
// voxels under AddressSanitizer).
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grid/regular_grid.h"
#include "tests/culling/registry/extremes_harness.h"
#include "tests/culling/registry/extremes_scenes.h"

namespace gridcull {
namespace {

using test::ExtremeCase;
using test::makeCamera;

ExtremeCase gridCase(int dims, const glm::ivec3& resolution, int objects, int frames,
                     double far = 1000.0) {
    Scene scene = dims == 3 ? test::makeScene(3, Aabb{{0, 0, 0}, {100, 100, 100}}, resolution)
                            : test::makeScene(2, Aabb{{0, 0, 0}, {100, 100, 0}}, resolution);
    EXPECT_EQ(checkResolution(dims, scene.grid.resolution), "");
    SeededRandom rng(uint64_t(resolution.x) * 7919 + uint64_t(resolution.y) * 31 +
                     uint64_t(resolution.z));
    test::addRandomObjects(scene, rng, objects);
    char name[96];
    std::snprintf(name, sizeof name, "%dd grid %d x %d%s", dims, resolution.x, resolution.y,
                  dims == 3 ? (" x " + std::to_string(resolution.z)).c_str() : "");
    ExtremeCase c{name, scene, {}, {}};
    // Walking diagonally through the grid from outside it, turning as it goes.
    for (int f = 0; f < frames; ++f) {
        const double s = double(f) / std::max(1, frames - 1);
        const glm::dvec3 eye = dims == 3 ? glm::dvec3(-10 + 100 * s, 20 + 50 * s, 10 + 70 * s)
                                         : glm::dvec3(-10 + 100 * s, 20 + 50 * s, 0);
        const glm::dvec3 target =
            dims == 3 ? glm::dvec3(100 - 80 * s, 100, 50) : glm::dvec3(100 - 80 * s, 100, 0);
        c.frames.push_back({f * test::kDt,
                            makeCamera(dims, eye, target, dims == 3 ? 70 : 120, 16.0 / 9.0, 0.1,
                                       far),
                            {},
                            {}});
    }
    test::adoptCamera(c.scene, c.frames.front().camera);
    c.scene.finalize();
    return c;
}

TEST(ExtremesGrid, DegenerateOddAndNonPowerOfTwoGrids) {
    const glm::ivec3 grids2[] = {{1, 1, 1},  {1, 64, 1},  {64, 1, 1},
                                 {7, 13, 1}, {999, 3, 1}, {3, 1000, 1}};
    for (const glm::ivec3& r : grids2) test::runExtremeCase(gridCase(2, r, 40, 5));
    const glm::ivec3 grids3[] = {{1, 1, 1}, {1, 64, 1}, {1, 1, 64}, {7, 13, 5}, {255, 3, 17}};
    for (const glm::ivec3& r : grids3) test::runExtremeCase(gridCase(3, r, 40, 3));
}

TEST(ExtremesGrid, LargeGrids) {
    // Typical working sizes, then the largest the voxel budget allows.
    test::runExtremeCase(gridCase(2, {1024, 1024, 1}, 60, 3));
    // A grid culler's cost grows with the voxels its traversal visits: a
    // 70-degree view over most of a 256^3 grid or of 2^26 voxels takes rgvc
    // seconds per frame (9 s under ASan at 256^3), so the large 3D grids are
    // seen with a far plane of 60 or 40 units (a tenth of their voxels or less),
    // as the largest 2D grid below is.
    test::runExtremeCase(gridCase(3, {256, 256, 256}, 60, 2, 60.0));
    test::runExtremeCase(gridCase(3, {406, 406, 406}, 30, 1, 40.0));
    test::runExtremeCase(gridCase(3, {8192, 8192, 1}, 30, 1, 40.0));
}

// 8192 x 8192 voxels of one unit. A grid culler's cost grows with the voxels
// its traversal visits (rgvc: about 10 s per frame under ASan when a 120-degree
// view sweeps most of the 2^26 voxels), so the camera looks from near the far
// corner (the largest voxel indices) and from the origin with a far plane of
// 400 units, and teleports between the two.
TEST(ExtremesGrid, LargestTwoDimensionalGridTheBudgetAllows) {
    ASSERT_EQ(int64_t(8192) * 8192, kMaxGridVoxels);
    Scene scene = test::makeScene(2, Aabb{{0, 0, 0}, {8192, 8192, 0}}, {8192, 8192, 1});
    ASSERT_EQ(checkResolution(2, scene.grid.resolution), "");
    SeededRandom rng(8192);
    test::addRandomObjects(scene, rng, 30);
    // Small objects around both viewpoints.
    for (int k = 0; k < 20; ++k) {
        const double a = k * 0.3;
        test::addSphere(scene, 100 + k, {8000 - 15.0 * k, 8000 - 9.0 * k + std::sin(a) * 40, 0}, 3);
        test::addBox(scene, 200 + k, {60.0 + 14 * k, 80 + std::cos(a) * 30, 0},
                     {64.0 + 14 * k, 84 + std::cos(a) * 30, 0});
    }
    ExtremeCase c{"2d grid 8192 x 8192 (the budget), far 400", scene, {}, {}};
    const struct {
        glm::dvec3 eye, target;
    } views[] = {{{8191.5, 8191.5, 0}, {0, 0, 0}},
                 {{8150, 8100, 0}, {8192, 8192, 0}},
                 {{0.5, 0.5, 0}, {8192, 8192, 0}},
                 {{300, 120, 0}, {0, 100, 0}}};
    int f = 0;
    for (const auto& v : views) {
        c.frames.push_back(
            {f * test::kDt, makeCamera(2, v.eye, v.target, 90, 1.0, 0.1, 400), {}, {}});
        ++f;
    }
    test::adoptCamera(c.scene, c.frames.front().camera);
    c.scene.finalize();
    test::runExtremeCase(c);
}

TEST(ExtremesGrid, ResolutionBeyondTheBudgetIsRejectedBeforeAllocating) {
    EXPECT_EQ(checkResolution(2, {8192, 8192, 1}), "");
    EXPECT_EQ(checkResolution(3, {406, 406, 406}), "");
    EXPECT_NE(checkResolution(2, {8193, 8192, 1}), "");
    EXPECT_EQ(checkResolution(3, {407, 406, 406}), "");  // 67,088,252 voxels
    EXPECT_NE(checkResolution(3, {407, 407, 406}), "");  // 67,253,494
    EXPECT_EQ(checkResolution(3, {8192, 8192, 1}), "");
    EXPECT_NE(checkResolution(3, {8192, 8192, 2}), "");
    EXPECT_NE(checkResolution(3, {2147483647, 2147483647, 2147483647}), "");
    EXPECT_NE(checkResolution(2, {0, 5, 1}), "");

    auto text = [](const std::string& resolution, int dims) {
        const std::string v0 = dims == 3 ? "[0, 0, 0]" : "[0, 0]";
        const std::string v1 = dims == 3 ? "[100, 100, 100]" : "[100, 100]";
        return R"({ "format": "gridcull-scene/1", "dimensions": )" + std::to_string(dims) +
               R"(, "world": { "min": )" + v0 + R"(, "max": )" + v1 + R"( },
  "grid": { "resolution": )" +
               resolution + R"( },
  "camera": { "path": [ { "t": 0, "position": )" +
               v0 + R"(, "target": )" + v1 + R"( } ] } })";
    };
    EXPECT_EQ(test::loadErrors(text("[8192, 8192]", 2)), "");
    EXPECT_EQ(test::loadErrors(text("[406, 406, 406]", 3)), "");
    const auto start = std::chrono::steady_clock::now();
    const std::string errors = test::loadErrors(text("[2147483647, 2147483647, 2147483647]", 3));
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NE(
        errors.find("extreme.json: grid.resolution: must fit in memory: grid of more than "
                    "67108864 voxels is beyond the memory budget, got [2147483647,2147483647,"),
        std::string::npos)
        << errors;
    EXPECT_LT(ms, 1000.0) << "rejecting a resolution must not allocate or loop over voxels";
    EXPECT_NE(test::loadErrors(text("[8193, 8192]", 2)).find("beyond the memory budget"),
              std::string::npos);
    EXPECT_NE(test::loadErrors(text("[2147483648, 1]", 2)).find("grid.resolution"),
              std::string::npos);
    EXPECT_NE(test::loadErrors(text("[0, 1]", 2)).find("grid.resolution"), std::string::npos);
}

// A grid culler turns the viewpoint into a voxel every frame. Points far out
// (or NaN, from a degenerate grid) must give a clamped voxel outside the grid,
// never an int overflow (UBSan's float-cast-overflow checks the cast).
TEST(ExtremesGrid, VoxelOfFarAndNonFinitePointsIsClamped) {
    RegularGrid grid;
    grid.world = Aabb{{0, 0, 0}, {100, 100, 100}};
    grid.resolution = {10, 10, 10};
    const double nan = std::nan("");
    const double inf = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& p :
         {glm::dvec3(nan, 5, 5), glm::dvec3(inf, -inf, 5), glm::dvec3(1e300, -1e300, nan),
          glm::dvec3(1e10, 5, 5), glm::dvec3(-1e10, 5, 5)}) {
        const glm::ivec3 v = grid.voxelOf(p);
        EXPECT_FALSE(grid.inside(v));
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GE(v[axis], -1000000000);
            EXPECT_LE(v[axis], 1000000000);
        }
    }
    // A degenerate (zero-width) grid, which the loader rejects: 0 / 0 is NaN.
    grid.world = Aabb{{5, 5, 5}, {5, 5, 5}};
    const glm::ivec3 v = grid.voxelOf({5, 5, 5});
    EXPECT_FALSE(grid.inside(v));
}

}  // namespace
}  // namespace gridcull
