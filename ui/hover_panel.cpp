#include "ui/hover_panel.h"

#include <imgui.h>

namespace gridcull {

namespace {

void drawDetails(const FrameSnapshot& snapshot) {
    const HoverInfo& hover = snapshot.hover;
    const int dims = snapshot.scene->dimensions;
    const Rgb c = objectStateColor(hover.state);
    ImGui::Text("object %d, %s,", hover.id, shapeName(hover.shape, dims));
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(c.r, c.g, c.b, 1.0f), "%s", objectStateName(hover.state));
    if (dims == 3) {
        ImGui::Text("bounds min (%.2f, %.2f, %.2f)", hover.bounds.min.x, hover.bounds.min.y,
                    hover.bounds.min.z);
        ImGui::Text("       max (%.2f, %.2f, %.2f)", hover.bounds.max.x, hover.bounds.max.y,
                    hover.bounds.max.z);
        ImGui::Text("%s, max speed %.2f, %.2f away", motionName(hover.motion), hover.max_speed,
                    hover.distance);
    } else {
        ImGui::Text("bounds min (%.2f, %.2f) max (%.2f, %.2f)", hover.bounds.min.x,
                    hover.bounds.min.y, hover.bounds.max.x, hover.bounds.max.y);
        ImGui::Text("%s, max speed %.2f", motionName(hover.motion), hover.max_speed);
    }
}

}  // namespace

void drawHoverPanel(const FrameSnapshot& snapshot) {
    if (!ImGui::CollapsingHeader("Under the mouse", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (snapshot.hover.id < 0) {
        ImGui::TextDisabled("nothing: point at an object in the view");
        return;
    }
    drawDetails(snapshot);
}

void drawHoverTooltip(const FrameSnapshot& snapshot) {
    if (snapshot.hover.id < 0) return;
    ImGui::BeginTooltip();
    drawDetails(snapshot);
    ImGui::EndTooltip();
}

}  // namespace gridcull
