#include "grid/regular_grid.h"

#include <gtest/gtest.h>

namespace gridcull {
namespace {

RegularGrid makeGrid3() {
    RegularGrid g;
    g.dimensions = 3;
    g.world = {{0, 0, 0}, {100, 60, 100}};
    g.resolution = {50, 30, 50};
    return g;
}

TEST(RegularGrid, VoxelOfFollowsTheHalfOpenConvention) {
    const RegularGrid g = makeGrid3();
    EXPECT_EQ(g.voxelSize(), glm::dvec3(2, 2, 2));
    EXPECT_EQ(g.voxelOf({0, 0, 0}), glm::ivec3(0, 0, 0));
    EXPECT_EQ(g.voxelOf({1.999, 2.0, 3.5}), glm::ivec3(0, 1, 1));
    // The max face belongs to the voxel past the last one: [min, max) per voxel.
    EXPECT_EQ(g.voxelOf({100, 60, 100}), glm::ivec3(50, 30, 50));
    EXPECT_FALSE(g.inside(g.voxelOf({100, 60, 100})));
    EXPECT_EQ(g.voxelOf({-0.5, -3, -4.01}), glm::ivec3(-1, -2, -3));
}

TEST(RegularGrid, FarPointsClampInsteadOfOverflowing) {
    const RegularGrid g = makeGrid3();
    const glm::ivec3 v = g.voxelOf({1e300, -1e300, 5});
    EXPECT_EQ(v.x, 1000000000);
    EXPECT_EQ(v.y, -1000000000);
    EXPECT_FALSE(g.inside(v));
}

TEST(RegularGrid, VoxelBoundsContainTheirPoints) {
    const RegularGrid g = makeGrid3();
    const Aabb b = g.voxelBounds({3, 4, 5});
    EXPECT_EQ(b.min, glm::dvec3(6, 8, 10));
    EXPECT_EQ(b.max, glm::dvec3(8, 10, 12));
    EXPECT_EQ(g.voxelOf(b.min), glm::ivec3(3, 4, 5));
    EXPECT_EQ(g.linearIndex({3, 4, 5}), (5 * 30 + 4) * 50 + 3);
    EXPECT_EQ(g.voxelCount(), 50 * 30 * 50);
}

TEST(RegularGrid, TwoDimensionalGridIsOneVoxelDeep) {
    RegularGrid g;
    g.dimensions = 2;
    g.world = {{-10, -10, 0}, {10, 10, 0}};
    g.resolution = {20, 40, 1};
    EXPECT_EQ(g.voxelSize(), glm::dvec3(1, 0.5, 1));
    EXPECT_EQ(g.voxelOf({0.5, 0.25, 123}), glm::ivec3(10, 20, 0));
    const Aabb b = g.voxelBounds({0, 0, 0});
    EXPECT_EQ(b.min, glm::dvec3(-10, -10, 0));
    EXPECT_EQ(b.max, glm::dvec3(-9, -9.5, 0));
}

TEST(RegularGrid, ResolutionBudgetIsCheckedBeforeAllocating) {
    EXPECT_EQ(checkResolution(3, {256, 256, 256}), "");
    EXPECT_EQ(checkResolution(2, {1024, 1024, 1}), "");
    EXPECT_EQ(checkResolution(2, {8192, 8192, 1}), "");
    EXPECT_NE(checkResolution(2, {8193, 8192, 1}), "");
    EXPECT_NE(checkResolution(3, {1024, 1024, 1024}), "");
    // Products that overflow 64 bits must still be caught.
    EXPECT_NE(checkResolution(3, {2000000000, 2000000000, 2000000000}), "");
    EXPECT_NE(checkResolution(3, {0, 5, 5}), "");
    EXPECT_NE(checkResolution(2, {5, -1, 1}), "");
    // In 2D the z resolution is not part of the count.
    EXPECT_EQ(checkResolution(2, {4, 4, 0}), "");
}

}  // namespace
}  // namespace gridcull
