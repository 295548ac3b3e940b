// OcclusionBuffer::countFree (culling/raster/occlusion_buffer.cpp) against a
// pixel-by-pixel count, on seeded random bit patterns and rectangles (inside one
// word, across words, clipped at the image borders): both of its popcount paths,
// the POPCNT one chosen at run time on this CPU (countFree) and the portable
// SWAR one (countFreeSwar), must give the exact count. GRIDCULL_SEED=N replays one seed.
#include <algorithm>

#include <gtest/gtest.h>

#include "culling/raster/occlusion_buffer.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/test_seeds.h"

namespace gridcull {
namespace {

TEST(OcclusionBufferCount, BothPopcountPathsCountEveryFreePixelExactly) {
    for (uint64_t seed : test::seedsToRun(1, 200)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const int width = 1 + int(rng.below(300)), height = 1 + int(rng.below(80));
            OcclusionBuffer buffer;
            buffer.resize(width, height);
            buffer.clear();
            const int marks = int(rng.below(40));
            for (int k = 0; k < marks; ++k) {
                const int x0 = int(rng.below(uint64_t(width))), y0 = int(rng.below(uint64_t(height)));
                const int w = int(rng.below(uint64_t(width))) / 3, h = int(rng.below(uint64_t(height))) / 3;
                buffer.markOccluded({x0, y0, x0 + w, y0 + h});
            }
            for (int q = 0; q < 30; ++q) {
                const int x0 = int(rng.below(uint64_t(width + 20))) - 10;
                const int y0 = int(rng.below(uint64_t(height + 20))) - 10;
                const PixelRect rect{x0, y0, x0 + int(rng.below(140)), y0 + int(rng.below(40))};
                long long free = 0;
                for (int py = std::max(0, rect.y0); py <= std::min(height - 1, rect.y1); ++py)
                    for (int px = std::max(0, rect.x0); px <= std::min(width - 1, rect.x1); ++px)
                        free += buffer.occluded(px, py) ? 0 : 1;
                EXPECT_EQ(buffer.countFree(rect), free);
                EXPECT_EQ(buffer.countFreeSwar(rect), free);
            }
        });
    }
}

}  // namespace
}  // namespace gridcull
