// BresenhamLine3: one voxel per chess layer, 26-connected, within half a voxel of
// its line, the 2D line in the plane z = 0, symmetric under sign flips, and
// towards() safe for directions of any magnitude.
#include "grid/bresenham3d.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <limits>

#include <gtest/gtest.h>

#include "culling/scene/seeded_random.h"
#include "grid/bresenham.h"

namespace gridcull {
namespace {

// towards() keeps each slope to 24 bits: the minor components are rounded to
// integers against a dominant one of 2^24, a slope error of at most 2^-25 per step.
constexpr double kSlopeErrorPerStep = 1.0 / (1 << 25);
// Double rounding in the test's own evaluation of the real line.
constexpr double kEvalTolerance = 1e-9;

__extension__ typedef __int128 Int128;

int64_t chessDistance3(glm::i64vec3 p) {
    return std::max({std::llabs(p.x), std::llabs(p.y), std::llabs(p.z)});
}

int majorAxis(glm::i64vec3 delta) {
    const int64_t ax = std::llabs(delta.x), ay = std::llabs(delta.y), az = std::llabs(delta.z);
    return ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
}

// The k-th voxel by the defining rule, in 128-bit arithmetic: the minor
// coordinate is k * |minor| / |major| rounded to nearest, halves away from zero.
glm::i64vec3 referenceAt(glm::i64vec3 delta, int64_t k) {
    const int major = majorAxis(delta);
    const Int128 am = std::llabs(delta[major]);
    glm::i64vec3 p;
    for (int i = 0; i < 3; ++i) {
        const Int128 a = std::llabs(delta[i]);
        const Int128 step = i == major ? Int128(k) : (2 * Int128(k) * a + am) / (2 * am);
        p[i] = int64_t(delta[i] < 0 ? -step : step);
    }
    return p;
}

glm::i64vec3 randomDelta(SeededRandom& rng, int64_t limit) {
    glm::i64vec3 d;
    for (int i = 0; i < 3; ++i) d[i] = int64_t(rng.below(uint64_t(2 * limit + 1))) - limit;
    return d;
}

TEST(BresenhamLine3, OneVoxelPerChessLayerAndTwentySixConnected) {
    SeededRandom rng(41);
    for (int trial = 0; trial < 200; ++trial) {
        // Small deltas give many exact ties and equal components; large ones long runs.
        const glm::i64vec3 delta = randomDelta(rng, trial % 2 == 0 ? 6 : 1 << 24);
        const BresenhamLine3 line(delta);
        SCOPED_TRACE(::testing::Message()
                     << "delta " << delta.x << "," << delta.y << "," << delta.z);
        glm::i64vec3 prev = line.at(0);
        ASSERT_EQ(prev, glm::i64vec3(0, 0, 0));
        for (int64_t k = 1; k <= 2000; ++k) {
            const glm::i64vec3 p = line.at(k);
            ASSERT_EQ(chessDistance3(p), k);
            ASSERT_EQ(chessDistance3(p - prev), 1) << "k " << k;
            prev = p;
        }
        // Far along the line: pairs of consecutive voxels up to k = 1e6.
        for (int sample = 0; sample < 200; ++sample) {
            const int64_t k = int64_t(rng.below(1000001));
            const glm::i64vec3 p = line.at(k), q = line.at(k + 1);
            ASSERT_EQ(chessDistance3(p), k);
            ASSERT_EQ(chessDistance3(q - p), 1) << "k " << k;
        }
    }
}

TEST(BresenhamLine3, LargeStepsMatchTheRuleWithoutOverflow) {
    SeededRandom rng(42);
    const int64_t big_ks[] = {(int64_t(1) << 31) - 1, int64_t(1) << 31,
                              (int64_t(1) << 31) + 1, (int64_t(1) << 31) + 987654321,
                              int64_t(1) << 40,       (int64_t(1) << 62) + 12345};
    for (int trial = 0; trial < 300; ++trial) {
        // Up to the largest delta the constructor takes, where 2 * k * minor
        // alone would overflow for k >= 2^31.
        const int64_t limit =
            trial % 3 == 0 ? BresenhamLine3::kMaxComponent : (trial % 3 == 1 ? 1 << 24 : 1000);
        const glm::i64vec3 delta = randomDelta(rng, limit);
        const BresenhamLine3 line(delta);
        for (const int64_t k : big_ks) {
            const glm::i64vec3 p = line.at(k);
            ASSERT_EQ(p, referenceAt(line.delta(), k))
                << "delta " << delta.x << "," << delta.y << "," << delta.z << " k " << k;
            ASSERT_EQ(chessDistance3(p), k);
            ASSERT_EQ(chessDistance3(line.at(k + 1) - p), 1);
        }
    }
}

TEST(BresenhamLine3, StaysWithinHalfAVoxelOfItsIntegerLine) {
    SeededRandom rng(43);
    for (int trial = 0; trial < 300; ++trial) {
        const glm::i64vec3 delta = randomDelta(rng, trial % 2 == 0 ? 20 : 1 << 24);
        const BresenhamLine3 line(delta);
        const int major = majorAxis(line.delta());
        const int64_t am = std::llabs(line.delta()[major]);
        for (int64_t k = 0; k <= 1000000; k += 1 + int64_t(rng.below(5000))) {
            const glm::i64vec3 p = line.at(k);
            // |p_i - k * delta_i / |delta_major|| <= 1/2, exactly, in integers.
            for (int i = 0; i < 3; ++i) {
                const Int128 twice_error = 2 * Int128(p[i]) * am - 2 * Int128(k) * line.delta()[i];
                ASSERT_LE(twice_error < 0 ? -twice_error : twice_error, Int128(am))
                    << "delta " << delta.x << "," << delta.y << "," << delta.z << " k " << k;
            }
        }
    }
}

TEST(BresenhamLine3, StaysWithinHalfAVoxelOfTheRealDirection) {
    SeededRandom rng(44);
    for (int trial = 0; trial < 300; ++trial) {
        const glm::dvec3 dir = randomDirection(rng, 3);
        const BresenhamLine3 line = BresenhamLine3::towards(dir.x, dir.y, dir.z);
        const int major = majorAxis(line.delta());
        for (int64_t k = 0; k <= 2000; k += 7) {
            const glm::i64vec3 p = line.at(k);
            const double t = double(k) / std::abs(dir[major]);
            for (int i = 0; i < 3; ++i) {
                const double err = std::abs(double(p[i]) - t * dir[i]);
                ASSERT_LE(err, 0.5 + double(k) * kSlopeErrorPerStep + kEvalTolerance)
                    << "dir " << dir.x << "," << dir.y << "," << dir.z << " k " << k;
            }
        }
    }
}

TEST(BresenhamLine3, IsTheTwoDimensionalLineWhenZIsZero) {
    SeededRandom rng(45);
    for (int trial = 0; trial < 300; ++trial) {
        const glm::i64vec3 d3 = randomDelta(rng, trial % 2 == 0 ? 9 : 1 << 24);
        const glm::i64vec2 d2{d3.x, d3.y};
        const BresenhamLine line2(d2);
        const BresenhamLine3 line3({d3.x, d3.y, 0});
        for (int64_t k = 0; k <= 3000; k += 1 + int64_t(rng.below(20))) {
            const glm::i64vec2 p2 = line2.at(k);
            ASSERT_EQ(line3.at(k), glm::i64vec3(p2.x, p2.y, 0))
                << "delta " << d2.x << "," << d2.y << " k " << k;
        }
        const double angle = rng.uniform(0.0, 6.283185307179586);
        const glm::i64vec2 t2 = BresenhamLine::towards(std::cos(angle), std::sin(angle)).delta();
        EXPECT_EQ(BresenhamLine3::towards(std::cos(angle), std::sin(angle), 0.0).delta(),
                  glm::i64vec3(t2.x, t2.y, 0));
    }
    // Both take the zero delta as +x.
    EXPECT_EQ(BresenhamLine3({0, 0, 0}).at(5), glm::i64vec3(5, 0, 0));
}

TEST(BresenhamLine3, FlippingSignsOfTheDeltaFlipsTheVoxels) {
    SeededRandom rng(46);
    for (int trial = 0; trial < 200; ++trial) {
        const glm::i64vec3 delta = randomDelta(rng, trial % 2 == 0 ? 7 : 1 << 24);
        const BresenhamLine3 line(delta);
        for (int flips = 1; flips < 8; ++flips) {
            const glm::i64vec3 s{flips & 1 ? -1 : 1, flips & 2 ? -1 : 1, flips & 4 ? -1 : 1};
            const BresenhamLine3 mirrored(s * delta);
            for (int64_t k = 0; k <= 500; k += 1 + int64_t(rng.below(9)))
                ASSERT_EQ(mirrored.at(k), s * line.at(k))
                    << "delta " << delta.x << "," << delta.y << "," << delta.z << " flips " << flips
                    << " k " << k;
        }
    }
}

TEST(BresenhamLine3, TowardsTinyHugeAndDegenerateDirections) {
    const int64_t one = int64_t(1) << 24;
    const double huge = DBL_MAX, tiny = std::numeric_limits<double>::denorm_min();
    struct Case {
        double x, y, z;
        glm::i64vec3 delta;
    };
    const Case cases[] = {
        {tiny, 0.0, 0.0, {one, 0, 0}},  // 2^24 / tiny alone overflows
        {0.0, -tiny, tiny, {0, -one, one}},
        {1e-310, -1e-310, 2e-310, {one / 2, -one / 2, one}},
        {1e-300, 3e-300, -2e-300, {std::llround(one / 3.0), one, -std::llround(2.0 * one / 3.0)}},
        {huge, -huge, huge, {one, -one, one}},
        {1e300, 1.0, 1e-300, {one, 0, 0}},  // minor components below 2^-25 vanish
        {-huge, 1e300, 0.0, {-one, 0, 0}},
        {0.0, 0.0, 0.0, {1, 0, 0}},
        {std::nan(""), 1.0, 0.0, {1, 0, 0}},
        {1.0, std::numeric_limits<double>::infinity(), 0.0, {1, 0, 0}},
    };
    for (const Case& c : cases) {
        const BresenhamLine3 line = BresenhamLine3::towards(c.x, c.y, c.z);
        EXPECT_EQ(line.delta(), c.delta) << c.x << "," << c.y << "," << c.z;
        EXPECT_EQ(chessDistance3(line.at(1000000)), 1000000);
        EXPECT_EQ(chessDistance3(line.at(int64_t(1) << 31)), int64_t(1) << 31);
    }
}

}  // namespace
}  // namespace gridcull
