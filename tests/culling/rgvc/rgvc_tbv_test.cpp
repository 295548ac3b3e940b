// TBVs of rgvc in the TBV matrix (culling/rgvc/rgvc_tbv.h):
//  - the 4-connected boundary circle encloses every voxel the disc touches, so
//    no 8-connected path from outside reaches them without stepping on it
//    (flood fill over all paths at once, and random viewer paths as the paper
//    states it);
//  - the filled form holds every voxel the disc touches;
//  - tbvCurveMayEnclose is never wrong when it says no, and the shortened
//    radius really leaves the viewer's voxel outside.
#include <cmath>
#include <deque>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "culling/rgvc/rgvc_tbv.h"
#include "culling/scene/seeded_random.h"

namespace gridcull {
namespace {

using VoxelSet = std::set<std::pair<int64_t, int64_t>>;

RegularGrid gridFor(SeededRandom& rng) {
    RegularGrid grid;
    grid.dimensions = 2;
    const double sx = rng.uniform(0.3, 3.0);
    const double sy = rng.uniform() < 0.5 ? sx : rng.uniform(0.3, 3.0);
    grid.world = {{-10, -20, 0}, {-10 + 200 * sx, -20 + 200 * sy, 0}};
    grid.resolution = {200, 200, 1};
    return grid;
}

bool voxelTouchesDisc(const RegularGrid& grid, int64_t x, int64_t y, glm::dvec3 c, double r) {
    const Aabb b = grid.voxelBounds({int(x), int(y), 0});
    const double gx = std::max({b.min.x - c.x, 0.0, c.x - b.max.x});
    const double gy = std::max({b.min.y - c.y, 0.0, c.y - b.max.y});
    return std::hypot(gx, gy) <= r;
}

TEST(RgvcTbv, BoundaryCircleSeparatesTheDiscFromEveryEightConnectedPath) {
    SeededRandom rng(41);
    for (int trial = 0; trial < 300; ++trial) {
        const RegularGrid grid = gridFor(rng);
        const glm::dvec3 d = grid.voxelSize();
        const glm::dvec3 c{grid.world.min.x + rng.uniform(0.3, 0.7) * 200 * d.x,
                           grid.world.min.y + rng.uniform(0.3, 0.7) * 200 * d.y, 0};
        const double r = rng.uniform(0.0, 25.0) * std::min(d.x, d.y);
        const RgvcTbvCurve curve = tbvCurveFor(grid, c, r);
        VoxelSet boundary;
        forEachTbvBoundaryVoxel(curve, [&](int x, int y) { boundary.insert({x, y}); });
        for (const auto& v : boundary) ASSERT_TRUE(tbvCurveMayEnclose(curve, {v.first, v.second}));
        // Flood fill 8-connected from outside the curve's box, never entering it.
        const int64_t reach = curve.radius + 3;
        const int64_t x0 = curve.centre.x - reach, x1 = curve.centre.x + reach;
        const int64_t y0 = curve.centre.y - reach, y1 = curve.centre.y + reach;
        VoxelSet seen;
        std::deque<std::pair<int64_t, int64_t>> queue;
        queue.push_back({x0, y0});
        seen.insert({x0, y0});
        while (!queue.empty()) {
            const auto v = queue.front();
            queue.pop_front();
            ASSERT_FALSE(voxelTouchesDisc(grid, v.first, v.second, c, r))
                << "trial " << trial << ": voxel " << v.first << "," << v.second
                << " touches the disc but is reachable around the curve";
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const std::pair<int64_t, int64_t> n{v.first + dx, v.second + dy};
                    if (n.first < x0 || n.first > x1 || n.second < y0 || n.second > y1) continue;
                    if (boundary.count(n) || !seen.insert(n).second) continue;
                    queue.push_back(n);
                }
            }
        }
        // Anything the fill did not reach is on or inside the curve; whatever
        // cannot be enclosed must have been reached.
        for (int64_t y = y0; y <= y1; ++y) {
            for (int64_t x = x0; x <= x1; ++x) {
                if (!tbvCurveMayEnclose(curve, {x, y})) {
                    ASSERT_TRUE(seen.count({x, y}));
                }
            }
        }
        // The filled form covers the disc's voxels.
        VoxelSet filled;
        forEachTbvFilledSpan(curve, [&](int y, int a, int b) {
            for (int x = a; x <= b; ++x) filled.insert({x, y});
        });
        for (const auto& v : boundary) ASSERT_TRUE(filled.count(v));
        for (int64_t y = y0; y <= y1; ++y) {
            for (int64_t x = x0; x <= x1; ++x) {
                if (voxelTouchesDisc(grid, x, y, c, r)) {
                    ASSERT_TRUE(filled.count({x, y}));
                }
            }
        }
    }
}

