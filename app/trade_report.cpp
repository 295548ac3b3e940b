#include "app/trade_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

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

bool parseTradeCsv(const std::string& text, std::vector<TradeSetting>& settings,
                   std::vector<TradePoint>& points, std::string& error) {
    settings.clear();
    points.clear();
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < text.size()) {
        const size_t end = text.find('\n', start);
        lines.push_back(text.substr(start, end == std::string::npos ? end : end - start));
        start = end == std::string::npos ? text.size() : end + 1;
    }
    auto split = [](const std::string& line) {
        std::vector<std::string> cells(1);
        for (char ch : line) {
            if (ch == ',')
                cells.emplace_back();
            else
                cells.back() += ch;
        }
        return cells;
    };
    const std::string header = formatTradeCsv({}, {});
    if (lines.empty() || lines[0] + "\n" != header) {
        error = "line 1: expected the header gridcull trade writes: " +
                header.substr(0, header.size() - 1);
        return false;
    }
    const size_t columns = split(lines[0]).size();
    for (size_t n = 1; n < lines.size(); ++n) {
        const std::vector<std::string> c = split(lines[n]);
        const std::string where = "line " + std::to_string(n + 1) + ": ";
        if (c.size() != columns) {
            error = where + "expected " + std::to_string(columns) + " columns, got " +
                    std::to_string(c.size());
            return false;
        }
        auto number = [&](size_t i, double& v) {
            if (c[i].empty()) {
                v = 0.0;
                return true;
            }
            char* end = nullptr;
            v = std::strtod(c[i].c_str(), &end);
            if (end && *end == '\0' && std::isfinite(v)) return true;
            error = where + "column " + std::to_string(i + 1) + ": expected a number, got '" +
                    c[i] + "'";
            return false;
        };
        TradeSetting s;
        TradePoint p;
        double false_culls = 0;
        p.setting = s.label = c[0];
        p.algorithm = s.algorithm = c[1];
        s.knob = c[2];
        if (!number(3, s.value) || !number(4, p.cull_ms) || !number(5, p.cull_p95_ms) ||
            !number(6, p.draw_ms) || !number(7, p.frame_ms) || !number(8, p.frame_p95_ms) ||
            !number(9, p.memory_bytes) || !number(10, p.pvs_ratio) || !number(11, false_culls))
            return false;
        p.false_culls = int64_t(false_culls);
        settings.push_back(s);
        points.push_back(p);
    }
    return true;
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
