#include "ui/trade_plot.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "ui/palette.h"
#include "ui/ui_units.h"

namespace gridcull {

namespace {

// Series colours in the order algorithms first appear; vermillion is left to
// false culls, white to the marks.
constexpr Swatch kSeries[] = {Swatch::Blue,          Swatch::Orange, Swatch::BluishGreen,
                              Swatch::ReddishPurple, Swatch::SkyBlue, Swatch::Yellow,
                              Swatch::Grey};
// Points closer than this to the pointer (in design pixels) are hovered.
constexpr float kPickRadius = 8.0f;
// Costs spanning more than this ratio, and PVS/exact reaching beyond it, are
// plotted on a log scale, so the settings near the best keep room apart.
constexpr double kLogScaleSpan = 10.0;

ImU32 colorOf(Swatch swatch, float alpha = 1.0f) {
    const Rgb c = swatchColor(swatch);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, alpha));
}

// A tick's label, "%.3g", in a buffer of its own (no allocation).
struct Number {
    char text[32];
    explicit Number(double v) { std::snprintf(text, sizeof text, "%.3g", v); }
};

// Maps data to the plot box.
struct Axes {
    ImVec2 lo, hi;  // the box, pixels
    double x0 = 0, x1 = 1, y0 = 1, y1 = 2;
    bool log_x = false, log_y = false;
    double xOf(double cost) const {
        const double a = log_x ? std::log10(cost) : cost;
        const double b0 = log_x ? std::log10(x0) : x0, b1 = log_x ? std::log10(x1) : x1;
        return lo.x + (a - b0) / (b1 - b0) * (hi.x - lo.x);
    }
    double yOf(double ratio) const {
        const double a = log_y ? std::log10(ratio) : ratio;
        const double b0 = log_y ? std::log10(y0) : y0, b1 = log_y ? std::log10(y1) : y1;
        return hi.y - (a - b0) / (b1 - b0) * (hi.y - lo.y);
    }
};

Axes axesFor(const std::vector<TradePoint>& points, double target, ImVec2 lo, ImVec2 hi) {
    Axes a;
    a.lo = lo;
    a.hi = hi;
    double cmin = 1e300, cmax = 0, rmax = 1.0;
    for (const TradePoint& p : points) {
        cmin = std::min(cmin, std::max(p.cost(), 1e-6));
        cmax = std::max(cmax, p.cost());
        rmax = std::max(rmax, p.pvs_ratio);
    }
    rmax = std::max(rmax, target);
    // A single cost (or a few alike) gets a range around it, not a sliver.
    if (cmax < cmin * 1.2) {
        const double mid = 0.5 * (cmin + cmax);
        cmin = std::min(cmin, mid / 1.2);
        cmax = std::max(cmax, mid * 1.2);
    }
    a.log_x = cmax / cmin > kLogScaleSpan;
    if (a.log_x) {
        a.x0 = cmin / 1.25;
        a.x1 = cmax * 1.25;
    } else {
        const double pad = 0.08 * (cmax - cmin);
        a.x0 = std::max(0.0, cmin - pad);
        a.x1 = cmax + pad;
    }
    a.y0 = 1.0;
    a.log_y = rmax > kLogScaleSpan;
    a.y1 = a.log_y ? rmax * 1.25 : 1.0 + (rmax - 1.0) * 1.08 + 0.02;
    return a;
}

// Decades (and 2, 5) on a log scale, five steps on a linear one. A fixed array:
// costs lie between 1e-6 ms (axesFor's floor) and at most about 1e9 ms, 16
// decades of three ticks; beyond kMaxTicks the rest are left out.
constexpr size_t kMaxTicks = 64;
struct Ticks {
    std::array<double, kMaxTicks> values{};
    size_t count = 0;
    void add(double v) {
        if (count < kMaxTicks) values[count++] = v;
    }
    const double* begin() const { return values.data(); }
    const double* end() const { return values.data() + count; }
};

