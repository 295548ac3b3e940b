// The Z-pyramid (culling/hzb_tbv/z_pyramid.h; Greene, Kass & Miller's
// hierarchical z-buffer as Sudarsky & Gotsman, "Dynamic scene occlusion
// culling", section 2.1.1 and Fig. 1, use it) against brute force over level 0:
// level sizes halve rounding up to a 1 x 1 top; every texel is the farthest of
// the (up to 2 x 2) texels below it and the farthest level-0 pixel of its whole
// footprint, on random depth buffers of odd, 1 x N and N x 1 sizes; the Z query
// is conservative (some pixel of the rectangle at or beyond znear: visible) and
// answers exactly what its level's 2 x 2 block says; it culls a box behind a
// wall drawn by the shared rasterizer; rebuilding keeps the buffers.
//
// Tolerance: none. A maximum of doubles is one of its arguments, rounding
// nothing, so texels equal brute-force maxima exactly, and the query compares
// the same doubles as the brute force. GRIDCULL_SEED=N replays one seed.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "culling/hzb_tbv/z_pyramid.h"
#include "culling/raster/id_depth_buffer.h"
#include "culling/raster/screen_mapping.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/test_seeds.h"

namespace gridcull {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct DepthImage {
    int width = 0, height = 0;
    std::vector<double> depth;
    double at(int x, int y) const { return depth[size_t(y) * size_t(width) + size_t(x)]; }
};

// Empty pixels (+infinity), walls of constant depth painted nearest first wins,
// and noise, so that maxima vary and some regions are nearer than others.
DepthImage randomDepths(SeededRandom& rng, int width, int height) {
    DepthImage img{width, height, std::vector<double>(size_t(width) * size_t(height), kInf)};
    const int walls = 1 + int(rng.below(6));
    for (int w = 0; w < walls; ++w) {
        const int x0 = int(rng.below(uint64_t(width))), y0 = int(rng.below(uint64_t(height)));
        const int x1 = std::min(width - 1, x0 + int(rng.below(uint64_t(width)))),
                  y1 = std::min(height - 1, y0 + int(rng.below(uint64_t(height))));
        const double z = rng.uniform(1.0, 50.0);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                double& d = img.depth[size_t(y) * size_t(width) + size_t(x)];
                d = std::min(d, z);
            }
    }
    for (double& d : img.depth)
        if (rng.uniform() < 0.1) d = rng.uniform() < 0.3 ? kInf : rng.uniform(0.5, 60.0);
    return img;
}

// The brute force: the farthest level-0 depth over pixels [x0, x1] x [y0, y1]
// (clipped to the image); -infinity over no pixel.
double farthestOver(const DepthImage& img, int x0, int y0, int x1, int y1) {
    double m = -kInf;
    for (int y = std::max(0, y0); y <= std::min(img.height - 1, y1); ++y)
        for (int x = std::max(0, x0); x <= std::min(img.width - 1, x1); ++x)
            m = std::max(m, img.at(x, y));
    return m;
}

std::pair<int, int> randomSize(SeededRandom& rng) {
    static const std::pair<int, int> kShapes[] = {{1, 1},   {1, 2},   {2, 1},  {1, 37},
                                                  {53, 1},  {3, 3},   {5, 9},  {17, 13},
                                                  {64, 36}, {63, 37}, {2, 65}, {100, 3}};
    if (rng.uniform() < 0.5) return kShapes[rng.below(std::size(kShapes))];
    return {1 + int(rng.below(90)), 1 + int(rng.below(90))};
}

TEST(ZPyramid, LevelsHalveRoundingUpToOneTexel) {
    const std::pair<int, int> sizes[] = {{1, 1}, {1, 9},   {9, 1},  {2, 2},
                                         {5, 3}, {64, 64}, {65, 33}};
    for (const auto& [w, h] : sizes) {
        ZPyramid pyramid;
        const std::vector<double> depths(size_t(w) * size_t(h), 1.0);
        pyramid.build(w, h, depths.data());
        int lw = w, lh = h;
        for (int l = 0; l < pyramid.levelCount(); ++l) {
            EXPECT_EQ(pyramid.level(l).width, lw) << w << "x" << h << " level " << l;
            EXPECT_EQ(pyramid.level(l).height, lh) << w << "x" << h << " level " << l;
            lw = (lw + 1) / 2;
            lh = (lh + 1) / 2;
        }
        const ZPyramidLevel top = pyramid.level(pyramid.levelCount() - 1);
        EXPECT_EQ(top.width, 1);
        EXPECT_EQ(top.height, 1);
        // The top is the only 1 x 1 level: levels = 1 + ceil(log2(max side)).
        EXPECT_EQ(pyramid.levelCount(), 1 + int(std::ceil(std::log2(double(std::max(w, h))))));
    }
}

