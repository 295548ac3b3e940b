#include "app/bench_table.h"

#include <algorithm>
#include <cassert>
#include <cstdio>

#include "culling/scene/object_triangles.h"

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

// Value of (run, frame) in a [run * frames + frame] table.
using RunValue = double (*)(const AlgoBench&, size_t);
double cullOf(const AlgoBench& b, size_t k) { return b.ms[k]; }
double drawOf(const AlgoBench& b, size_t k) { return b.draw_ms[k]; }
double frameOf(const AlgoBench& b, size_t k) { return b.ms[k] + b.draw_ms[k]; }

double medianOverRuns(const AlgoBench& bench, RunValue value, int frame, int frames, int runs) {
    std::vector<double> values(static_cast<size_t>(runs));
    for (int r = 0; r < runs; ++r) values[size_t(r)] = value(bench, size_t(r * frames + frame));
    return medianOf(values);
}

// The median and 95th percentile over frames of each frame's median over runs.
void frameStatistics(const AlgoBench& bench, RunValue value, int frames, int runs,
                     double& median, double& p95, double* mean = nullptr) {
    std::vector<double> medians(static_cast<size_t>(frames));
    for (int f = 0; f < frames; ++f)
        medians[size_t(f)] = medianOverRuns(bench, value, f, frames, runs);
    if (mean) {
        double sum = 0.0;
        for (double m : medians) sum += m;
        *mean = sum / frames;
    }
    std::vector<double> sorted = medians;
    std::sort(sorted.begin(), sorted.end());
    p95 = sorted[std::min(sorted.size() - 1, size_t(0.95 * double(sorted.size())))];
    median = medianOf(medians);
}

int countMissing(const std::vector<int>& exact, const std::vector<int>& pvs) {
    int missing = 0;
    size_t j = 0;
    for (int id : exact) {
        while (j < pvs.size() && pvs[j] < id) ++j;
        if (j == pvs.size() || pvs[j] != id) ++missing;
    }
    return missing;
}

}  // namespace

void recordFrame(const Scene& scene, int frame, const FrameResult& result,
                 const FrameResult* exact, AlgoBench& b) {
    const size_t f = size_t(frame);
    b.pvs_size[f] = int(result.pvs.size());
    for (int id : result.pvs)
        b.pvs_triangles[f] += trianglesOf(scene.objects[size_t(scene.indexOf(id))]);
    b.stats[f] = result.stats;
    if (exact) {
        b.exact_size[f] = int(exact->pvs.size());
        b.false_culls[f] = countMissing(exact->pvs, result.pvs);
    }
}

void sizeBench(AlgoBench& b, int frames, int runs, bool drawn) {
    const size_t n = size_t(frames), slots = n * size_t(runs);
    b.ms.assign(slots, 0.0);
    b.draw_ms.assign(drawn ? slots : 0, 0.0);
    b.pvs_triangles.assign(n, 0);
    b.pvs_size.assign(n, 0);
    b.exact_size.assign(n, -1);
    b.false_culls.assign(n, 0);
    b.stats.assign(n, CullStats{});
}

double frameMedianMs(const AlgoBench& bench, int frame, int frames, int runs) {
    return medianOverRuns(bench, cullOf, frame, frames, runs);
}

int medianFrameRun(const AlgoBench& bench, int frame, int frames, int runs) {
    assert(!bench.draw_ms.empty());
    std::vector<int> order(static_cast<size_t>(runs));
    for (int r = 0; r < runs; ++r) order[size_t(r)] = r;
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return frameOf(bench, size_t(a * frames + frame)) <
               frameOf(bench, size_t(b * frames + frame));
    });
    return order[size_t(runs - 1) / 2];
}

BenchSummary summarize(const AlgoBench& bench, int frames, int runs) {
    BenchSummary s;
    frameStatistics(bench, cullOf, frames, runs, s.median_ms, s.p95_ms, &s.mean_ms);
    if (!bench.draw_ms.empty()) {
        frameStatistics(bench, drawOf, frames, runs, s.median_draw_ms, s.p95_draw_ms);
        frameStatistics(bench, frameOf, frames, runs, s.median_frame_ms, s.p95_frame_ms);
    }

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
        if (Counter(c) == Counter::PixelQueries || Counter(c) == Counter::OcclusionQueries)
            s.mean_queries += total / frames;
    }
    return s;
}

double modelledFrameMs(const BenchSummary& s, bool drawn, double cost_us) {
    return (drawn ? s.median_frame_ms : s.median_ms) + s.mean_queries * cost_us * 1e-3;
}

