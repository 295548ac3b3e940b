// The input queue (app/input_queue.h): a press and release within one frame
// reach ImGui over two frames, one transition per key per frame, other keys
// unaffected, modifiers follow their keys. Seen failing without the queue:
// ImGui 1.86 then reports no press at all for such a tap.
#include "app/input_queue.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <gtest/gtest.h>

namespace gridcull {
namespace {

class InputQueueTest : public ::testing::Test {
protected:
    void SetUp() override {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(64, 64);
        io.DeltaTime = 1.0f / 60.0f;
        io.IniFilename = nullptr;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    }
    void TearDown() override { ImGui::DestroyContext(); }
    // One ImGui frame after the queue is applied; whether `key` was pressed in it.
    bool frame(int key) {
        queue_.apply(ImGui::GetIO());
        ImGui::NewFrame();
        const bool pressed = ImGui::IsKeyPressed(key, false);
        ImGui::EndFrame();
        return pressed;
    }
    InputQueue queue_;
};

TEST_F(InputQueueTest, ATapWithinOneFrameIsSeenOnce) {
    queue_.push(GLFW_KEY_SPACE, true);
    queue_.push(GLFW_KEY_LEFT, true);
    queue_.push(GLFW_KEY_LEFT, false);
    EXPECT_TRUE(frame(GLFW_KEY_LEFT));
    EXPECT_TRUE(ImGui::GetIO().KeysDown[GLFW_KEY_SPACE]);  // another key, same frame
    EXPECT_FALSE(queue_.empty());                          // the release waits
    EXPECT_FALSE(frame(GLFW_KEY_LEFT));
    EXPECT_FALSE(ImGui::GetIO().KeysDown[GLFW_KEY_LEFT]);
    EXPECT_TRUE(queue_.empty());
}

// Ctrl held around two taps of another key: its release waits behind them, so
// both taps are seen with Ctrl down.
TEST_F(InputQueueTest, EventsNeverOvertakeEachOther) {
    queue_.push(GLFW_KEY_LEFT_CONTROL, true);
    for (int i = 0; i < 2; ++i) {
        queue_.push(GLFW_KEY_EQUAL, true);
        queue_.push(GLFW_KEY_EQUAL, false);
    }
    queue_.push(GLFW_KEY_LEFT_CONTROL, false);
    int with_ctrl = 0;
    for (int i = 0; i < 8; ++i)
        if (frame(GLFW_KEY_EQUAL) && ImGui::GetIO().KeyCtrl) ++with_ctrl;
    EXPECT_EQ(with_ctrl, 2);
    EXPECT_FALSE(ImGui::GetIO().KeyCtrl);
    EXPECT_TRUE(queue_.empty());
}

TEST_F(InputQueueTest, TwoTapsAreTwoPresses) {
    for (int i = 0; i < 2; ++i) {
        queue_.push(GLFW_KEY_RIGHT, true);
        queue_.push(GLFW_KEY_RIGHT, false);
    }
    int presses = 0;
    for (int i = 0; i < 6; ++i) presses += frame(GLFW_KEY_RIGHT) ? 1 : 0;
    EXPECT_EQ(presses, 2);
}

TEST_F(InputQueueTest, ModifiersFollowTheirKeysAndBadKeysAreDropped) {
    queue_.push(GLFW_KEY_LEFT_CONTROL, true);
    queue_.push(-1, true);
    queue_.push(100000, true);
    frame(GLFW_KEY_A);
    EXPECT_TRUE(ImGui::GetIO().KeyCtrl);
    EXPECT_TRUE(queue_.empty());
    queue_.push(GLFW_KEY_LEFT_CONTROL, false);
    frame(GLFW_KEY_A);
    EXPECT_FALSE(ImGui::GetIO().KeyCtrl);
}

}  // namespace
}  // namespace gridcull
