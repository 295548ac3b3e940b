#include "app/bench_table.h"

#include <algorithm>
#include <cassert>
#include <cstdio>

namespace gridcull {

namespace {

double medianOf(std::vector<double>& values) {
    assert(!values.empty());
    const size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + mid, values.end());
    double m = values[mid];
    if (values.size() % 2 == 0) {
        m = (m + *std::max_element(values.begin(), values.begin() + mid)) * 0.5;
    }
    return m;
}

std::string format(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

}  // namespace

double frameMedianMs(const AlgoBench& bench, int frame, int frames, int runs) {
    std::vector<double> values(static_cast<size_t>(runs));
    for (int r = 0; r < runs; ++r) values[size_t(r)] = bench.ms[size_t(r * frames + frame)];
    return medianOf(values);
}

BenchSummary summarize(const AlgoBench& bench, int frames, int runs) {
    BenchSummary s;
    std::vector<double> medians(static_cast<size_t>(frames));
    for (int f = 0; f < frames; ++f) medians[size_t(f)] = frameMedianMs(bench, f, frames, runs);
    double sum = 0.0;
    for (double m : medians) sum += m;
    s.mean_ms = sum / frames;
    std::vector<double> sorted = medians;
    std::sort(sorted.begin(), sorted.end());
    s.p95_ms = sorted[std::min(sorted.size() - 1, size_t(0.95 * double(sorted.size())))];
    s.median_ms = medianOf(medians);

    long long pvs_sum = 0, exact_sum = 0;
    bool quality = true;
    for (int f = 0; f < frames; ++f) {
        pvs_sum += bench.pvs_size[size_t(f)];
        if (size_t(f) < bench.pvs_triangles.size())
            s.mean_pvs_triangles += double(bench.pvs_triangles[size_t(f)]) / frames;
        if (bench.exact_size[size_t(f)] < 0) quality = false;
        exact_sum += bench.exact_size[size_t(f)];
        s.false_culls += bench.false_culls[size_t(f)];
        if (bench.false_culls[size_t(f)] > 0) ++s.frames_with_false_culls;
    }
    s.mean_pvs = double(pvs_sum) / frames;
    if (quality) {
        s.mean_exact = double(exact_sum) / frames;
        s.pvs_over_exact = exact_sum > 0 ? double(pvs_sum) / double(exact_sum) : 0.0;
    }
    for (int c = 0; c < kCounterCount; ++c) {
        if (!bench.stats.front().has(Counter(c))) continue;
        double total = 0.0;
        for (const CullStats& st : bench.stats) total += double(st.get(Counter(c)));
        s.counter_means.emplace_back(Counter(c), total / frames);
    }
    return s;
}

std::string formatBenchTable(const std::vector<AlgoBench>& benches, int frames, int runs) {
    std::vector<BenchSummary> sums;
    for (const auto& b : benches) sums.push_back(summarize(b, frames, runs));
    // Ratios against the first algorithm listed: on a shared, noisy machine the
    // ratio of two algorithms timed in the same run is what holds.
    const double base = sums.front().median_ms;
    // The algo column fits the longest label (entries like NAME:FLAG=VALUE).
    int width = 14;
    for (const auto& b : benches) width = std::max(width, int(b.algo.size()));
    std::string out;
    char line[1024];
    std::snprintf(line, sizeof line, "%-*s %10s %10s %10s %9s %9s %9s %10s %9s %10s  %s\n", width,
                  "algo", "median ms", "p95 ms",
                  ("x " + benches.front().algo).substr(0, 10).c_str(), "pvs", "exact", "pvs/exact",
                  "false cull", "fc frames", "pvs tris", "counters (mean per frame)");
    out += line;
    for (size_t i = 0; i < benches.size(); ++i) {
        const BenchSummary& s = sums[i];
        std::string counters;
        for (const auto& [counter, mean] : s.counter_means) {
            counters += std::string(counters.empty() ? "" : " ") + counterName(counter) + "=" +
                        format("%.6g", mean);
        }
        const std::string ratio = base > 0.0 ? format("%.3g", s.median_ms / base) : "-";
        const std::string exact = s.mean_exact >= 0 ? format("%.1f", s.mean_exact) : "-";
        const std::string over = s.mean_exact >= 0 ? format("%.3f", s.pvs_over_exact) : "-";
        const std::string fc = s.mean_exact >= 0 ? std::to_string(s.false_culls) : "-";
        std::snprintf(line, sizeof line,
                      "%-*s %10.4g %10.4g %10s %9.1f %9s %9s %10s %9d %10.0f  %s\n", width,
                      benches[i].algo.c_str(), s.median_ms, s.p95_ms, ratio.c_str(), s.mean_pvs,
                      exact.c_str(), over.c_str(), fc.c_str(), s.frames_with_false_culls,
                      s.mean_pvs_triangles, counters.c_str());
        out += line;
    }
    return out;
}

std::string formatBenchCsv(const std::vector<AlgoBench>& benches, int frames, int runs, double dt) {
    // Columns for every counter any algorithm reported, so all rows line up.
    uint32_t present = 0;
    for (const auto& b : benches) present |= b.stats.front().present;
    std::string out = "algo,frame,t,cull_ms_median,cull_ms_min,pvs,exact,false_culls,pvs_triangles";
    for (int c = 0; c < kCounterCount; ++c)
        if ((present >> c) & 1u) out += std::string(",") + counterName(Counter(c));
    out += "\n";
    for (const auto& b : benches) {
        for (int f = 0; f < frames; ++f) {
            double min_ms = b.ms[size_t(f)];
            for (int r = 1; r < runs; ++r) min_ms = std::min(min_ms, b.ms[size_t(r * frames + f)]);
            out += b.algo + "," + std::to_string(f) + "," + format("%.6g", f * dt) + "," +
                   format("%.6g", frameMedianMs(b, f, frames, runs)) + "," +
                   format("%.6g", min_ms) + "," + std::to_string(b.pvs_size[size_t(f)]) + "," +
                   (b.exact_size[size_t(f)] >= 0 ? std::to_string(b.exact_size[size_t(f)]) : "") +
                   "," +
                   (b.exact_size[size_t(f)] >= 0 ? std::to_string(b.false_culls[size_t(f)]) : "") +
                   "," +
                   (size_t(f) < b.pvs_triangles.size() ? std::to_string(b.pvs_triangles[size_t(f)])
                                                       : "");
            for (int c = 0; c < kCounterCount; ++c) {
                if (!((present >> c) & 1u)) continue;
                const CullStats& st = b.stats[size_t(f)];
                out += ",";
                if (st.has(Counter(c))) out += std::to_string(st.get(Counter(c)));
            }
            out += "\n";
        }
    }
    return out;
}

}  // namespace gridcull
