#include "grid/bresenham.h"

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "culling/scene/seeded_random.h"
#include "grid/chess_ring.h"

namespace gridcull {
namespace {

TEST(BresenhamLine, OneVoxelPerChessLayerAndEightConnected) {
    SeededRandom rng(5);
    for (int trial = 0; trial < 300; ++trial) {
        const glm::i64vec2 delta{int64_t(rng.below(2001)) - 1000, int64_t(rng.below(2001)) - 1000};
        const BresenhamLine line(delta);
        glm::i64vec2 prev = line.at(0);
        EXPECT_EQ(prev, glm::i64vec2(0, 0));
        for (int64_t k = 1; k <= 300; ++k) {
            const glm::i64vec2 p = line.at(k);
            ASSERT_EQ(chessDistance(p), k) << "delta " << delta.x << "," << delta.y;
            ASSERT_EQ(chessDistance(p - prev), 1);
            prev = p;
        }
    }
}

TEST(BresenhamLine, StaysWithinHalfAVoxelOfTheLine) {
    SeededRandom rng(6);
    for (int trial = 0; trial < 300; ++trial) {
        const double angle = rng.uniform(0.0, 6.283185307179586);
        const double dx = std::cos(angle), dy = std::sin(angle);
        const BresenhamLine line = BresenhamLine::towards(dx, dy);
        for (int64_t k = 0; k <= 500; k += 7) {
            const glm::i64vec2 p = line.at(k);
            // Distance along the minor axis from the ideal line through (0, 0).
            const double err = std::abs(dx) >= std::abs(dy) ? std::abs(double(p.y) - p.x * dy / dx)
                                                            : std::abs(double(p.x) - p.y * dx / dy);
            ASSERT_LE(err, 0.5 + 1e-6);
        }
    }
}

TEST(BresenhamLine, SegmentVisitsBothEndsInOrder) {
    std::vector<std::pair<int64_t, int64_t>> seen;
    bresenhamSegment({2, 3}, {9, -1}, [&](int64_t x, int64_t y) { seen.push_back({x, y}); });
    ASSERT_EQ(seen.size(), size_t(8));
    EXPECT_EQ(seen.front(), std::make_pair(int64_t(2), int64_t(3)));
    EXPECT_EQ(seen.back(), std::make_pair(int64_t(9), int64_t(-1)));
}

// As BresenhamLine3's: subnormal directions (2^24 / m alone overflows),
// huge ones, and directions with no direction (zero, NaN, infinite) give +x.
TEST(BresenhamLine, TowardsTinyHugeAndDegenerateDirections) {
    const int64_t one = int64_t(1) << 24;
    const double huge = DBL_MAX, tiny = std::numeric_limits<double>::denorm_min();
    struct Case {
        double x, y;
        glm::i64vec2 delta;
    };
    const Case cases[] = {
        {tiny, 0.0, {one, 0}},
        {0.0, -tiny, {0, -one}},
        {1e-310, -2e-310, {one / 2, -one}},
        {1e-300, 3e-300, {std::llround(one / 3.0), one}},
        {huge, -huge, {one, -one}},
        {1e300, 1e-300, {one, 0}},
        {0.0, 0.0, {1, 0}},
        {std::nan(""), 1.0, {1, 0}},
        {1.0, std::nan(""), {1, 0}},
        {1.0, std::numeric_limits<double>::infinity(), {1, 0}},
    };
    for (const Case& c : cases) {
        const BresenhamLine line = BresenhamLine::towards(c.x, c.y);
        EXPECT_EQ(line.delta(), c.delta) << c.x << "," << c.y;
        EXPECT_EQ(chessDistance(line.at(1000000)), 1000000);
    }
}

TEST(BresenhamCircle4, ClosedFourConnectedSimpleAndNearTheRadius) {
    for (int r = 0; r <= 150; ++r) {
        std::vector<glm::i64vec2> curve;
        bresenhamCircle4(r, [&](int64_t x, int64_t y) { curve.push_back({x, y}); });
        ASSERT_EQ(curve.size(), size_t(r == 0 ? 1 : 8 * r)) << "r " << r;
        std::set<std::pair<int64_t, int64_t>> unique;
        for (size_t i = 0; i < curve.size(); ++i) {
            const glm::i64vec2 a = curve[i], b = curve[(i + 1) % curve.size()];
            unique.insert({a.x, a.y});
            const int64_t rr = int64_t(r) * r, d2 = a.x * a.x + a.y * a.y;
            if (r > 0) {
                // 4-connected: consecutive voxels share an edge, the last with the first.
                ASSERT_EQ(std::llabs(a.x - b.x) + std::llabs(a.y - b.y), 1)
                    << "r " << r << " i " << i;
                ASSERT_GT(d2, (r - 1) * (r - 1)) << "r " << r;
                ASSERT_LE(d2, rr + 2 * r + 1) << "r " << r;
            }
        }
        ASSERT_EQ(unique.size(), curve.size()) << "r " << r;
        ASSERT_EQ(curve.front(), glm::i64vec2(r, 0));
    }
}

}  // namespace
}  // namespace gridcull
