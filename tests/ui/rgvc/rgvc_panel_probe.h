// Headless ImGui for the rgvc panel tests: draws a piece of panel in a window
// of its own and returns its text (ImGui's log capture), or finds where a
// click on it changes something (a sweep of clicks over the window, each a
// press and a release frame). The caller owns no ImGui context: each call
// makes and destroys one.
#pragma once
#include <functional>
#include <string>

#include <imgui.h>
#include <imgui_internal.h>

namespace gridcull::test {

class PanelProbe {
public:
    PanelProbe() {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(kWidth, kHeight);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    }
    ~PanelProbe() { ImGui::DestroyContext(); }
    PanelProbe(const PanelProbe&) = delete;
    PanelProbe& operator=(const PanelProbe&) = delete;

    // The text `draw` puts into the window (labels of buttons included).
    std::string text(const std::function<void()>& draw) {
        std::string out;
        frame([&] {
            ImGui::LogBegin(ImGuiLogType_Buffer, -1);
            draw();
            out = GImGui->LogBuffer.c_str();
            ImGui::LogFinish();
        });
        return out;
    }

    // Clicks (press, then release) at points of the window `step` pixels
    // apart, row by row, until done() is true after a click; false when none
    // makes it so.
    bool clickUntil(const std::function<void()>& draw, const std::function<bool()>& done,
                    float step = 4.0f) {
        for (int settle = 0; settle < 2; ++settle) frame(draw);
        for (float y = 2.0f; y < kHeight; y += step)
            for (float x = 2.0f; x < kWidth; x += 3.0f * step) {
                ImGuiIO& io = ImGui::GetIO();
                io.MousePos = ImVec2(x, y);
                io.MouseDown[0] = false;
                frame(draw);
                io.MouseDown[0] = true;
                frame(draw);
                io.MouseDown[0] = false;
                frame(draw);
                if (done()) return true;
            }
        return false;
    }

    static constexpr float kWidth = 380.0f, kHeight = 240.0f;

private:
    void frame(const std::function<void()>& draw) {
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(kWidth, kHeight));
        ImGui::Begin("probe", nullptr,
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar);
        draw();
        ImGui::End();
        ImGui::Render();
    }
};

}  // namespace gridcull::test
