// What `gridcull bench` measures, kept apart from how it is printed: per algorithm
// and frame the cull time of every run (and with --draw the draw time), and
// (from the first run) the PVS size, the exact visible count, the false culls
// and the counters.
//
// A frame's time is cull + draw of one run. Per frame, bench reports the median
// over runs; for cull, draw and frame together (the CSV) it reports the run
// whose frame time is that median (the lower middle one for an even count), so
// that its cull + draw is its frame.
#pragma once
#include <string>
#include <vector>

#include "culling/api/counters.h"
#include "culling/api/culler.h"
#include "culling/scene/scene.h"

namespace gridcull {

struct AlgoBench {
    std::string algo;
    std::vector<double> ms;                // cull: [run * frames + frame]
    std::vector<double> draw_ms;           // [run * frames + frame]; empty without --draw
    std::vector<int> pvs_size;             // [frame]
    std::vector<long long> pvs_triangles;  // [frame]: triangles of the PVS's objects
    std::vector<int> exact_size;           // [frame], -1 when quality was not measured
    std::vector<int> false_culls;          // [frame]: ids exact sees that the PVS lacks
    std::vector<CullStats> stats;          // [frame], from the first run
};

struct BenchSummary {
    double median_ms = 0.0;  // median over frames of each frame's median over runs
    double mean_ms = 0.0;    // mean over frames of each frame's median over runs
    double p95_ms = 0.0;     // 95th percentile over frames of the per-frame medians
    // With drawing (zero without): the same statistics of draw and of frame
    // (cull + draw, one run's) times.
    double median_draw_ms = 0.0, p95_draw_ms = 0.0;
    double median_frame_ms = 0.0, p95_frame_ms = 0.0;
    double mean_pvs = 0.0;
    double mean_pvs_triangles = 0.0;
    double mean_exact = -1.0;     // -1 without quality
    double pvs_over_exact = 0.0;  // sum of PVS sizes / sum of exact sizes
    long long false_culls = 0;
    int frames_with_false_culls = 0;
    std::vector<std::pair<Counter, double>> counter_means;  // per frame
    // Round trips to the image per frame: pixel_queries + occlusion_queries (a
    // read-back or a query object each on a GPU).
    double mean_queries = 0.0;
};

// The query cost model: the frame's measured time (cull, or cull + draw when
// drawn) plus `queries` round trips of `cost_us` microseconds each, the regime
// where a query waits for the GPU (a glReadPixels round
// trip of microseconds) rather than reading memory (about 0.1 us here). The
// measured part keeps this machine's own query cost, which overstates the model
// by at most queries x that.
double modelledFrameMs(const BenchSummary& s, bool drawn, double cost_us);

// Keeps the first run's quality of one frame in `b`: the PVS's size, triangles
// and counters, and against `exact` (null without quality) its size and the
// false culls (ids exact sees that the PVS lacks; both sorted).
void recordFrame(const Scene& scene, int frame, const FrameResult& result,
                 const FrameResult* exact, AlgoBench& b);
// Sizes b's per-frame tables for `frames` frames and `runs` runs, with draw
// times when `drawn`.
void sizeBench(AlgoBench& b, int frames, int runs, bool drawn);

// The median over runs of one frame's cull time.
double frameMedianMs(const AlgoBench& bench, int frame, int frames, int runs);
// The run whose cull + draw time of `frame` is the median over runs (the lower
// middle one for an even count); drawn benches only.
int medianFrameRun(const AlgoBench& bench, int frame, int frames, int runs);
BenchSummary summarize(const AlgoBench& bench, int frames, int runs);

// The side-by-side table printed on standard output. Times are compared with
// row `baseline` (an index into `benches`) in a column "x NAME", and, when
// `limit` is a row (>= 0), with it too.
// With `query_cost_us` >= 0, a column "model ms" of modelledFrameMs.
std::string formatBenchTable(const std::vector<AlgoBench>& benches, int frames, int runs,
                             size_t baseline = 0, int limit = -1, double query_cost_us = -1.0);
// CSV, one row per algorithm and frame, with a header; counters as columns.
std::string formatBenchCsv(const std::vector<AlgoBench>& benches, int frames, int runs, double dt);

}  // namespace gridcull
