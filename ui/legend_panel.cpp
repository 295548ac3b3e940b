#include "ui/legend_panel.h"

#include <imgui.h>

#include "ui/ui_units.h"

namespace gridcull {

namespace {

void swatch(Rgb c, const char* name, const char* meaning) {
    const ImVec4 color(c.r, c.g, c.b, 1.0f);
    ImGui::ColorButton(name, color, ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop,
                       ImVec2(scaledPixels(13), scaledPixels(13)));
    ImGui::SameLine();
    ImGui::Text("%-12s %s", name, meaning);
}

}  // namespace

void drawLegendPanel(const FrameSnapshot& snapshot) {
    if (!ImGui::CollapsingHeader("Legend", ImGuiTreeNodeFlags_DefaultOpen)) return;
    // Sub-sample objects exist only while the oracle asks about them.
    const bool sub_sample = snapshot.exact && snapshot.exact->stats.has(Counter::SubSampleCandidates);
    for (int s = 0; s < kObjectStateCount; ++s) {
        const ObjectState state = ObjectState(s);
        if (state == ObjectState::SubSample && !sub_sample) continue;
        swatch(objectStateColor(state), objectStateName(state), objectStateMeaning(state));
    }
    swatch(cullingCameraColor(), "camera",
           snapshot.scene->dimensions == 3 ? "culling frustum, cut to the world"
                                           : "culling view wedge");
}

}  // namespace gridcull
