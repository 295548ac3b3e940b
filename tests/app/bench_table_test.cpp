// What bench prints from its measurements (app/bench_table.h), on synthetic
// tables: the frame statistics with drawing, the run whose frame time is the
// median, and the query cost model.
#include <gtest/gtest.h>

#include "app/bench_table.h"

namespace gridcull {
namespace {

// One algorithm, 2 frames, 3 runs; cull and draw times chosen per (run, frame).
AlgoBench twoFramesThreeRuns() {
    AlgoBench b;
    b.algo = "x";
    // [run * frames + frame]
    b.ms = {1.0, 2.0, /*run 1*/ 3.0, 1.0, /*run 2*/ 2.0, 9.0};
    b.draw_ms = {5.0, 1.0, /*run 1*/ 0.5, 4.0, /*run 2*/ 1.0, 1.0};
    b.pvs_size = {10, 20};
    b.pvs_triangles = {100, 200};
    b.exact_size = {5, 10};
    b.false_culls = {0, 0};
    b.stats.assign(2, CullStats{});
    b.stats[0].set(Counter::PixelQueries, 100);
    b.stats[1].set(Counter::PixelQueries, 300);
    return b;
}

TEST(BenchTable, TheMedianRunsCullAndDrawMakeItsFrame) {
    const AlgoBench b = twoFramesThreeRuns();
    // Frame 0: frames 6, 3.5, 3 -> the median is run 1 (3.5).
    EXPECT_EQ(medianFrameRun(b, 0, 2, 3), 1);
    // Frame 1: frames 3, 5, 10 -> run 1 (5).
    EXPECT_EQ(medianFrameRun(b, 1, 2, 3), 1);
    const BenchSummary s = summarize(b, 2, 3);
    EXPECT_DOUBLE_EQ(s.median_ms, (2.0 + 2.0) / 2);       // cull medians 2 and 2
    EXPECT_DOUBLE_EQ(s.median_draw_ms, (1.0 + 1.0) / 2);  // draw medians 1 and 1
    EXPECT_DOUBLE_EQ(s.median_frame_ms, (3.5 + 5.0) / 2);
    EXPECT_DOUBLE_EQ(s.p95_frame_ms, 5.0);
}

TEST(BenchTable, TheQueryCostModelAddsEachRoundTrip) {
    const BenchSummary s = summarize(twoFramesThreeRuns(), 2, 3);
    EXPECT_DOUBLE_EQ(s.mean_queries, 200.0);
    // 200 queries of 50 us: 10 ms over the measured time.
    EXPECT_DOUBLE_EQ(modelledFrameMs(s, false, 50.0), s.median_ms + 10.0);
    EXPECT_DOUBLE_EQ(modelledFrameMs(s, true, 50.0), s.median_frame_ms + 10.0);
    EXPECT_DOUBLE_EQ(modelledFrameMs(s, true, 0.0), s.median_frame_ms);
}

}  // namespace
}  // namespace gridcull
