// What `gridcull bench` measures, kept apart from how it is printed: per algorithm
// and frame the cull time of every run, and (from the first run) the PVS size, the
// exact visible count, the false culls and the counters.
#pragma once
#include <string>
#include <vector>

#include "culling/api/counters.h"

namespace gridcull {

struct AlgoBench {
    std::string algo;
    std::vector<double> ms;                // [run * frames + frame]
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
    double mean_pvs = 0.0;
    double mean_pvs_triangles = 0.0;
    double mean_exact = -1.0;     // -1 without quality
    double pvs_over_exact = 0.0;  // sum of PVS sizes / sum of exact sizes
    long long false_culls = 0;
    int frames_with_false_culls = 0;
    std::vector<std::pair<Counter, double>> counter_means;  // per frame
};

// The median over runs of one frame's cull time.
double frameMedianMs(const AlgoBench& bench, int frame, int frames, int runs);
BenchSummary summarize(const AlgoBench& bench, int frames, int runs);

// The side-by-side table printed on standard output.
std::string formatBenchTable(const std::vector<AlgoBench>& benches, int frames, int runs);
// CSV, one row per algorithm and frame, with a header; counters as columns.
std::string formatBenchCsv(const std::vector<AlgoBench>& benches, int frames, int runs, double dt);

}  // namespace gridcull
