#include "grid/bit_matrix.h"

#include <vector>

#include <gtest/gtest.h>

#include "culling/scene/seeded_random.h"

namespace gridcull {
namespace {

TEST(BitMatrix, SetGetResetAndCount) {
    BitMatrix m(70, 3);
    EXPECT_EQ(m.count(), 0);
    m.set(0, 0);
    m.set(63, 1);
    m.set(64, 1);
    m.set(69, 2);
    EXPECT_TRUE(m.get(0, 0));
    EXPECT_TRUE(m.get(63, 1));
    EXPECT_TRUE(m.get(64, 1));
    EXPECT_TRUE(m.get(69, 2));
    EXPECT_FALSE(m.get(1, 0));
    EXPECT_FALSE(m.get(63, 0));
    EXPECT_EQ(m.count(), 4);
    m.reset(63, 1);
    EXPECT_FALSE(m.get(63, 1));
    EXPECT_EQ(m.count(), 3);
    m.clearAll();
    EXPECT_EQ(m.count(), 0);
}

TEST(BitMatrix, SetRunMatchesBitByBitAcrossWordBoundaries) {
    SeededRandom rng(3);
    for (int trial = 0; trial < 500; ++trial) {
        const int width = 1 + int(rng.below(200));
        BitMatrix m(width, 2);
        std::vector<char> naive(size_t(width), 0);
        for (int run = 0; run < 4; ++run) {
            const int a = int(rng.below(uint64_t(width))), b = int(rng.below(uint64_t(width)));
            const int x0 = std::min(a, b), x1 = std::max(a, b);
            m.setRun(1, x0, x1);
            for (int x = x0; x <= x1; ++x) naive[size_t(x)] = 1;
        }
        m.setRun(1, 5, 4);  // empty run: no-op
        for (int x = 0; x < width; ++x) {
            ASSERT_EQ(m.get(x, 1), naive[size_t(x)] != 0) << "width " << width << " x " << x;
            ASSERT_FALSE(m.get(x, 0));  // the other row is untouched
        }
    }
}

TEST(BitMatrix, CopyFromAndMemory) {
    BitMatrix a(256, 256), b(256, 256);
    a.set(10, 20);
    a.setRun(255, 0, 255);
    b.set(1, 1);
    b.copyFrom(a);
    EXPECT_TRUE(b.get(10, 20));
    EXPECT_FALSE(b.get(1, 1));
    EXPECT_EQ(b.count(), 257);
    // 256 x 256 bits = 8 KiB.
    EXPECT_EQ(a.memoryBytes(), size_t(8192));
    a.release();
    EXPECT_EQ(a.memoryBytes(), size_t(0));
    EXPECT_TRUE(a.empty());
}

}  // namespace
}  // namespace gridcull
