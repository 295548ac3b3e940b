// The debugger's panels (ui/) run headless: an ImGui context with no backend, no
// GL, no window, fed a snapshot of a real culling session. With the mouse away
// they must ask for nothing; the layout must leave the scene view its place.
#include "ui/debugger_ui.h"

#include <cfloat>

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"
#include "tests/ui/headless_imgui.h"
#include "tests/ui/panel_test_helpers.h"
#include "ui/debugger_session.h"

namespace gridcull {
namespace {

TEST(WindowLayout, PanelColumnOnTheRight) {
    const WindowLayout wide = computeLayout(1280, 720, true);
    EXPECT_EQ(wide.panels.width, kPanelColumnWidth);
    EXPECT_EQ(wide.panels.x + wide.panels.width, 1280);
    EXPECT_EQ(wide.scene_view.x, 0);
    EXPECT_EQ(wide.scene_view.width, 1280 - kPanelColumnWidth);
    EXPECT_EQ(wide.scene_view.height, 720 - kTimelineHeight);
    EXPECT_EQ(wide.timeline.y, 720 - kTimelineHeight);
    EXPECT_EQ(wide.timeline.width, wide.scene_view.width);
    const WindowLayout narrow = computeLayout(400, 300, true);
    EXPECT_EQ(narrow.panels.width, 400 * 45 / 100);
    EXPECT_EQ(narrow.scene_view.width + narrow.panels.width, 400);
    const WindowLayout bare = computeLayout(640, 480, false);
    EXPECT_EQ(bare.panels.width, 0);
    EXPECT_EQ(bare.scene_view.width, 640);
    EXPECT_TRUE(bare.scene_view.contains(639.5, 479.5));
    EXPECT_FALSE(bare.scene_view.contains(640.0, 10.0));
    // --ui-scale 2 on a 1080p screen: a column twice as wide.
    const WindowLayout projector = computeLayout(1920, 1080, true, 2.0);
    EXPECT_EQ(projector.panels.width, 2 * kPanelColumnWidth);
    EXPECT_EQ(projector.scene_view.width, 1920 - 2 * kPanelColumnWidth);
    EXPECT_EQ(computeLayout(1280, 720, true, 4.0).panels.width, 1280 * 45 / 100);
}

class HeadlessImGui : public test::HeadlessImGuiTest {};

TEST_F(HeadlessImGui, PanelsAskForNothingWithoutInput) {
    KnobValues knobs;
    knobs.set("oracle-res", 96);
    DebuggerSession session(knobs);
    std::string error;
    ASSERT_TRUE(session.open(defaultScene(), "", "vfc", error)) << error;
    session.seek(6);

    const std::vector<std::string> names = algorithmNames(3);
    const std::string file;
    const std::vector<std::string> errors = {"x.json: objects[0].radius: must be > 0"};
    FrameSnapshot snapshot = test::snapshotOfSession(session, names, file, errors);
    snapshot.algo_index = 1;
    snapshot.hover.id = session.scene().objects[0].id;

    UiState state;
    const WindowLayout layout = computeLayout(1280, 720, true);
    for (int frame = 0; frame < 3; ++frame) {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(1280, 720);
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        ImGui::NewFrame();
        const UiActions actions = drawDebuggerUi(snapshot, state, layout);
        ImGui::Render();
        EXPECT_FALSE(actions.playback.toggle_play);
        EXPECT_FALSE(actions.playback.step);
        EXPECT_EQ(actions.playback.seek_frame, -1);
        EXPECT_FALSE(actions.algorithm.select_algo.has_value());
        EXPECT_FALSE(actions.algorithm.freeze_culling.has_value());
        EXPECT_FALSE(actions.algorithm.view_mode.has_value());
        EXPECT_FALSE(actions.scene.open);
    }
    const ImDrawData* draw = ImGui::GetDrawData();
    ASSERT_NE(draw, nullptr);
    EXPECT_GT(draw->TotalVtxCount, 1000);  // the panels and the legend drew
    // The object under the mouse is described by the cursor too.
    const ImGuiWindow* tooltip = ImGui::FindWindowByName("##Tooltip_00");
    ASSERT_NE(tooltip, nullptr);
    EXPECT_TRUE(tooltip->Active);

    // Nothing under the mouse: no tooltip.
    snapshot.hover.id = -1;
    ImGui::NewFrame();
    drawDebuggerUi(snapshot, state, layout);
    ImGui::Render();
    EXPECT_FALSE(ImGui::FindWindowByName("##Tooltip_00")->Active);
}

}  // namespace
}  // namespace gridcull