Ticks ticksOf(double lo, double hi, bool log) {
    Ticks ticks;
    if (!log) {
        for (int k = 0; k <= 4; ++k) ticks.add(lo + (hi - lo) * k / 4);
        return ticks;
    }
    for (double decade = std::pow(10.0, std::floor(std::log10(lo))); decade <= hi; decade *= 10)
        for (double m : {1.0, 2.0, 5.0})
            if (decade * m >= lo && decade * m <= hi) ticks.add(decade * m);
    return ticks;
}

void drawAxes(ImDrawList& draw, const Axes& a) {
    const ImU32 grid = colorOf(Swatch::LineGrey), text = colorOf(Swatch::LightGrey);
    draw.AddRect(a.lo, a.hi, grid);
    // x ticks: decades (and 2, 5) on a log scale, five steps on a linear one.
    for (double v : ticksOf(a.x0, a.x1, a.log_x)) {
        const float x = float(a.xOf(v));
        draw.AddLine(ImVec2(x, a.lo.y), ImVec2(x, a.hi.y), colorOf(Swatch::LineGrey, 0.35f));
        const Number label(v);
        const ImVec2 size = ImGui::CalcTextSize(label.text);
        draw.AddText(ImVec2(x - size.x / 2, a.hi.y + 2), text, label.text);
    }
    for (double v : ticksOf(a.y0, a.y1, a.log_y)) {
        const float y = float(a.yOf(v));
        draw.AddLine(ImVec2(a.lo.x, y), ImVec2(a.hi.x, y), colorOf(Swatch::LineGrey, 0.35f));
        const Number label(v);
        const ImVec2 size = ImGui::CalcTextSize(label.text);
        draw.AddText(ImVec2(a.lo.x - size.x - 4, y - size.y / 2), text, label.text);
    }
}

void dashedLine(ImDrawList& draw, ImVec2 from, ImVec2 to, ImU32 color) {
    const float dash = scaledPixels(6.0f), length = to.x - from.x;
    for (float x = 0; x < length; x += 2 * dash)
        draw.AddLine(ImVec2(from.x + x, from.y), ImVec2(from.x + std::min(x + dash, length), to.y),
                     color, kFineLine);
}

// The most front labels one plot places; beyond, a label is left out, as a
// crowded one is (the tooltip and the CSV name every point).
constexpr size_t kMaxLabels = 64;

}  // namespace

TradePlotLayout tradePlotLayout(const std::vector<TradePoint>& points,
                                const std::vector<std::string>& series_order) {
    TradePlotLayout layout;
    layout.point_count = points.size();
    // Colour slots: series_order first, then algorithms in order of appearance.
    std::vector<std::string> dealt = series_order;
    auto slotOf = [&](const std::string& name) {
        const auto it = std::find(dealt.begin(), dealt.end(), name);
        if (it != dealt.end()) return int(it - dealt.begin());
        dealt.push_back(name);
        return int(dealt.size()) - 1;
    };
    for (const TradePoint& p : points) {
        const int slot = slotOf(p.algorithm);
        layout.point_series.push_back(slot);
        if (std::find(layout.names.begin(), layout.names.end(), p.algorithm) != layout.names.end())
            continue;
        layout.names.push_back(p.algorithm);
        layout.name_series.push_back(slot);
    }
    for (const std::string& name : layout.names) {
        std::vector<TradePoint> own;
        std::vector<size_t> index;
        for (size_t i = 0; i < points.size(); ++i)
            if (points[i].algorithm == name) {
                own.push_back(points[i]);
                index.push_back(i);
            }
        std::vector<size_t> front;
        for (size_t k : paretoFront(own)) front.push_back(index[k]);
        layout.fronts.push_back(std::move(front));
    }
    layout.front = paretoFront(points);
    return layout;
}

