#include "app/trade_report.h"

#include <algorithm>
#include <cstdio>

namespace gridcull {

namespace {

std::string format(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

}  // namespace

std::vector<size_t> pointsOf(const std::vector<TradePoint>& points, const std::string& algorithm) {
    std::vector<size_t> out;
    for (size_t i = 0; i < points.size(); ++i)
        if (points[i].algorithm == algorithm) out.push_back(i);
    return out;
}

std::vector<bool> onFront(const std::vector<TradePoint>& points, bool by_algorithm) {
    std::vector<bool> on(points.size(), false);
    if (!by_algorithm) {
        for (size_t i : paretoFront(points)) on[i] = true;
        return on;
    }
    std::vector<std::string> seen;
    for (const TradePoint& p : points) {
        if (std::find(seen.begin(), seen.end(), p.algorithm) != seen.end()) continue;
        seen.push_back(p.algorithm);
        const std::vector<size_t> own = pointsOf(points, p.algorithm);
        std::vector<TradePoint> subset;
        for (size_t i : own) subset.push_back(points[i]);
        for (size_t k : paretoFront(subset)) on[own[k]] = true;
    }
    return on;
}

std::string formatTradeCsv(const std::vector<TradeSetting>& settings,
                           const std::vector<TradePoint>& points) {
    const std::vector<bool> own = onFront(points, true), all = onFront(points, false);
    std::string out =
        "setting,algorithm,knob,value,cull_ms_median,cull_ms_p95,draw_ms_median,frame_ms_median,"
        "frame_ms_p95,memory_bytes,pvs_over_exact,false_culls,front,front_all\n";
    for (size_t i = 0; i < points.size(); ++i) {
        const TradePoint& p = points[i];
        const TradeSetting& s = settings[i];
        const bool drawn = p.frame_ms > 0.0;
        out += p.setting + "," + p.algorithm + "," + s.knob + "," +
               (s.knob.empty() ? "" : format("%.6g", s.value)) + "," + format("%.6g", p.cull_ms) +
               "," + format("%.6g", p.cull_p95_ms) + "," +
               (drawn ? format("%.6g", p.draw_ms) : "") + "," +
               (drawn ? format("%.6g", p.frame_ms) : "") + "," +
               (drawn ? format("%.6g", p.frame_p95_ms) : "") + "," +
               format("%.0f", p.memory_bytes) + "," + format("%.6g", p.pvs_ratio) + "," +
               std::to_string(p.false_culls) + "," + (own[i] ? "1" : "0") + "," +
               (all[i] ? "1" : "0") + "\n";
    }
    return out;
}

std::string formatTradeTable(const std::vector<TradePoint>& points) {
    const std::vector<bool> own = onFront(points, true);
    int width = 12;
    for (const TradePoint& p : points) width = std::max(width, int(p.setting.size()));
    std::string out;
    char line[512];
    std::snprintf(line, sizeof line, "%-*s %9s %9s %9s %9s %9s %9s %9s %10s  %s\n", width,
                  "setting", "cull ms", "cull p95", "draw ms", "frame ms", "frame p95", "MiB",
                  "pvs/exact", "false cull", "front");
    out += line;
    for (size_t i = 0; i < points.size(); ++i) {
        const TradePoint& p = points[i];
        const bool drawn = p.frame_ms > 0.0;
        std::snprintf(line, sizeof line, "%-*s %9.4g %9.4g %9s %9s %9s %9.1f %9.3f %10lld  %s\n",
                      width, p.setting.c_str(), p.cull_ms, p.cull_p95_ms,
                      drawn ? format("%.4g", p.draw_ms).c_str() : "-",
                      drawn ? format("%.4g", p.frame_ms).c_str() : "-",
                      drawn ? format("%.4g", p.frame_p95_ms).c_str() : "-",
                      p.memory_bytes / (1 << 20), p.pvs_ratio, (long long)p.false_culls,
                      own[i] ? "*" : "");
        out += line;
    }
    return out;
}

}  // namespace gridcull
