#include "ui/debugger_ui.h"

#include <cassert>

#include <imgui.h>

#include "ui/hover_panel.h"
#include "ui/legend_panel.h"

namespace gridcull {

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
        actions.scene = drawScenePanel(snapshot, state.scene);
        actions.playback = drawPlaybackPanel(snapshot);
        actions.algorithm = drawAlgorithmPanel(snapshot);
        // The family's own panel right under the culler that fills it.
        if (family) family->drawPanel(family_context, actions.family);
        actions.knobs = drawKnobsPanel(snapshot, state.knobs);
        drawStatsPanel(snapshot);
        drawHoverPanel(snapshot);
        drawLegendPanel(snapshot);
    }
    ImGui::End();
    actions.timeline = drawTimeline(snapshot, state.timeline, layout.timeline);
    drawHoverTooltip(snapshot);
    return actions;
}

}  // namespace gridcull
