// The trade curve (ui/trade_plot.h) written as a PNG: drawn by ImGui into an
// offscreen framebuffer of the process's hidden GL context, so the file shows
// what the window's trade panel shows. Needs an X display (xvfb-run when
// headless).
#pragma once
#include <memory>
#include <string>

#include "app/imgui_runtime.h"
#include "app/offscreen_target.h"
#include "ui/trade_plot.h"

namespace gridcull {

class TradePlotPng {
public:
    bool init(int width, int height, std::string& error);
    // Draws `input` and writes it to `path` (whole or not at all).
    bool write(const TradePlotInput& input, const std::string& path, std::string& error);

private:
    OffscreenTarget target_;
    std::unique_ptr<ImGuiRuntime> imgui_;
    int width_ = 0, height_ = 0;
};

}  // namespace gridcull
