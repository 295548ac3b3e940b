#include "ui/timeline_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "ui/palette.h"
#include "ui/ui_units.h"

namespace gridcull {

namespace {

ImU32 colorOf(Swatch swatch, float alpha = 1.0f) {
    const Rgb c = swatchColor(swatch);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, alpha));
}

// Where frame f's values come from: the run computed ahead, else the frames
// run so far; false when neither holds it.
const FrameHistory* sourceOf(const FrameSnapshot& s, int f) {
    if (s.timeline && f < s.timeline_frames) return s.timeline;
    if (f <= s.frame) return s.history;
    return nullptr;
}

enum class Series { Pvs, Exact, Ratio, CullMs, DrawMs, Counter };

bool valueAt(const FrameSnapshot& s, const TimelineState& state, Series series, int f, float& v) {
    const FrameHistory* h = sourceOf(s, f);
    if (!h) return false;
    const size_t i = size_t(f);
    switch (series) {
        case Series::Pvs:
            v = h->pvs_size[i];
            return true;
        case Series::Exact:
            v = h->exact_visible[i];
            return true;
        case Series::Ratio:
            if (h->exact_visible[i] <= 0.0f) return false;
            v = h->pvs_size[i] / h->exact_visible[i];
            return true;
        case Series::CullMs:
            v = h->cull_ms[i];
            return true;
        case Series::DrawMs:
            v = s.history->draw_ms[i];  // drawing happens in the window only
            return v > 0.0f;
        case Series::Counter:
            if (!h->stats[i].has(Counter(state.counter))) return false;
            v = float(h->stats[i].get(Counter(state.counter)));
            return true;
    }
    return false;
}

// A step between labelled frames near `about`: 1, 2, 5, 10, 20, 50, ...
int niceStep(double about) {
    int step = 1;
    for (int decade = 1;; decade *= 10) {
        for (const int m : {1, 2, 5}) {
            step = m * decade;
            if (step >= about) return step;
        }
    }
}

struct Plot {
    ImVec2 min, max;  // the plotting area in screen pixels
    int frames;
    float xOf(int f) const {
        return min.x + (max.x - min.x) * (frames > 1 ? float(f) / float(frames - 1) : 0.5f);
    }
};

float largestOf(const FrameSnapshot& s, const TimelineState& state, Series series, int frames) {
    float largest = 0.0f, v = 0.0f;
    for (int f = 0; f < frames; ++f)
        if (valueAt(s, state, series, f, v)) largest = std::max(largest, v);
    return largest;
}

// The series scaled so that `largest` is near the top.
void drawSeries(const FrameSnapshot& s, TimelineState& state, Series series, Swatch swatch,
                const Plot& plot, float largest) {
    if (largest <= 0.0f) return;
    float v = 0.0f;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float height = plot.max.y - plot.min.y;
    // One polyline per run of frames with values.
    std::vector<float>& points = state.scratch;
    auto flush = [&] {
        if (points.size() >= 4)
            draw->AddPolyline(reinterpret_cast<const ImVec2*>(points.data()),
                              int(points.size() / 2), colorOf(swatch), 0, kFineLine);
        points.clear();
    };
    for (int f = 0; f < plot.frames; ++f) {
        if (!valueAt(s, state, series, f, v)) {
            flush();
            continue;
        }
        points.push_back(plot.xOf(f));
        points.push_back(plot.max.y - height * 0.92f * v / largest);
    }
    flush();
}

void seriesToggle(const char* name, bool* on, Swatch swatch, float largest) {
    char label[64];
    if (*on && largest > 0.0f)
        std::snprintf(label, sizeof label, "%s (max %.4g)###%s", name, double(largest), name);
    else
        std::snprintf(label, sizeof label, "%s###%s", name, name);
    ImGui::PushStyleColor(ImGuiCol_Text, colorOf(swatch));
    ImGui::Checkbox(label, on);
    ImGui::PopStyleColor();
    ImGui::SameLine();
}

}  // namespace

int timelineFrameAt(float x, float left, float right, int frames) {
    if (frames <= 1 || right <= left) return 0;
    const float t = (x - left) / (right - left);
    return std::clamp(int(std::lround(t * float(frames - 1))), 0, frames - 1);
}

