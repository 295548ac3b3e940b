#include "ui/trade_panel.h"

#include <imgui.h>

#include <cstdio>

#include "ui/trade_plot.h"
#include "ui/ui_units.h"

namespace gridcull {

namespace {

// The plot's height in design pixels; its width is the column's.
constexpr float kPlotHeight = 260.0f;

}  // namespace

TradeAction drawTradePanel(const TradeCurveView& view, const std::string& selected) {
    TradeAction action;
    if (!ImGui::CollapsingHeader("Trade curve")) return action;
    if (view.running) {
        char label[64];
        std::snprintf(label, sizeof label, "%s: %d settings", view.algorithm.c_str(),
                      view.settings);
        ImGui::ProgressBar(float(view.progress), ImVec2(-1, 0), label);
        if (ImGui::Button("Stop")) action.stop = true;
    } else {
        const bool stale = !view.algorithm.empty() && view.algorithm != selected;
        const bool fresh = view.algorithm.empty() || stale;
        char label[160];  // a longer algorithm name is cut, never overrun
        std::snprintf(label, sizeof label, "%s%s's trade", fresh ? "Measure " : "Measure again ",
                      selected.c_str());
        if (ImGui::Button(label)) action.start = true;
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "Each knob of its family over the values gridcull trade sweeps, one at a time\n"
                "from the knobs in use, every setting run over the scene's first frames and\n"
                "judged by the exact oracle. In the background; the window stays live.");
        if (stale)
            ImGui::TextDisabled("The curve below is %s's.", view.algorithm.c_str());
    }
    if (!view.error.empty()) ImGui::TextWrapped("Stopped: %s", view.error.c_str());
    if (view.algorithm.empty()) return action;
    ImGui::TextDisabled("%zu of %d settings, frames 0..%d, %d run%s",
                        view.points.size(), view.settings, view.frames - 1, view.runs,
                        view.runs == 1 ? "" : "s");
    TradePlotInput input;
    input.points = &view.points;
    input.current = view.current;
    input.layout = &view.layout;
    const TradePlotResult result =
        drawTradePlot(input, ImGui::GetContentRegionAvail().x, scaledPixels(kPlotHeight));
    if (!view.running && result.clicked >= 0 && view.algorithm == selected)
        action.apply = result.clicked;
    if (!view.points.empty())
        ImGui::TextDisabled(view.current >= 0
                                ? "Ringed: the setting in use. Click a point to apply it."
                                : "Click a point to apply its setting.");
    return action;
}

}  // namespace gridcull
