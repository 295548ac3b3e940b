#include "ui/debugger_ui.h"

#include <algorithm>
#include <cassert>

#include <imgui.h>

#include "ui/hover_panel.h"
#include "ui/legend_panel.h"
#include "ui/palette.h"

namespace gridcull {

namespace {

// A row of buttons, one per preset the family offers.
std::optional<OverlayPreset> drawOverlayPresets(const FamilyView& family) {
    std::optional<OverlayPreset> chosen;
    const std::vector<OverlayPreset> presets = family.overlayPresets();
    if (presets.empty()) return chosen;
    ImGui::TextUnformatted("overlay:");
    for (OverlayPreset preset : presets) {
        ImGui::SameLine();
        if (ImGui::SmallButton(overlayPresetTitle(preset))) chosen = preset;
    }
    return chosen;
}

// Each pane's title and figures over its top left corner, on a dark plate so
// they read over any scene.
void drawPaneCaptions(const FrameSnapshot& snapshot) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const ImGuiStyle& style = ImGui::GetStyle();
    const Rgb text = swatchColor(Swatch::White);
    if (!snapshot.panes) return;
    for (const PaneCaption& pane : *snapshot.panes) {
        const ImVec2 at(float(pane.rect.x) + style.WindowPadding.x,
                        float(pane.rect.y) + style.WindowPadding.y);
        const ImVec2 title = ImGui::CalcTextSize(pane.title.c_str());
        const ImVec2 detail = ImGui::CalcTextSize(pane.detail.c_str());
        const float line = ImGui::GetTextLineHeightWithSpacing();
        const ImVec2 size(std::max(title.x, detail.x), pane.detail.empty() ? line : 2 * line);
        const ImVec2 pad = style.FramePadding;
        draw->AddRectFilled(ImVec2(at.x - pad.x, at.y - pad.y),
                            ImVec2(at.x + size.x + pad.x, at.y + size.y + pad.y),
                            IM_COL32(0, 0, 0, 190), style.FrameRounding);
        const ImU32 color = ImGui::ColorConvertFloat4ToU32(ImVec4(text.r, text.g, text.b, 1.0f));
        draw->AddText(at, color, pane.title.c_str());
        if (!pane.detail.empty())
            draw->AddText(ImVec2(at.x, at.y + line), color, pane.detail.c_str());
    }
}

}  // namespace

UiActions drawDebuggerUi(const FrameSnapshot& snapshot, UiState& state, const WindowLayout& layout,
                         FamilyView* family, const FamilyViewContext& family_context) {
    assert(snapshot.scene && snapshot.algo_names && snapshot.result && snapshot.exact &&
           snapshot.false_culled && snapshot.history && snapshot.scene_file &&
           snapshot.scene_errors && snapshot.knobs);
    UiActions actions;

    const WindowRect& column = layout.panels;
    ImGui::SetNextWindowPos(ImVec2(float(column.x), float(column.y)), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(float(column.width), float(column.height)), ImGuiCond_Always);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;
    if (ImGui::Begin("gridcull debugger", nullptr, flags)) {
        // Top to bottom: what is loaded, time, the culler, its numbers, the object
        // under the mouse, the colour key.
        if (snapshot.lesson) actions.lesson = drawLessonPanel(*snapshot.lesson);
        actions.scene = drawScenePanel(snapshot, state.scene);
        actions.playback = drawPlaybackPanel(snapshot);
        actions.algorithm = drawAlgorithmPanel(snapshot);
        // The family's own panel right under the culler that fills it.
        if (family) {
            actions.overlay_preset = drawOverlayPresets(*family);
            family->drawPanel(family_context, actions.family);
        }
        actions.knobs = drawKnobsPanel(snapshot, state.knobs);
        drawStatsPanel(snapshot);
        drawHoverPanel(snapshot);
        drawLegendPanel(snapshot);
    }
    ImGui::End();
    actions.timeline = drawTimeline(snapshot, state.timeline, layout.timeline);
    drawPaneCaptions(snapshot);
    drawHoverTooltip(snapshot);
    return actions;
}

}  // namespace gridcull
