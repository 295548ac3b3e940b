#include "ui/playback_panel.h"

#include <algorithm>

#include <imgui.h>

namespace gridcull {

PlaybackAction drawPlaybackPanel(const FrameSnapshot& snapshot) {
    PlaybackAction action;
    if (!ImGui::CollapsingHeader("Playback", ImGuiTreeNodeFlags_DefaultOpen)) return action;
    const int last = std::max(snapshot.scene->frames - 1, 0);

    if (ImGui::Button(snapshot.playing ? "Pause" : "Play", ImVec2(60, 0)))
        action.toggle_play = true;
    ImGui::SameLine();
    if (ImGui::Button("|<")) action.seek_frame = 0;
    ImGui::SameLine();
    ImGui::BeginDisabled(snapshot.frame <= 0);
    if (ImGui::Button("<")) action.seek_frame = snapshot.frame - 1;
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(snapshot.frame >= last);
    if (ImGui::Button("Step >")) action.step = true;
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::Text("t = %.3f s", snapshot.t);

    int frame = snapshot.frame;
    ImGui::SetNextItemWidth(-60);
    // Going backwards re-runs the cullers from frame 0: they keep temporal state.
    if (ImGui::SliderInt("frame", &frame, 0, last)) action.seek_frame = frame;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Space: play/pause, arrows: step");
    return action;
}

}  // namespace gridcull
