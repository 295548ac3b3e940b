#include "ui/stats_panel.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

namespace gridcull {

namespace {

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

}  // namespace

void drawStatsPanel(const FrameSnapshot& snapshot) {
    if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const FrameResult& result = *snapshot.result;
    const int pvs = int(result.pvs.size());
    const int exact = int(snapshot.exact->pvs.size());
    const int false_culls = int(snapshot.false_culled->size());

    if (ImGui::BeginTable("stats", 2, ImGuiTableFlags_SizingStretchProp)) {
        row("PVS size", "%.0f", pvs);
        row("exact visible", "%.0f", exact);
        row("false culls", "%.0f", false_culls,
            false_culls > 0 ? toU32(objectStateColor(ObjectState::FalseCulled)) : 0);
        // What the oracle saw or could not decide between pixel centres, while
        // it asks (--oracle-refine 1): shown, not hidden.
        if (snapshot.exact->stats.has(Counter::SubSampleCandidates)) {
            const int sub_sample = int(snapshot.exact->sub_sample_visible.size() +
                                       snapshot.exact->sub_sample_undecided.size());
            row("sub-sample", "%.0f", sub_sample,
                sub_sample > 0 ? toU32(objectStateColor(ObjectState::SubSample)) : 0);
        }
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
}

}  // namespace gridcull