std::string formatBenchTable(const std::vector<AlgoBench>& benches, int frames, int runs,
                             size_t baseline, int limit, double query_cost_us) {
    std::vector<BenchSummary> sums;
    for (const auto& b : benches) sums.push_back(summarize(b, frames, runs));
    const bool drawn = !benches.front().draw_ms.empty();
    // Ratios against a row of the same run: on a shared, noisy machine the ratio
    // of two algorithms timed in the same run is what holds. With drawing, of
    // frame times; else of cull times.
    auto timeOf = [&](size_t i) { return drawn ? sums[i].median_frame_ms : sums[i].median_ms; };
    auto ratio = [&](size_t i, size_t to) {
        return timeOf(to) > 0.0 ? format("%.3g", timeOf(i) / timeOf(to)) : std::string("-");
    };
    // The algo column fits the longest label (entries like NAME:FLAG=VALUE).
    int width = 14;
    for (const auto& b : benches) width = std::max(width, int(b.algo.size()));
    std::string out;
    char line[1024];
    const std::string base_head = ("x " + benches[baseline].algo).substr(0, 10);
    if (drawn) {
        std::snprintf(line, sizeof line, "%-*s %9s %9s %9s %9s %10s %10s", width, "algo",
                      "cull ms", "draw ms", "frame ms", "frame p95", base_head.c_str(),
                      limit >= 0 ? "x limit" : "");
    } else {
        std::snprintf(line, sizeof line, "%-*s %10s %10s %10s", width, "algo", "median ms",
                      "p95 ms", base_head.c_str());
    }
    out += line;
    const bool model = query_cost_us >= 0.0;
    if (model) {
        std::snprintf(line, sizeof line, " %10s %10s", "queries",
                      ("model@" + format("%g", query_cost_us) + "us").substr(0, 10).c_str());
        out += line;
    }
    std::snprintf(line, sizeof line, " %9s %9s %9s %10s %9s %10s  %s\n", "pvs", "exact",
                  "pvs/exact", "false cull", "fc frames", "pvs tris", "counters (mean per frame)");
    out += line;
    for (size_t i = 0; i < benches.size(); ++i) {
        const BenchSummary& s = sums[i];
        std::string counters;
        for (const auto& [counter, mean] : s.counter_means) {
            counters += std::string(counters.empty() ? "" : " ") + counterName(counter) + "=" +
                        format("%.6g", mean);
        }
        const std::string exact = s.mean_exact >= 0 ? format("%.1f", s.mean_exact) : "-";
        const std::string over = s.mean_exact >= 0 ? format("%.3f", s.pvs_over_exact) : "-";
        const std::string fc = s.mean_exact >= 0 ? std::to_string(s.false_culls) : "-";
        if (drawn) {
            const std::string to_limit = limit >= 0 ? ratio(i, size_t(limit)) : "";
            std::snprintf(line, sizeof line, "%-*s %9.4g %9.4g %9.4g %9.4g %10s %10s", width,
                          benches[i].algo.c_str(), s.median_ms, s.median_draw_ms,
                          s.median_frame_ms, s.p95_frame_ms, ratio(i, baseline).c_str(),
                          to_limit.c_str());
        } else {
            std::snprintf(line, sizeof line, "%-*s %10.4g %10.4g %10s", width,
                          benches[i].algo.c_str(), s.median_ms, s.p95_ms,
                          ratio(i, baseline).c_str());
        }
        out += line;
        if (model) {
            std::snprintf(line, sizeof line, " %10.1f %10.4g", s.mean_queries,
                          modelledFrameMs(s, drawn, query_cost_us));
            out += line;
        }
        std::snprintf(line, sizeof line, " %9.1f %9s %9s %10s %9d %10.0f  %s\n", s.mean_pvs,
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
    const bool drawn = !benches.front().draw_ms.empty();
    std::string out = "algo,frame,t,cull_ms_median,cull_ms_min,pvs,exact,false_culls,pvs_triangles";
    // With drawing: the run whose frame time is the frame's median, and its
    // cull, draw and frame (= cull + draw) times.
    if (drawn) out += ",median_run,cull_ms,draw_ms,frame_ms";
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
            if (drawn) {
                const int run = medianFrameRun(b, f, frames, runs);
                const size_t k = size_t(run * frames + f);
                // Printed to 17 digits, so the columns add up as the doubles do.
                out += "," + std::to_string(run) + "," + format("%.17g", b.ms[k]) + "," +
                       format("%.17g", b.draw_ms[k]) + "," + format("%.17g", frameOf(b, k));
            }
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
