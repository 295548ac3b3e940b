// The conservative discretization (grid/conservative_raster.h): opaque voxels
// (O) lie wholly inside the shape, spanned voxels (I) cover the shape, and for
// circles and boxes both sets are exactly the voxels a direct test gives.
#include "grid/conservative_raster.h"

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "culling/scene/seeded_random.h"

namespace gridcull {
namespace {

using VoxelSet = std::set<std::pair<int, int>>;

RegularGrid randomGrid(SeededRandom& rng) {
    RegularGrid grid;
    grid.dimensions = 2;
    const double x0 = rng.uniform(-20, 20), y0 = rng.uniform(-20, 20);
    grid.world = {{x0, y0, 0}, {x0 + rng.uniform(20, 60), y0 + rng.uniform(20, 60), 0}};
    grid.resolution = {4 + int(rng.below(40)), 4 + int(rng.below(40)), 1};
    return grid;
}

template <typename Raster>
void collect(Raster&& raster, const RegularGrid& grid, VoxelSet& touched, VoxelSet& inside) {
    raster(
        [&](int y, int x0, int x1) {
            ASSERT_LE(x0, x1);
            ASSERT_TRUE(x0 >= 0 && x1 < grid.resolution.x && y >= 0 && y < grid.resolution.y);
            for (int x = x0; x <= x1; ++x) ASSERT_TRUE(touched.insert({x, y}).second);
        },
        [&](int y, int x0, int x1) {
            ASSERT_LE(x0, x1);
            ASSERT_TRUE(x0 >= 0 && x1 < grid.resolution.x && y >= 0 && y < grid.resolution.y);
            for (int x = x0; x <= x1; ++x) ASSERT_TRUE(inside.insert({x, y}).second);
        });
}

// Every voxel of `inside` is in `touched`, lies wholly inside (sampled on a 7x7
// lattice including its corners) and every sampled point of the shape lies in a
// touched voxel.
template <typename Contains>
void checkConservative(const RegularGrid& grid, const VoxelSet& touched, const VoxelSet& inside,
                       const Aabb& bounds, Contains&& contains, SeededRandom& rng) {
    const glm::dvec3 d = grid.voxelSize();
    for (const auto& v : inside) {
        ASSERT_TRUE(touched.count(v));
        const Aabb b = grid.voxelBounds({v.first, v.second, 0});
        for (int i = 0; i <= 6; ++i)
            for (int j = 0; j <= 6; ++j)
                ASSERT_TRUE(contains(glm::dvec3(b.min.x + d.x * i / 6, b.min.y + d.y * j / 6, 0)))
                    << "opaque voxel " << v.first << "," << v.second << " not inside";
    }
    for (int s = 0; s < 4000; ++s) {
        const glm::dvec3 p{rng.uniform(bounds.min.x, bounds.max.x),
                           rng.uniform(bounds.min.y, bounds.max.y), 0};
        if (!contains(p)) continue;
        const glm::ivec3 v = grid.voxelOf(p);
        if (!grid.inside(v)) continue;
        ASSERT_TRUE(touched.count({v.x, v.y}))
            << "point in shape, voxel " << v.x << "," << v.y << " not spanned";
    }
}

TEST(ConservativeRaster, CirclesAreExact) {
    SeededRandom rng(31);
    for (int trial = 0; trial < 300; ++trial) {
        const RegularGrid grid = randomGrid(rng);
        const glm::dvec3 e = grid.world.extent();
        const glm::dvec3 c{grid.world.min.x + rng.uniform(-0.2, 1.2) * e.x,
                           grid.world.min.y + rng.uniform(-0.2, 1.2) * e.y, 0};
        const double r = rng.uniform(0.05, 0.4) * std::min(e.x, e.y);
        VoxelSet touched, inside;
        collect([&](auto&& t, auto&& in) { rasterizeCircle(grid, c, r, t, in); }, grid, touched,
                inside);
        for (int y = 0; y < grid.resolution.y; ++y) {
            for (int x = 0; x < grid.resolution.x; ++x) {
                const Aabb b = grid.voxelBounds({x, y, 0});
                const double gx = std::max({b.min.x - c.x, 0.0, c.x - b.max.x});
                const double gy = std::max({b.min.y - c.y, 0.0, c.y - b.max.y});
                const double near = std::hypot(gx, gy);
                const double fx = std::max(std::abs(b.min.x - c.x), std::abs(b.max.x - c.x));
                const double fy = std::max(std::abs(b.min.y - c.y), std::abs(b.max.y - c.y));
                const double far = std::hypot(fx, fy);
                const double tol = 1e-7 * r;
                if (std::abs(near - r) > tol) {
                    ASSERT_EQ(touched.count({x, y}) == 1, near < r)
                        << "trial " << trial << " voxel " << x << "," << y;
                }
                if (std::abs(far - r) > tol) {
                    ASSERT_EQ(inside.count({x, y}) == 1, far < r)
                        << "trial " << trial << " voxel " << x << "," << y;
                }
            }
        }
        checkConservative(
            grid, touched, inside, Aabb{c - glm::dvec3(r, r, 0), c + glm::dvec3(r, r, 0)},
            [&](const glm::dvec3& p) { return std::hypot(p.x - c.x, p.y - c.y) <= r; }, rng);
    }
}

TEST(ConservativeRaster, BoxesAreExact) {
    SeededRandom rng(32);
    for (int trial = 0; trial < 300; ++trial) {
        const RegularGrid grid = randomGrid(rng);
        const glm::dvec3 e = grid.world.extent(), d = grid.voxelSize();
        glm::dvec3 lo{grid.world.min.x + rng.uniform(-0.2, 1.0) * e.x,
                      grid.world.min.y + rng.uniform(-0.2, 1.0) * e.y, 0};
        glm::dvec3 hi =
            lo + glm::dvec3(rng.uniform(0.01, 0.5) * e.x, rng.uniform(0.01, 0.5) * e.y, 0);
        if (trial % 3 == 0) {
            // Snap to voxel boundaries: the edge cases of "touch" and "inside".
            lo.x = grid.world.min.x + std::round((lo.x - grid.world.min.x) / d.x) * d.x;
            hi.y = grid.world.min.y + std::round((hi.y - grid.world.min.y) / d.y) * d.y + d.y;
        }
        VoxelSet touched, inside;
        collect(
            [&](auto&& t, auto&& in) {
                rasterizeBox(grid, Aabb{lo, hi}, t, in);
            },
            grid, touched, inside);
        for (int y = 0; y < grid.resolution.y; ++y) {
            for (int x = 0; x < grid.resolution.x; ++x) {
                const Aabb b = grid.voxelBounds({x, y, 0});
                const bool meets =
                    b.min.x <= hi.x && b.max.x >= lo.x && b.min.y <= hi.y && b.max.y >= lo.y;
                const double snap = kOpaqueSnap * std::max(d.x, d.y) * 2;
                const bool within = b.min.x >= lo.x - snap && b.max.x <= hi.x + snap &&
                                    b.min.y >= lo.y - snap && b.max.y <= hi.y + snap;
                // Touching exactly at an edge counts as spanned; a voxel flush with the
                // box's edge counts as inside (to within kOpaqueSnap).
                if (meets) {
                    ASSERT_TRUE(touched.count({x, y})) << "trial " << trial;
                }
                if (inside.count({x, y})) {
                    ASSERT_TRUE(within) << "trial " << trial;
                }
                const double m = 1e-6 * std::min(d.x, d.y);
                const bool clearly_within = b.min.x > lo.x + m && b.max.x < hi.x - m &&
                                            b.min.y > lo.y + m && b.max.y < hi.y - m;
                if (clearly_within) {
                    ASSERT_TRUE(inside.count({x, y})) << "trial " << trial;
                }
                const bool clearly_apart = b.min.x > hi.x + m || b.max.x < lo.x - m ||
                                           b.min.y > hi.y + m || b.max.y < lo.y - m;
                if (clearly_apart) {
                    ASSERT_FALSE(touched.count({x, y})) << "trial " << trial;
                }
            }
        }
    }
}

TEST(ConservativeRaster, PolygonsConvexAndConcave) {
    SeededRandom rng(33);
    for (int trial = 0; trial < 200; ++trial) {
        const RegularGrid grid = randomGrid(rng);
        const glm::dvec3 e = grid.world.extent();
        const glm::dvec3 c{grid.world.min.x + rng.uniform(0.0, 1.0) * e.x,
                           grid.world.min.y + rng.uniform(0.0, 1.0) * e.y, 0};
        const int corners = 3 + int(rng.below(8));
        const double reach = rng.uniform(0.05, 0.5) * std::min(e.x, e.y);
        std::vector<glm::dvec3> points;
        for (int k = 0; k < corners; ++k) {
            const double angle = (k + rng.uniform(0.0, 0.8)) * 6.283185307179586 / corners;
            points.push_back(c + glm::dvec3(std::cos(angle), std::sin(angle), 0) *
                                     (reach * rng.uniform(0.2, 1.0)));
        }
        const glm::dvec3 shift{rng.uniform(-3, 3), rng.uniform(-3, 3), 0};
        VoxelSet touched, inside;
        collect(
            [&](auto&& t, auto&& in) {
                rasterizePolygon(grid, points.data(), points.size(), shift, t, in);
            },
            grid, touched, inside);
        Aabb bounds{points[0] + shift, points[0] + shift};
        for (const glm::dvec3& p : points) bounds.merge(Aabb{p + shift, p + shift});
        auto contains = [&](const glm::dvec3& p) {
            return pointInPolygonXY(p, points.data(), points.size(), shift);
        };
        checkConservative(grid, touched, inside, bounds, contains, rng);
        // The polygon's corners and edge points are spanned too.
        for (size_t i = 0; i < points.size(); ++i) {
            for (int s = 0; s <= 10; ++s) {
                const glm::dvec3 p =
                    points[i] + (points[(i + 1) % points.size()] - points[i]) * (s / 10.0) + shift;
                const glm::ivec3 v = grid.voxelOf(p);
                if (grid.inside(v)) {
                    ASSERT_TRUE(touched.count({v.x, v.y})) << "trial " << trial;
                }
            }
        }
    }
}

}  // namespace
}  // namespace gridcull