TimelineAction drawTimeline(const FrameSnapshot& s, TimelineState& state, const WindowRect& rect) {
    TimelineAction action;
    if (rect.width <= 0 || rect.height <= 0) return action;
    ImGui::SetNextWindowPos(ImVec2(float(rect.x), float(rect.y)), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(float(rect.width), float(rect.height)), ImGuiCond_Always);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoScrollbar |
                                   ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;
    if (!ImGui::Begin("timeline", nullptr, flags)) {
        ImGui::End();
        return action;
    }
    const int frames = std::max(s.scene->frames, 1);
    // The plot first (its maxima go into the toggles' labels), under the toggles.
    const float row = ImGui::GetFrameHeightWithSpacing();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float axis_h = ImGui::GetTextLineHeight();
    Plot plot;
    plot.frames = frames;
    plot.min = ImVec2(origin.x + scaledPixels(4), origin.y + row);
    plot.max = ImVec2(origin.x + avail.x - scaledPixels(4), origin.y + avail.y - axis_h);
    if (plot.max.y - plot.min.y < scaledPixels(8)) {
        ImGui::End();
        return action;
    }
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(plot.min, plot.max, IM_COL32(20, 22, 26, 255));
    // Frames not computed yet (nor run): shaded.
    const int known = std::max(s.timeline ? s.timeline_frames : 0, s.frame + 1);
    if (known < frames)
        draw->AddRectFilled(ImVec2(plot.xOf(known), plot.min.y), plot.max,
                            IM_COL32(60, 60, 66, 255));
    // Frame axis: a faint line and a label every nice step.
    const float width = plot.max.x - plot.min.x;
    const int step = niceStep(double(frames) * scaledPixels(70) / std::max(width, 1.0f));
    for (int f = 0; f < frames; f += step) {
        const float x = plot.xOf(f);
        draw->AddLine(ImVec2(x, plot.min.y), ImVec2(x, plot.max.y),
                      colorOf(Swatch::LineGrey, 0.25f));
        char text[16];
        std::snprintf(text, sizeof text, "%d", f);
        draw->AddText(ImVec2(x - ImGui::CalcTextSize(text).x * 0.5f, plot.max.y),
                      colorOf(Swatch::LineGrey), text);
    }

    // PVS and exact share one scale, so that their gap reads as over-estimation.
    const float counts_max = state.counts ? std::max(largestOf(s, state, Series::Pvs, frames),
                                                     largestOf(s, state, Series::Exact, frames))
                                          : 0.0f;
    const float ratio_max = state.ratio ? largestOf(s, state, Series::Ratio, frames) : 0.0f;
    const bool times = s.show_timings;
    const float cull_max = state.cull_ms && times ? largestOf(s, state, Series::CullMs, frames) : 0;
    const float draw_max = state.draw_ms && times ? largestOf(s, state, Series::DrawMs, frames) : 0;
    const float counter_max =
        state.counter >= 0 ? largestOf(s, state, Series::Counter, frames) : 0.0f;
    drawSeries(s, state, Series::Exact, Swatch::White, plot, counts_max);
    drawSeries(s, state, Series::Pvs, Swatch::SkyBlue, plot, counts_max);
    drawSeries(s, state, Series::Ratio, Swatch::Blue, plot, ratio_max);
    drawSeries(s, state, Series::CullMs, Swatch::Orange, plot, cull_max);
    drawSeries(s, state, Series::DrawMs, Swatch::BluishGreen, plot, draw_max);
    drawSeries(s, state, Series::Counter, Swatch::ReddishPurple, plot, counter_max);
    // False culls: a mark the full height of the frame, in the one colour that
    // means a false cull.
    for (int f = 0; f < frames; ++f) {
        const FrameHistory* h = sourceOf(s, f);
        if (h && h->false_culls[size_t(f)] > 0.0f) {
            const float x = plot.xOf(f);
            draw->AddLine(ImVec2(x, plot.min.y), ImVec2(x, plot.max.y), colorOf(Swatch::Vermillion),
                          kBoldLine);
        }
    }
    // The current frame.
    const float cursor = plot.xOf(s.frame);
    draw->AddLine(ImVec2(cursor, plot.min.y), ImVec2(cursor, plot.max.y),
                  colorOf(Swatch::LightGrey), kHeavyLine);

    // Click or drag to seek; hover for the values.
    ImGui::SetCursorScreenPos(plot.min);
    ImGui::InvisibleButton("##plot", ImVec2(plot.max.x - plot.min.x, plot.max.y - plot.min.y));
    const float mouse_x = ImGui::GetIO().MousePos.x;
    const int under = timelineFrameAt(mouse_x, plot.min.x, plot.max.x, frames);
    if (ImGui::IsItemActive() && under != s.frame) action.seek_frame = under;
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::Text("frame %d", under);
        const FrameHistory* h = sourceOf(s, under);
        if (!h) {
            ImGui::TextDisabled("not computed yet");
        } else {
            const size_t i = size_t(under);
            ImGui::Text("PVS %.0f, exact %.0f, false culls %.0f", double(h->pvs_size[i]),
                        double(h->exact_visible[i]), double(h->false_culls[i]));
            if (s.show_timings) ImGui::Text("cull %.3f ms", double(h->cull_ms[i]));
        }
        ImGui::EndTooltip();
    }

    // The toggles, with each series' largest value: the axis of its curve.
    ImGui::SetCursorScreenPos(origin);
    seriesToggle("PVS (blue), exact (white)", &state.counts, Swatch::SkyBlue, counts_max);
    seriesToggle("PVS/exact", &state.ratio, Swatch::Blue, ratio_max);
    if (s.show_timings) {
        seriesToggle("cull ms", &state.cull_ms, Swatch::Orange, cull_max);
        seriesToggle("draw ms", &state.draw_ms, Swatch::BluishGreen, draw_max);
    }
    const CullStats& stats = s.result->stats;
    const char* preview = state.counter >= 0 ? counterName(Counter(state.counter)) : "no counter";
    char label[64];
    if (state.counter >= 0 && counter_max > 0)
        std::snprintf(label, sizeof label, "max %.4g", double(counter_max));
    else
        std::snprintf(label, sizeof label, "counter");
    ImGui::SetNextItemWidth(scaledPixels(150));
    ImGui::PushStyleColor(ImGuiCol_Text, colorOf(Swatch::ReddishPurple));
    if (ImGui::BeginCombo(label, preview)) {
        if (ImGui::Selectable("no counter", state.counter < 0)) state.counter = -1;
        for (int c = 0; c < kCounterCount; ++c)
            if (stats.has(Counter(c)) &&
                ImGui::Selectable(counterName(Counter(c)), state.counter == c))
                state.counter = c;
        ImGui::EndCombo();
    }
    ImGui::PopStyleColor();
    ImGui::SameLine();
    ImGui::TextDisabled("vermillion: false culls; click to seek");
    ImGui::End();
    return action;
}

}  // namespace gridcull
