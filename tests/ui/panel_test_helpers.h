// What the panel tests share: the FrameSnapshot fields every panel test fills
// from a DebuggerSession, and the whole column drawn headless with and without a
// family's view.
#pragma once
#include <cfloat>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <imgui.h>

#include "ui/debugger_session.h"
#include "ui/debugger_ui.h"
#include "ui/frame_snapshot.h"

namespace gridcull::test {

// The scene, frame, time, results, history and scene-file fields, borrowing
// from the session and the given lists, which must outlive the snapshot's use.
inline FrameSnapshot snapshotOfSession(const DebuggerSession& session,
                                       const std::vector<std::string>& algo_names,
                                       const std::string& scene_file,
                                       const std::vector<std::string>& scene_errors) {
    FrameSnapshot snapshot;
    snapshot.scene = &session.scene();
    snapshot.frame = session.frame();
    snapshot.t = session.t();
    snapshot.algo_names = &algo_names;
    snapshot.result = &session.result();
    snapshot.exact = &session.exactResult();
    snapshot.false_culled = &session.falseCulled();
    snapshot.history = &session.history();
    snapshot.knobs = &session.knobs();
    snapshot.scene_file = &scene_file;
    snapshot.scene_errors = &scene_errors;
    return snapshot;
}

// Draws the whole panel column headless (in an ImGui context the caller made;
// tall enough that no panel is clipped, the mouse away) three times with the
// family's `view` and once without it. No pass may ask for anything. Returns how
// many more vertices the column has with the family's panel than without it.
inline int familyPanelVertices(const FrameSnapshot& snapshot, FamilyView* view,
                               const FamilyViewContext& context) {
    UiState state;
    const WindowLayout layout = computeLayout(1280, 4000, true);
    int with = 0, without = 0;
    for (int pass = 0; pass < 4; ++pass) {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(1280, 4000);
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        ImGui::NewFrame();
        // Pass 3: another culler, whose family has no view.
        const UiActions actions =
            drawDebuggerUi(snapshot, state, layout, pass == 3 ? nullptr : view, context);
        ImGui::Render();
        EXPECT_TRUE(actions.family.knobs.empty()) << "pass " << pass;
        (pass == 3 ? without : with) = ImGui::GetDrawData()->TotalVtxCount;
    }
    return with - without;
}

}  // namespace gridcull::test
