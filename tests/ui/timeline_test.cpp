// The timeline (ui/timeline_run.h, ui/timeline_panel.h): the run computed ahead
// on a worker equals the frames run in order, frame for frame; stopping it
// midway is clean; a click on the plot asks for the frame under the mouse.
#include <cfloat>
#include <chrono>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <imgui.h>

#include "culling/io/scene_loader.h"
#include "tests/ui/headless_imgui.h"
#include "tests/ui/panel_test_helpers.h"
#include "ui/debugger_session.h"
#include "ui/timeline_panel.h"

namespace gridcull {
namespace {

KnobValues fastKnobs() {
    KnobValues knobs;
    knobs.set("oracle-res", 96);
    return knobs;
}

TEST(TimelineRun, ComputedAheadEqualsTheFramesRunInOrder) {
    SceneLoadResult loaded =
        loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/hidden-movers-3d.json");
    ASSERT_TRUE(loaded.scene);
    const Scene& scene = *loaded.scene;
    std::string error;
    DebuggerSession ahead(fastKnobs());
    ahead.setComputeAhead(true);
    ASSERT_TRUE(ahead.open(scene, "", "hzb-tbv", error)) << error;
    DebuggerSession in_order(fastKnobs());
    ASSERT_TRUE(in_order.open(scene, "", "hzb-tbv", error)) << error;
    while (in_order.step()) {
    }
    FrameHistory history;
    int done = 0;
    for (int i = 0; i < 20000 && done < scene.frames; ++i) {
        done = ahead.computedAhead(history);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ASSERT_EQ(done, scene.frames);
    EXPECT_EQ(ahead.frame(), 0);  // the session itself stayed where it was
    const FrameHistory& want = in_order.history();
    for (int f = 0; f < scene.frames; ++f) {
        const size_t i = size_t(f);
        ASSERT_EQ(history.pvs_size[i], want.pvs_size[i]) << "frame " << f;
        ASSERT_EQ(history.exact_visible[i], want.exact_visible[i]) << "frame " << f;
        ASSERT_EQ(history.false_culls[i], want.false_culls[i]) << "frame " << f;
        ASSERT_EQ(history.stats[i].values, want.stats[i].values) << "frame " << f;
    }
    // The run ahead left its checkpoints: a seek far ahead replays an interval.
    ahead.seek(scene.frames - 1);
    EXPECT_LE(ahead.lastReplayedFrames(), kDefaultCheckpointInterval);
    EXPECT_EQ(ahead.result().pvs, in_order.result().pvs);  // in_order is at the last frame
    // Another culler starts it over; closing the session midway stops it.
    ASSERT_TRUE(ahead.selectAlgorithm("rgvc", error)) << error;
    EXPECT_LT(ahead.computedAhead(history), scene.frames);
}

TEST(TimelinePanel, AFrameUnderTheMouse) {
    EXPECT_EQ(timelineFrameAt(100.0f, 100.0f, 300.0f, 101), 0);
    EXPECT_EQ(timelineFrameAt(300.0f, 100.0f, 300.0f, 101), 100);
    EXPECT_EQ(timelineFrameAt(200.0f, 100.0f, 300.0f, 101), 50);
    EXPECT_EQ(timelineFrameAt(-50.0f, 100.0f, 300.0f, 101), 0);
    EXPECT_EQ(timelineFrameAt(999.0f, 100.0f, 300.0f, 101), 100);
    EXPECT_EQ(timelineFrameAt(150.0f, 100.0f, 300.0f, 1), 0);
}

class TimelineImGui : public test::HeadlessImGuiTest {};

TEST_F(TimelineImGui, AClickOnThePlotSeeksThere) {
    DebuggerSession session(fastKnobs());
    std::string error;
    ASSERT_TRUE(session.open(defaultScene(), "", "vfc", error)) << error;
    session.seek(30);
    const std::vector<std::string> names = {"vfc"};
    const std::string file;
    const std::vector<std::string> errors;
    FrameSnapshot snapshot = test::snapshotOfSession(session, names, file, errors);
    TimelineState state;
    const WindowRect rect{0, 600, 900, 120};
    // Pressed at three quarters of the way along, held for two frames.
    int asked = -1;
    for (int frame = 0; frame < 4; ++frame) {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(1280, 720);
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = frame == 0 ? ImVec2(-FLT_MAX, -FLT_MAX) : ImVec2(0.75f * 900.0f, 690.0f);
        io.MouseDown[0] = frame >= 2;
        ImGui::NewFrame();
        const TimelineAction action = drawTimeline(snapshot, state, rect);
        ImGui::Render();
        if (action.seek_frame >= 0) asked = action.seek_frame;
    }
    const int frames = session.scene().frames;
    EXPECT_NEAR(asked, 0.75 * (frames - 1), 0.02 * frames);
}

}  // namespace
}  // namespace gridcull
