#include "grid/polygon_raster.h"

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "culling/scene/seeded_random.h"

namespace gridcull {
namespace {

// A random convex region: a wedge from an apex (possibly unbounded) cut by a
// couple of random half-planes that keep a chosen interior point.
std::vector<HalfPlane2> randomConvexRegion(SeededRandom& rng) {
    std::vector<HalfPlane2> planes;
    const double cx = rng.uniform(-5, 45), cy = rng.uniform(-5, 45);
    const int count = 1 + int(rng.below(4));
    for (int i = 0; i < count; ++i) {
        const double angle = rng.uniform(0.0, 6.283185307179586);
        const double nx = std::cos(angle), ny = std::sin(angle);
        // The plane passes at distance s on the far side of (cx, cy).
        const double s = rng.uniform(0.0, 20.0);
        planes.push_back({nx, ny, nx * cx + ny * cy - s});
    }
    return planes;
}

TEST(PolygonRaster, SamplesExactlyTheIntegerPointsInside) {
    SeededRandom rng(21);
    for (int trial = 0; trial < 400; ++trial) {
        const std::vector<HalfPlane2> planes = randomConvexRegion(rng);
        std::set<std::pair<int, int>> got;
        rasterizeConvexAtCentres(planes.data(), int(planes.size()), 0, 39, 0, 39,
                                 [&](int y, int x0, int x1) {
                                     ASSERT_LE(x0, x1);
                                     for (int x = x0; x <= x1; ++x)
                                         ASSERT_TRUE(got.insert({x, y}).second);
                                 });
        for (int y = 0; y < 40; ++y) {
            for (int x = 0; x < 40; ++x) {
                double worst = 1e300;
                for (const HalfPlane2& p : planes) worst = std::min(worst, p.eval(x, y));
                if (std::abs(worst) < 1e-9) continue;  // on an edge: either way
                ASSERT_EQ(got.count({x, y}) == 1, worst > 0.0)
                    << "trial " << trial << " at " << x << "," << y;
            }
        }
    }
}

TEST(PolygonRaster, WholeVoxelsOnlyMarksExactlyTheVoxelsInside) {
    SeededRandom rng(22);
    for (int trial = 0; trial < 400; ++trial) {
        const std::vector<HalfPlane2> planes = randomConvexRegion(rng);
        std::vector<HalfPlane2> shrunk;
        for (const HalfPlane2& p : planes) shrunk.push_back(wholeVoxelsOnly(p, 1e-9));
        std::set<std::pair<int, int>> got;
        rasterizeConvexAtCentres(shrunk.data(), int(shrunk.size()), 0, 39, 0, 39,
                                 [&](int y, int x0, int x1) {
                                     for (int x = x0; x <= x1; ++x) got.insert({x, y});
                                 });
        for (int y = 0; y < 40; ++y) {
            for (int x = 0; x < 40; ++x) {
                // The voxel around centre (x, y): its least value over all planes.
                double worst = 1e300;
                for (const HalfPlane2& p : planes)
                    for (int c = 0; c < 4; ++c)
                        worst = std::min(
                            worst, p.eval(x + ((c & 1) ? 0.5 : -0.5), y + ((c & 2) ? 0.5 : -0.5)));
                if (got.count({x, y})) {
                    ASSERT_GE(worst, 0.0) << "voxel " << x << "," << y << " marked but not inside";
                } else if (worst > 1e-6) {
                    ADD_FAILURE() << "voxel " << x << "," << y << " inside but not marked";
                    return;
                }
            }
        }
    }
}

TEST(PolygonRaster, VoxelCentreCoordinatesFollowTheGrid) {
    RegularGrid grid;
    grid.dimensions = 2;
    grid.world = {{-10, 5, 0}, {30, 25, 0}};
    grid.resolution = {8, 10, 1};  // voxels 5 x 2
    SeededRandom rng(23);
    for (int trial = 0; trial < 100; ++trial) {
        const HalfPlane2 world{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-20, 20)};
        const HalfPlane2 centre = toVoxelCentreCoords(world, grid);
        for (int j = 0; j < 10; ++j)
            for (int i = 0; i < 8; ++i) {
                const double wx = -10 + (i + 0.5) * 5, wy = 5 + (j + 0.5) * 2;
                ASSERT_NEAR(centre.eval(i, j), world.eval(wx, wy), 1e-9);
            }
    }
}

}  // namespace
}  // namespace gridcull
