// An ImGui context for the tests that draw headless (no window, no GL): no
// imgui.ini written, the font atlas built (NewFrame needs it; its texture is
// never uploaded).
#pragma once
#include <gtest/gtest.h>
#include <imgui.h>

namespace gridcull::test {

inline void createHeadlessImGui() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
}

// A fixture that owns one such context per test.
class HeadlessImGuiTest : public ::testing::Test {
protected:
    void SetUp() override { createHeadlessImGui(); }
    void TearDown() override { ImGui::DestroyContext(); }
};

// Starts a frame of a width x height display, the pointer at (x, y) and the left
// button down or not, and opens an undecorated window `name` filling it. The
// caller draws, then ImGui::End() and ImGui::Render().
inline void beginWholeDisplayWindow(const char* name, float width, float height, float x, float y,
                                    bool button_down) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(width, height);
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = ImVec2(x, y);
    io.MouseDown[0] = button_down;
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(io.DisplaySize);
    ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoDecoration);
}

}  // namespace gridcull::test

