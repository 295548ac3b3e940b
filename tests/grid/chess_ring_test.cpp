#include "grid/chess_ring.h"

#include <set>
#include <utility>

#include <gtest/gtest.h>

namespace gridcull {
namespace {

TEST(ChessRing, IndexAndOffsetAreInversesOverTheWholeRing) {
    for (int64_t k = 0; k <= 40; ++k) {
        std::set<std::pair<int64_t, int64_t>> seen;
        for (int64_t p = 0; p < ringSize(k); ++p) {
            const glm::i64vec2 v = ringOffset(k, p);
            ASSERT_EQ(chessDistance(v), k);
            ASSERT_EQ(ringIndex(v), p) << "k " << k << " p " << p;
            seen.insert({v.x, v.y});
        }
        ASSERT_EQ(int64_t(seen.size()), ringSize(k));
        // Every voxel at chess distance k is on the ring.
        int64_t count = 0;
        for (int64_t y = -k; y <= k; ++y)
            for (int64_t x = -k; x <= k; ++x) count += chessDistance({x, y}) == k;
        ASSERT_EQ(count, ringSize(k));
    }
    EXPECT_EQ(ringOffset(3, 0), glm::i64vec2(3, -3));
    EXPECT_EQ(ringOffset(3, -1), ringOffset(3, 23));  // indices wrap
}

TEST(ChessRing, SixRulesStepAlongThePerimeter) {
    for (int64_t k = 1; k <= 30; ++k) {
        for (int64_t p = 0; p < ringSize(k); ++p) {
            const glm::i64vec2 v = ringOffset(k, p);
            glm::i64vec2 ccw, cw;
            chessRingDirections(v, ccw, cw);
            ASSERT_EQ(v + ccw, ringOffset(k, p + 1)) << "k " << k << " p " << p;
            ASSERT_EQ(v + cw, ringOffset(k, p - 1)) << "k " << k << " p " << p;
        }
    }
    // The rules as the paper states them, at the corners of ring 2.
    glm::i64vec2 a, b;
    chessRingDirections({2, 2}, a, b);  // rule 3: -x and -y
    EXPECT_EQ(a, glm::i64vec2(-1, 0));
    EXPECT_EQ(b, glm::i64vec2(0, -1));
    chessRingDirections({-2, -2}, a, b);  // rule 4: +x and +y
    EXPECT_EQ(a, glm::i64vec2(1, 0));
    EXPECT_EQ(b, glm::i64vec2(0, 1));
    chessRingDirections({-2, 2}, a, b);  // rule 5: +x and -y
    EXPECT_EQ(a, glm::i64vec2(0, -1));
    EXPECT_EQ(b, glm::i64vec2(1, 0));
    chessRingDirections({2, -2}, a, b);  // rule 6: -x and +y
    EXPECT_EQ(a, glm::i64vec2(0, 1));
    EXPECT_EQ(b, glm::i64vec2(-1, 0));
}

TEST(ChessRing, HugeRingsDoNotOverflow) {
    const int64_t k = 3000000000LL;  // beyond 32 bits
    const glm::i64vec2 v{-k, 12345};
    EXPECT_EQ(ringOffset(k, ringIndex(v)), v);
}

}  // namespace
}  // namespace gridcull