TEST(ZPyramid, EachTexelIsTheFarthestOfItsFootprint) {
    long long texels = 0;
    for (uint64_t seed : test::seedsToRun(1, 60)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const auto [w, h] = randomSize(rng);
            DepthImage img = randomDepths(rng, w, h);
            std::vector<double> input = img.depth;
            if (rng.uniform() < 0.3) {  // a NaN reads as empty
                const size_t i = rng.below(input.size());
                input[i] = std::numeric_limits<double>::quiet_NaN();
                img.depth[i] = kInf;
            }
            ZPyramid pyramid;
            pyramid.build(w, h, input.data());
            ASSERT_EQ(pyramid.width(), w);
            ASSERT_EQ(pyramid.height(), h);
            for (int l = 0; l < pyramid.levelCount(); ++l) {
                const ZPyramidLevel lv = pyramid.level(l);
                for (int y = 0; y < lv.height; ++y)
                    for (int x = 0; x < lv.width; ++x) {
                        ++texels;
                        // Over level 0 directly: the whole footprint.
                        const double full = farthestOver(img, x << l, y << l, ((x + 1) << l) - 1,
                                                         ((y + 1) << l) - 1);
                        ASSERT_EQ(lv.at(x, y), full) << "level " << l << " texel " << x << "," << y;
                        if (l == 0) continue;
                        // Over the level below: the up to 2 x 2 texels that exist.
                        const ZPyramidLevel below = pyramid.level(l - 1);
                        double m = -kInf;
                        for (int dy = 0; dy < 2; ++dy)
                            for (int dx = 0; dx < 2; ++dx)
                                if (2 * x + dx < below.width && 2 * y + dy < below.height)
                                    m = std::max(m, below.at(2 * x + dx, 2 * y + dy));
                        ASSERT_EQ(lv.at(x, y), m) << "level " << l << " texel " << x << "," << y;
                    }
            }
        });
    }
    if (!test::singleSeedRun()) {
        EXPECT_GT(texels, 50000);
    }
}

// A rectangle of random size (up to a little more than the image) that meets
// the image, reaching past its edges now and then; one in ten lies anywhere,
// off the image too.
PixelRect randomRect(SeededRandom& rng, int w, int h) {
    const int rw = 1 + int(std::pow(double(w) + 1.0, rng.uniform())),
              rh = 1 + int(std::pow(double(h) + 1.0, rng.uniform()));
    if (rng.uniform() < 0.1) {
        const int x0 = int(rng.below(uint64_t(w + 6))) - 3,
                  y0 = int(rng.below(uint64_t(h + 6))) - 3;
        return {x0, y0, x0 + rw - 1, y0 + rh - 1};
    }
    const int x0 = int(rng.below(uint64_t(w + rw - 1))) - (rw - 1),
              y0 = int(rng.below(uint64_t(h + rh - 1))) - (rh - 1);
    return {x0, y0, x0 + rw - 1, y0 + rh - 1};
}

TEST(ZPyramid, QueryIsConservativeAndReadsItsLevelsBlock) {
    long long queries = 0, hidden = 0, hidden_by_rect_alone = 0, empty = 0;
    for (uint64_t seed : test::seedsToRun(1, 40)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const auto [w, h] = randomSize(rng);
            const DepthImage img = randomDepths(rng, w, h);
            ZPyramid pyramid;
            pyramid.build(w, h, img.depth.data());
            for (int q = 0; q < 200; ++q) {
                const PixelRect rect = randomRect(rng, w, h);
                const PixelRect r = rect.intersect({0, 0, w - 1, h - 1});
                const double in_rect = farthestOver(img, r.x0, r.y0, r.x1, r.y1);
                // znear around the rectangle's farthest depth, so that both answers
                // and the ties between them come up.
                double znear = rng.uniform(0.0, 70.0);
                if (std::isfinite(in_rect) && rng.uniform() < 0.7) {
                    const double d = rng.uniform();
                    znear = d < 0.2 ? in_rect : in_rect + rng.uniform(-3.0, 3.0);
                }
                const ZQueryResult result = pyramid.query(rect, znear);
                ++queries;
                hidden += !result.may_be_visible;
                hidden_by_rect_alone += !r.empty() && in_rect < znear;
                if (r.empty()) {
                    ++empty;
                    EXPECT_FALSE(result.may_be_visible);
                    continue;
                }
                // Conservative: a pixel at or beyond znear means visible.
                if (in_rect >= znear) {
                    ASSERT_TRUE(result.may_be_visible)
                        << "rect " << rect.x0 << "," << rect.y0 << "-" << rect.x1 << "," << rect.y1
                        << " farthest " << in_rect << " znear " << znear;
                }
                // The level: the lowest whose texels meeting r are at most 2 x 2.
                int level = 0;
                for (;; ++level) {
                    const int span = 1 << level;
                    int nx = 0, ny = 0;
                    for (int x = 0; x * span < w; ++x)
                        nx += x * span <= r.x1 && (x + 1) * span - 1 >= r.x0;
                    for (int y = 0; y * span < h; ++y)
                        ny += y * span <= r.y1 && (y + 1) * span - 1 >= r.y0;
                    if (nx <= 2 && ny <= 2) break;
                }
                ASSERT_EQ(result.level, level);
                // Exactly what that block's footprint says, over level 0.
                const int span = 1 << level;
                const double block =
                    farthestOver(img, (r.x0 / span) * span, (r.y0 / span) * span,
                                 (r.x1 / span + 1) * span - 1, (r.y1 / span + 1) * span - 1);
                ASSERT_EQ(result.may_be_visible, !(block < znear))
                    << "block farthest " << block << " znear " << znear;
                EXPECT_LE(result.texels_read, 4);
                EXPECT_GE(result.texels_read, 1);
            }
        });
    }
    if (!test::singleSeedRun()) {
        EXPECT_GE(queries, 8000);
        EXPECT_GT(hidden, queries / 10) << "the query must cull, not only say visible";
        // Hidden by the block implies hidden by the rectangle (empty rectangles apart).
        EXPECT_LE(hidden - empty, hidden_by_rect_alone);
        EXPECT_LT(empty, queries / 10);
    }
}

