#include "ui/scene_panel.h"

#include <filesystem>

#include <imgui.h>

#include "ui/ui_units.h"

namespace gridcull {

namespace {

// A list button beside the path field; the file picked, or null.
const std::string* pickScene(const FrameSnapshot& snapshot) {
    const std::vector<std::string>& choices = *snapshot.scene_choices;
    const std::string* picked = nullptr;
    if (!ImGui::BeginCombo("##pick", nullptr,
                           ImGuiComboFlags_NoPreview | ImGuiComboFlags_HeightLarge))
        return nullptr;
    if (choices.empty()) ImGui::TextDisabled("no scene files found");
    for (size_t i = 0; i < choices.size(); ++i) {
        if (i == 0 && snapshot.recent_scene_count > 0) ImGui::TextDisabled("opened recently");
        if (int(i) == snapshot.recent_scene_count) ImGui::TextDisabled("scene files");
        const std::string name = std::filesystem::path(choices[i]).filename().string();
        ImGui::PushID(int(i));
        if (ImGui::Selectable(name.c_str(), choices[i] == *snapshot.scene_file))
            picked = &choices[i];
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", choices[i].c_str());
        ImGui::PopID();
    }
    ImGui::EndCombo();
    return picked;
}

}  // namespace

SceneAction drawScenePanel(const FrameSnapshot& snapshot, ScenePanelState& state) {
    SceneAction action;
    if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return action;
    const Scene& scene = *snapshot.scene;
    const std::string& file = *snapshot.scene_file;
    // The file's name only: a full path would make shots depend on where the
    // source tree is. The full path is in the tooltip.
    const std::string shown =
        file.empty() ? "built in" : std::filesystem::path(file).filename().string();
    ImGui::Text("%s (%s)", scene.name.c_str(), shown.c_str());
    if (!file.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", file.c_str());
    const glm::ivec3 r = scene.grid.resolution;
    if (scene.dimensions == 3)
        ImGui::Text("3D, %zu objects, grid %dx%dx%d", scene.objects.size(), r.x, r.y, r.z);
    else
        ImGui::Text("2D, %zu objects, grid %dx%d", scene.objects.size(), r.x, r.y);
    ImGui::Text("%d frames, dt %.3f s", scene.frames, scene.dt);

    ImGui::SetNextItemWidth(-scaledPixels(80));
    const bool entered =
        ImGui::InputTextWithHint("##path", "path/to/scene.json", state.path, sizeof state.path,
                                 ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Open") || entered) && state.path[0] != '\0') {
        action.open = true;
        action.path = state.path;
    }
    if (snapshot.scene_choices) {
        ImGui::SameLine();
        if (const std::string* picked = pickScene(snapshot)) {
            action.open = true;
            action.path = *picked;
        }
    }
    const std::vector<std::string>& errors = *snapshot.scene_errors;
    if (!errors.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(240, 110, 90, 255));
        ImGui::TextUnformatted("not opened, scene kept:");
        for (const std::string& message : errors) ImGui::TextWrapped("%s", message.c_str());
        ImGui::PopStyleColor();
    }
    if (snapshot.note && !snapshot.note->empty()) {
        const Rgb c = cullingCameraColor();  // the window's own voice: the camera's yellow
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(c.r, c.g, c.b, 1.0f));
        ImGui::TextWrapped("%s", snapshot.note->c_str());
        ImGui::PopStyleColor();
    }
    return action;
}

}  // namespace gridcull