TradePlotResult drawTradePlot(const TradePlotInput& input, float width, float height) {
    TradePlotResult result;
    const std::vector<TradePoint>& points = *input.points;
    if (!input.title.empty()) ImGui::TextUnformatted(input.title.c_str());
    if (points.empty()) {
        ImGui::TextDisabled("No setting measured yet.");
        return result;
    }
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("trade plot", ImVec2(width, height));
    const bool hovered_box = ImGui::IsItemHovered();
    const bool clicked = ImGui::IsItemClicked();
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    const float line = ImGui::GetTextLineHeight();
    TradePlotLayout made;
    const bool given = input.layout && input.layout->point_count == points.size();
    if (!given) made = tradePlotLayout(points, input.series_order);
    const TradePlotLayout& layout = given ? *input.layout : made;
    const std::vector<std::string>& names = layout.names;
    // Above the box a row for the y axis's name and the legend; the legend
    // takes a row of its own when both do not fit in one.
    const char* y_name = "PVS/exact (crosses: false culls)";
    float legend_width = 0.0f;
    for (const std::string& n : names) legend_width += ImGui::CalcTextSize(n.c_str()).x + 2 * line;
    const bool legend_row = ImGui::CalcTextSize(y_name).x + legend_width + line > width;
    const float legend_y = origin.y + (legend_row ? 1.2f * line : 0.0f);
    const ImVec2 lo(origin.x + 4 * line, legend_y + 1.8f * line);
    const ImVec2 hi(origin.x + width - 0.5f * line, origin.y + height - 2.6f * line);
    const Axes axes = axesFor(points, input.target, lo, hi);
    drawAxes(draw, axes);
    const bool drawn = points.front().frame_ms > 0.0;
    const char* x_name = drawn ? "frame ms (median, cull + draw)" : "cull ms (median)";
    const ImVec2 x_size = ImGui::CalcTextSize(x_name);
    draw.AddText(ImVec2((lo.x + hi.x - x_size.x) / 2, hi.y + 1.3f * line),
                 colorOf(Swatch::LightGrey), x_name);
    draw.AddText(ImVec2(origin.x, origin.y), colorOf(Swatch::LightGrey), y_name);
    const char* scale = axes.log_x && axes.log_y ? "log scales"
                        : axes.log_x             ? "log scale"
                        : axes.log_y             ? "PVS/exact on a log scale"
                                                 : "";
    draw.AddText(ImVec2(hi.x - ImGui::CalcTextSize(scale).x, hi.y + 1.3f * line),
                 colorOf(Swatch::LineGrey), scale);

    auto seriesColor = [&](int s, float alpha = 1.0f) {
        return colorOf(kSeries[size_t(s) % (sizeof kSeries / sizeof kSeries[0])], alpha);
    };
    auto at = [&](const TradePoint& p) {
        return ImVec2(float(axes.xOf(std::max(p.cost(), axes.x0))), float(axes.yOf(p.pvs_ratio)));
    };

    draw.PushClipRect(lo, hi, true);
    if (input.target > 0.0) {
        const float y = float(axes.yOf(input.target));
        dashedLine(draw, ImVec2(lo.x, y), ImVec2(hi.x, y), colorOf(Swatch::White, 0.6f));
    }
    // Each algorithm's front, joined in increasing cost.
    for (size_t s = 0; s < names.size(); ++s) {
        const std::vector<size_t>& front = layout.fronts[s];
        for (size_t k = 1; k < front.size(); ++k)
            draw.AddLine(at(points[front[k - 1]]), at(points[front[k]]),
                         seriesColor(layout.name_series[s], 0.8f), kBoldLine);
    }
    const float r = scaledPixels(4.0f);
    for (size_t i = 0; i < points.size(); ++i) {
        const ImVec2 c = at(points[i]);
        if (points[i].false_culls > 0) {
            const ImU32 red = colorOf(Swatch::Vermillion);
            draw.AddLine(ImVec2(c.x - r, c.y - r), ImVec2(c.x + r, c.y + r), red, kBoldLine);
            draw.AddLine(ImVec2(c.x - r, c.y + r), ImVec2(c.x + r, c.y - r), red, kBoldLine);
        } else {
            draw.AddCircleFilled(c, r, seriesColor(layout.point_series[i]));
        }
    }
    if (input.chosen >= 0 && size_t(input.chosen) < points.size()) {
        const ImVec2 c = at(points[size_t(input.chosen)]);
        const float q = 2.2f * r;
        draw.AddRect(ImVec2(c.x - q, c.y - q), ImVec2(c.x + q, c.y + q), colorOf(Swatch::White), 0,
                     0, kBoldLine);
    }
    if (input.current >= 0 && size_t(input.current) < points.size())
        draw.AddCircle(at(points[size_t(input.current)]), 2.4f * r, colorOf(Swatch::White), 0,
                       kBoldLine);
    draw.PopClipRect();

    // The front's settings named beside their points: what to set. A label
    // goes above its point, else below, else (crowded) is left out: the
    // tooltip and the CSV name every point.
    std::array<ImVec4, kMaxLabels> placed;  // x0, y0, x1, y1
    size_t placed_count = 0;
    auto overlaps = [&](const ImVec4& a) {
        for (size_t k = 0; k < placed_count; ++k) {
            const ImVec4& b = placed[k];
            if (a.x < b.z && b.x < a.z && a.y < b.w && b.y < a.w) return true;
        }
        return false;
    };
    for (size_t i : layout.front) {
        if (placed_count == kMaxLabels) break;
        const std::string& label = points[i].setting;
        const size_t colon = label.find(':');
        // The knob and value; the base setting by its algorithm's name.
        const char* knob = label.c_str() + (colon == std::string::npos ? 0 : colon + 1);
        const ImVec2 c = at(points[i]);
        const ImVec2 size = ImGui::CalcTextSize(knob);
        const float x = std::min(c.x + 1.5f * r, hi.x - size.x - 2);
        for (float y : {c.y - size.y - r, c.y + r}) {
            const ImVec4 box(x, y, x + size.x, y + size.y);
            if (overlaps(box)) continue;
            placed[placed_count++] = box;
            draw.AddText(ImVec2(x, y), colorOf(Swatch::LightGrey), knob);
            break;
        }
    }

    // The legend, in the row above the box, from the right.
    float x = hi.x;
    for (size_t s = names.size(); s-- > 0;) {
        const ImVec2 size = ImGui::CalcTextSize(names[s].c_str());
        x -= size.x;
        draw.AddText(ImVec2(x, legend_y), colorOf(Swatch::LightGrey), names[s].c_str());
        draw.AddCircleFilled(ImVec2(x - 0.7f * line, legend_y + size.y / 2), r,
                             seriesColor(layout.name_series[s]));
        x -= 2.0f * line;
    }

    if (hovered_box) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        float best = scaledPixels(kPickRadius);
        for (size_t i = 0; i < points.size(); ++i) {
            const ImVec2 c = at(points[i]);
            const float d = std::hypot(c.x - mouse.x, c.y - mouse.y);
            if (d <= best) {
                best = d;
                result.hovered = int(i);
            }
        }
        if (result.hovered >= 0) {
            const TradePoint& p = points[size_t(result.hovered)];
            ImGui::BeginTooltip();
            ImGui::TextUnformatted(p.setting.c_str());
            ImGui::Text("cull %.3g ms (p95 %.3g)", p.cull_ms, p.cull_p95_ms);
            if (p.frame_ms > 0.0)
                ImGui::Text("draw %.3g ms, frame %.3g ms (p95 %.3g)", p.draw_ms, p.frame_ms,
                            p.frame_p95_ms);
            ImGui::Text("PVS/exact %.3f, memory %.1f MiB", p.pvs_ratio,
                        p.memory_bytes / (1 << 20));
            if (p.false_culls > 0)
                ImGui::Text("%lld false culls: never picked", (long long)p.false_culls);
            ImGui::EndTooltip();
            if (clicked) result.clicked = result.hovered;
        }
    }
    return result;
}

}  // namespace gridcull
