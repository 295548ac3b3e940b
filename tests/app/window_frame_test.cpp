// The window driven headless with synthetic input (app/window_frame.h): key taps
// pushed into the input queue as GLFW would deliver them, press and release
// within one frame, step the debugger forward and back; a step back replays
// from a checkpoint (at most its interval of frames, asserted, not timed) and
// the panels' snapshot shows what running the frames in order shows; a long
// seek asked for by the panels runs in the background, shows its progress in
// the snapshot, and Esc cancels it. Needs an X display (xvfb-run in the tests).
#include <GLFW/glfw3.h>

#include <gtest/gtest.h>

#include "app/debugger.h"
#include "app/gl_context.h"
#include "app/imgui_runtime.h"
#include "app/input_queue.h"
#include "app/window_frame.h"
#include "culling/io/scene_loader.h"
#include "run_command.h"

namespace gridcull {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

class WindowFrameTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(window_.create(kWidth, kHeight, "gridcull test", false, error)) << error;
        ASSERT_TRUE(imgui_.init(window_.get(), error)) << error;
        InputQueue::install(window_.get(), &input_);
        SceneLoadResult loaded = loadSceneFile(test::sourcePath("scenes/hidden-movers-3d.json"));
        ASSERT_TRUE(loaded.scene);
        scene_ = std::move(*loaded.scene);
        options_.algo = "hzb-tbv";
        options_.knobs.set("oracle-res", 96);
    }
    void frames(Debugger& debugger, int count) {
        for (int i = 0; i < count; ++i)
            drawWindowFrame(debugger, window_.get(), input_, kWidth, kHeight, kWidth, kHeight);
    }
    void tap(int key, int times = 1) {
        for (int i = 0; i < times; ++i) {
            input_.push(key, true);
            input_.push(key, false);
        }
    }
    // The PVS at `frame` when the frames are culled in order.
    std::vector<int> inOrder(int frame) {
        DebuggerSession session(options_.knobs);
        std::string error;
        EXPECT_TRUE(session.open(scene_, "", options_.algo, error)) << error;
        for (int f = 1; f <= frame; ++f) session.step();
        return session.result().pvs;
    }

    GlWindow window_;
    ImGuiRuntime imgui_;
    InputQueue input_;
    Scene scene_;
    ViewOptions options_;
};

TEST_F(WindowFrameTest, KeyTapsStepForwardAndBackAndEscCancelsASeek) {
    Debugger debugger(options_);
    std::string error;
    ASSERT_TRUE(debugger.init(scene_, error)) << error;
    frames(debugger, 1);

    // Ten taps, each pressed and released within one frame: none is lost.
    tap(GLFW_KEY_RIGHT, 10);
    frames(debugger, 20);
    EXPECT_TRUE(input_.empty());
    FrameSnapshot shown = debugger.snapshot();
    EXPECT_EQ(shown.frame, 10);
    EXPECT_EQ(debugger.session().lastReplayedFrames(), 1);

    tap(GLFW_KEY_LEFT, 3);
    frames(debugger, 6);
    shown = debugger.snapshot();
    EXPECT_EQ(shown.frame, 7);
    EXPECT_GE(debugger.session().lastReplayedFrames(), 1);
    EXPECT_LE(debugger.session().lastReplayedFrames(), kDefaultCheckpointInterval);
    EXPECT_EQ(shown.result->pvs, inOrder(7));
    EXPECT_EQ(shown.checkpointing.interval, kDefaultCheckpointInterval);
    EXPECT_GE(shown.checkpointing.count, 2);

    // The frame slider asks for frame 120: culled in the background.
    UiActions slider;
    slider.playback.seek_frame = 120;
    debugger.apply(slider);
    shown = debugger.snapshot();
    EXPECT_EQ(shown.seek_target, 120);
    EXPECT_EQ(shown.frame, 7);  // still showing where it was
    for (int i = 0; i < 100000 && debugger.session().seeking(); ++i) frames(debugger, 1);
    shown = debugger.snapshot();
    EXPECT_EQ(shown.seek_target, -1);
    EXPECT_EQ(shown.frame, 120);
    EXPECT_EQ(shown.result->pvs, inOrder(120));

    // Another long seek, cancelled with Esc: the view stays at 120.
    slider.playback.seek_frame = scene_.frames - 1;
    debugger.apply(slider);
    ASSERT_TRUE(debugger.session().seeking());
    tap(GLFW_KEY_ESCAPE);
    frames(debugger, 2);
    EXPECT_FALSE(debugger.session().seeking());
    EXPECT_EQ(debugger.snapshot().frame, 120);

    // Ctrl+plus twice, Ctrl+minus once: the panels a fifth larger, within range.
    input_.push(GLFW_KEY_LEFT_CONTROL, true);
    tap(GLFW_KEY_EQUAL, 2);
    tap(GLFW_KEY_MINUS);
    input_.push(GLFW_KEY_LEFT_CONTROL, false);
    frames(debugger, 8);
    EXPECT_NEAR(debugger.uiScale(), 1.2, 1e-9);
    EXPECT_TRUE(input_.empty());
}

}  // namespace
}  // namespace gridcull