TEST(ZPyramid, EdgeCasesOfTheQuery) {
    ZPyramid pyramid;
    EXPECT_TRUE(pyramid.boxMayBeVisible({0, 0, 3, 3}, 1.0));  // nothing built yet
    const std::vector<double> depths(7 * 5, 10.0);
    pyramid.build(7, 5, depths.data());
    EXPECT_FALSE(pyramid.boxMayBeVisible({0, 0, 6, 4}, 10.5));  // all nearer
    EXPECT_TRUE(pyramid.boxMayBeVisible({0, 0, 6, 4}, 10.0));   // a tie: visible
    EXPECT_TRUE(pyramid.boxMayBeVisible({2, 2, 2, 2}, std::numeric_limits<double>::quiet_NaN()));
    EXPECT_FALSE(pyramid.boxMayBeVisible({8, 0, 9, 4}, 0.0));  // off the image: no pixel sees it
    EXPECT_FALSE(pyramid.boxMayBeVisible({}, 0.0));            // empty
    EXPECT_FALSE(pyramid.boxMayBeVisible({-50, -50, 50, 50}, 11.0));  // clipped to the image
}

// The shared rasterizer draws a wall over the left half of the view at depth 5;
// boxes are mapped with ScreenMapping, as the culler will.
TEST(ZPyramid, CullsABoxBehindANearWall) {
    Camera camera;
    camera.position = {0, 0, 0};
    camera.target = {0, 0, 1};
    camera.up = {0, 1, 0};
    camera.fov_deg = 60.0;
    camera.aspect = 16.0 / 9.0;
    IdDepthBuffer buffer;
    buffer.resize(160, 90);
    buffer.begin(camera);
    ASSERT_TRUE(buffer.drawBox(0, {{-30, -30, 5}, {0, 30, 5.5}}));
    ZPyramid pyramid;
    pyramid.build(buffer);
    ScreenMapping mapping;
    mapping.set(camera, 160, 90);
    // The wall holds world x in [-30, 0]; a box at x in [-3, -1] behind it is hidden.
    const Aabb behind_wall{{-3, -1, 10}, {-1, 1, 11}};
    const BoxOnScreen hidden = mapping.project(behind_wall);
    ASSERT_FALSE(hidden.rect.empty());
    EXPECT_FALSE(pyramid.boxMayBeVisible(hidden));
    // The same box in front of the wall, beside it, or reaching past its edge.
    EXPECT_TRUE(pyramid.boxMayBeVisible(mapping.project({{-3, -1, 2}, {-1, 1, 3}})));
    EXPECT_TRUE(pyramid.boxMayBeVisible(mapping.project({{1, -1, 10}, {3, 1, 11}})));
    EXPECT_TRUE(pyramid.boxMayBeVisible(mapping.project({{-3, -1, 10}, {1, 1, 11}})));
    // Rebuilding at the same size keeps every buffer: no allocation per frame.
    const double* level0 = pyramid.level(0).data;
    const double* top = pyramid.level(pyramid.levelCount() - 1).data;
    buffer.begin(camera);
    pyramid.build(buffer);
    EXPECT_EQ(pyramid.level(0).data, level0);
    EXPECT_EQ(pyramid.level(pyramid.levelCount() - 1).data, top);
    EXPECT_TRUE(pyramid.boxMayBeVisible(hidden));  // the wall is gone
}

}  // namespace
}  // namespace gridcull