TEST(RgvcTbv, EveryEightConnectedViewerPathIntoTheCircleStepsOnIt) {
    SeededRandom rng(42);
    int paths = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const RegularGrid grid = gridFor(rng);
        const glm::dvec3 d = grid.voxelSize();
        const glm::dvec3 c{grid.world.min.x + 100 * d.x, grid.world.min.y + 100 * d.y, 0};
        const double r = rng.uniform(0.0, 20.0) * std::min(d.x, d.y);
        const RgvcTbvCurve curve = tbvCurveFor(grid, c, r);
        VoxelSet boundary;
        forEachTbvBoundaryVoxel(curve, [&](int x, int y) { boundary.insert({x, y}); });
        // A random walk of 8-neighbour steps from far outside, biased towards the
        // centre, until it reaches a voxel touching the disc.
        for (int walk = 0; walk < 20; ++walk) {
            const double angle = rng.uniform(0.0, 6.283185307179586);
            int64_t x = curve.centre.x + int64_t(std::lround((curve.radius + 5) * std::cos(angle)));
            int64_t y = curve.centre.y + int64_t(std::lround((curve.radius + 5) * std::sin(angle)));
            bool stepped_on = false;
            for (int step = 0; step < 10000; ++step) {
                stepped_on = stepped_on || boundary.count({x, y}) > 0;
                if (voxelTouchesDisc(grid, x, y, c, r)) break;
                const int64_t sx = curve.centre.x > x ? 1 : curve.centre.x < x ? -1 : 0;
                const int64_t sy = curve.centre.y > y ? 1 : curve.centre.y < y ? -1 : 0;
                const double u = rng.uniform();
                // Mostly towards the centre, sometimes sideways (still 8-connected).
                x += u < 0.7 ? sx : int64_t(rng.below(3)) - 1;
                y += u < 0.7 ? sy : int64_t(rng.below(3)) - 1;
            }
            ASSERT_TRUE(stepped_on) << "trial " << trial << " walk " << walk;
            ++paths;
        }
    }
    EXPECT_EQ(paths, 4000);
}

TEST(RgvcTbv, ShortenedRadiusLeavesTheViewerOutside) {
    SeededRandom rng(43);
    for (int trial = 0; trial < 2000; ++trial) {
        const RegularGrid grid = gridFor(rng);
        const glm::dvec3 d = grid.voxelSize();
        const glm::dvec3 c{grid.world.min.x + rng.uniform(50, 150) * d.x,
                           grid.world.min.y + rng.uniform(50, 150) * d.y, 0};
        const glm::i64vec2 viewer{int64_t(rng.below(200)), int64_t(rng.below(200))};
        const double r = tbvLargestRadiusExcluding(grid, c, viewer);
        if (r < 0.0) continue;
        ASSERT_FALSE(tbvCurveMayEnclose(tbvCurveFor(grid, c, r), viewer)) << "trial " << trial;
    }
}

TEST(RgvcTbv, InsideGridMeansTheWholeFilledFormIsInside) {
    RegularGrid grid;
    grid.dimensions = 2;
    grid.world = {{0, 0, 0}, {100, 100, 0}};
    grid.resolution = {100, 100, 1};
    const RgvcTbvCurve curve = tbvCurveFor(grid, {50.5, 50.5, 0}, 10.0);
    EXPECT_EQ(curve.centre, glm::i64vec2(50, 50));
    EXPECT_EQ(curve.radius, 13);  // ceil(10 + 2.5)
    EXPECT_TRUE(tbvCurveInsideGrid(grid, curve));
    EXPECT_FALSE(tbvCurveInsideGrid(grid, tbvCurveFor(grid, {5, 50, 0}, 10.0)));
    EXPECT_FALSE(tbvCurveInsideGrid(grid, tbvCurveFor(grid, {50, 98, 0}, 10.0)));
}

}  // namespace
}  // namespace gridcull
