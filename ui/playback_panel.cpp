#include "ui/playback_panel.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "ui/ui_units.h"

namespace gridcull {

PlaybackAction drawPlaybackPanel(const FrameSnapshot& snapshot) {
    PlaybackAction action;
    if (!ImGui::CollapsingHeader("Playback", ImGuiTreeNodeFlags_DefaultOpen)) return action;
    const int last = std::max(snapshot.scene->frames - 1, 0);

    if (ImGui::Button(snapshot.playing ? "Pause" : "Play", ImVec2(scaledPixels(60), 0)))
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
    ImGui::SetNextItemWidth(-scaledPixels(60));
    // Going backwards re-runs the cullers from their latest checkpoint: they
    // keep temporal state.
    if (ImGui::SliderInt("frame", &frame, 0, last)) action.seek_frame = frame;
    if (ImGui::IsItemHovered()) {
        const Checkpointing& saved = snapshot.checkpointing;
        if (saved.count > 0)
            ImGui::SetTooltip(
                "Space: play/pause, arrows: step, Esc: cancel a seek\n"
                "Going back restores a saved state of the culler and runs on from it:\n"
                "%d saved, every %d frames near this one (%.0f MiB of %.0f MiB)",
                saved.count, saved.interval, double(saved.bytes) / (1 << 20),
                double(saved.budget) / (1 << 20));
        else
            ImGui::SetTooltip(
                "Space: play/pause, arrows: step, Esc: cancel a seek\n"
                "This culler's state cannot be saved: going back runs again from frame 0");
    }
    if (snapshot.seek_target >= 0) {
        char label[64];
        std::snprintf(label, sizeof label, "seeking to frame %d", snapshot.seek_target);
        ImGui::ProgressBar(float(snapshot.seek_progress), ImVec2(-scaledPixels(60), 0), label);
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) action.cancel_seek = true;
    }
    return action;
}

}  // namespace gridcull
