#include "ui/algorithm_panel.h"

#include <imgui.h>

#include "ui/ui_units.h"

namespace gridcull {

namespace {

// Record a flight, then save it into the scene file for the culling camera.
void drawFlightControls(const FrameSnapshot& snapshot, AlgorithmAction& action) {
    const FlightState& flight = snapshot.flight;
    if (ImGui::Button(flight.recording ? "Stop flight" : "Record flight"))
        action.flight_record = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("R: the same. Keeps where you fly every frame time of the scene,\n"
                          "to save as the culling camera's path");
    ImGui::SameLine();
    ImGui::Text("%d keys, %.1f s", flight.keys, flight.seconds);
    if (flight.keys == 0 || flight.recording) return;
    const bool has_file = snapshot.scene_file && !snapshot.scene_file->empty();
    ImGui::BeginDisabled(!has_file);
    if (ImGui::Button("Save into the scene file")) action.flight_save = true;
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(has_file ? "Replaces camera.path (the old file is kept as FILE~)\n"
                                     "and reopens the scene: the culling camera flies it"
                                   : "The built-in scene has no file: open a scene file first");
    ImGui::SameLine();
    if (ImGui::Button("Discard")) action.flight_discard = true;
}

}  // namespace

AlgorithmAction drawAlgorithmPanel(const FrameSnapshot& snapshot) {
    AlgorithmAction action;
    if (!ImGui::CollapsingHeader("Algorithm and cameras", ImGuiTreeNodeFlags_DefaultOpen))
        return action;
    const std::vector<std::string>& names = *snapshot.algo_names;
    const char* current = snapshot.algo_index >= 0 && snapshot.algo_index < int(names.size())
                              ? names[size_t(snapshot.algo_index)].c_str()
                              : "?";
    ImGui::SetNextItemWidth(-scaledPixels(60));
    if (ImGui::BeginCombo("culler", current)) {
        for (int i = 0; i < int(names.size()); ++i) {
            const bool selected = i == snapshot.algo_index;
            if (ImGui::Selectable(names[size_t(i)].c_str(), selected) && !selected)
                action.select_algo = i;
            if (selected) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
    }
    const char* compared = snapshot.compare_index >= 0 && snapshot.compare_index < int(names.size())
                               ? names[size_t(snapshot.compare_index)].c_str()
                               : "none";
    ImGui::SetNextItemWidth(-scaledPixels(60));
    if (ImGui::BeginCombo("beside it", compared)) {
        if (ImGui::Selectable("none", snapshot.compare_index < 0) && snapshot.compare_index >= 0)
            action.compare_algo = -1;
        for (int i = 0; i < int(names.size()); ++i) {
            const bool selected = i == snapshot.compare_index;
            if (ImGui::Selectable(names[size_t(i)].c_str(), selected) && !selected)
                action.compare_algo = i;
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("A second culler on the same frame, in the right half of the view;\n"
                          "objects in one PVS and not the other are outlined in both");

    bool frozen = snapshot.culling_camera_frozen;
    if (ImGui::Checkbox("freeze culling camera", &frozen)) action.freeze_culling = frozen;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Cull from where the camera is now while objects keep moving");

    if (snapshot.scene->dimensions == 3) {
        int mode = int(snapshot.view_mode);
        ImGui::TextUnformatted("view:");
        ImGui::SameLine();
        bool changed = ImGui::RadioButton("orbit", &mode, int(ViewMode::Overview));
        ImGui::SameLine();
        changed |= ImGui::RadioButton("fly", &mode, int(ViewMode::Fly));
        ImGui::SameLine();
        changed |= ImGui::RadioButton("culling camera", &mode, int(ViewMode::CullingCamera));
        ImGui::SetCursorPosX(ImGui::GetCursorPosX() + ImGui::CalcTextSize("view: ").x);
        changed |= ImGui::RadioButton("orbit and culling camera side by side", &mode,
                                      int(ViewMode::Cameras));
        if (changed) action.view_mode = ViewMode(mode);
        if (snapshot.view_mode == ViewMode::Fly) drawFlightControls(snapshot, action);
        ImGui::TextDisabled(snapshot.view_mode == ViewMode::Fly
                                ? "WASD/QE move, right-drag look, shift fast"
                                : "right-drag rotate, wheel zoom");
    } else {
        ImGui::TextDisabled("top-down map: right-drag pan, wheel zoom");
    }
    return action;
}

}  // namespace gridcull
