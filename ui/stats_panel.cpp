#include "ui/stats_panel.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "ui/ui_units.h"

namespace gridcull {

namespace {

constexpr float kPlotHeight = 44.0f;  // design pixels

float seriesMax(const std::vector<float>& values, int count) {
    float m = 0.0f;
    for (int i = 0; i < count; ++i) m = std::max(m, values[size_t(i)]);
    return m;
}

// `tooltip`, when given, shows over the name: what the row counts.
void row(const char* name, const char* format, double value, ImU32 color = 0,
         const char* tooltip = nullptr) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted(name);
    if (tooltip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
    ImGui::TableSetColumnIndex(1);
    if (color) ImGui::PushStyleColor(ImGuiCol_Text, color);
    ImGui::Text(format, value);
    if (color) ImGui::PopStyleColor();
}

void hiddenRow(const char* name) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted(name);
    ImGui::TableSetColumnIndex(1);
    ImGui::TextDisabled("(not in shots)");
}

ImU32 toU32(Rgb c) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f));
}

// Two series on one scale: PVS size over the exact visible count, so the gap
// between the lines is the culler's over-estimation.
void countsPlot(const FrameHistory& history, int count, int objects) {
    const float top = std::max(
        {seriesMax(history.pvs_size, count), seriesMax(history.exact_visible, count), 1.0f});
    // ImGui 1.86's PlotLines takes no negative (fill) width: give it the space left.
    const ImVec2 size(ImGui::GetContentRegionAvail().x, scaledPixels(kPlotHeight));
    const ImVec2 at = ImGui::GetCursorPos();
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "PVS (blue) vs exact (white), of %d", objects);
    ImGui::PushStyleColor(ImGuiCol_PlotLines, toU32(objectStateColor(ObjectState::Hidden)));
    ImGui::PlotLines("##pvs", history.pvs_size.data(), count, 0, overlay, 0.0f, top * 1.1f, size);
    ImGui::PopStyleColor();
    ImGui::SetCursorPos(at);
    ImGui::PushStyleColor(ImGuiCol_FrameBg, IM_COL32(0, 0, 0, 0));
    ImGui::PushStyleColor(ImGuiCol_PlotLines, IM_COL32(235, 235, 235, 255));
    ImGui::PlotLines("##exact", history.exact_visible.data(), count, 0, nullptr, 0.0f, top * 1.1f,
                     size);
    ImGui::PopStyleColor(2);
}

}  // namespace

void drawStatsPanel(const FrameSnapshot& snapshot, StatsPanelState& state) {
    if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const FrameResult& result = *snapshot.result;
    const int pvs = int(result.pvs.size());
    const int exact = int(snapshot.exact->pvs.size());
    const int false_culls = int(snapshot.false_culled->size());
    const int objects = int(snapshot.scene->objects.size());

    if (ImGui::BeginTable("stats", 2, ImGuiTableFlags_SizingStretchProp)) {
        row("PVS size", "%.0f", pvs);
        row("exact visible", "%.0f", exact);
        row("false culls", "%.0f", false_culls,
            false_culls > 0 ? toU32(objectStateColor(ObjectState::FalseCulled)) : 0);
        if (snapshot.show_timings) {
            row("cull ms", "%.3f", result.stats.cull_ms);
            row("draw ms", "%.3f", snapshot.draw_ms);
        } else {
            hiddenRow("cull ms");
            hiddenRow("draw ms");
        }
        for (int c = 0; c < kCounterCount; ++c) {
            if (result.stats.has(Counter(c)))
                row(counterName(Counter(c)), "%.0f", double(result.stats.get(Counter(c))), 0,
                    counterMeaning(Counter(c)));
        }
        ImGui::EndTable();
    }

    const FrameHistory& history = *snapshot.history;
    const int count = std::min(snapshot.frame + 1, int(history.pvs_size.size()));
    if (count <= 0) return;
    countsPlot(history, count, objects);

    static const char* const kSeriesNames[] = {"false culls", "cull ms", "draw ms"};
    int series = int(state.series);
    ImGui::SetNextItemWidth(-scaledPixels(60));
    if (ImGui::Combo("plot", &series, kSeriesNames, IM_ARRAYSIZE(kSeriesNames)))
        state.series = StatsSeries(series);
    const std::vector<float>* values = &history.false_culls;
    if (state.series == StatsSeries::CullMs) values = &history.cull_ms;
    if (state.series == StatsSeries::DrawMs) values = &history.draw_ms;
    const bool timing = state.series != StatsSeries::FalseCulls;
    if (timing && !snapshot.show_timings) {
        ImGui::TextDisabled("(times are not drawn in shots)");
        return;
    }
    const float largest = seriesMax(*values, count);
    const float top = std::max(largest, timing ? 0.001f : 1.0f);
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%s, max %.3g", kSeriesNames[series], double(largest));
    ImGui::PlotLines("##series", values->data(), count, 0, overlay, 0.0f, top * 1.1f,
                     ImVec2(ImGui::GetContentRegionAvail().x, scaledPixels(kPlotHeight)));
}

}  // namespace gridcull
