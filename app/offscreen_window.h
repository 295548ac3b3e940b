// The window drawn off screen, exactly as the window draws it, frame after
// frame: a hidden GL context, a framebuffer object of the requested size, ImGui
// without a platform backend (a fixed time step, the mouse away), one Debugger.
// `shot` draws one frame with it, `record` a range of frames.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/debugger.h"
#include "app/gl_context.h"
#include "app/imgui_runtime.h"
#include "app/offscreen_target.h"
#include "app/window.h"
#include "ui/layout.h"

namespace gridcull {

class OffscreenWindow {
public:
    // Checks options.view and options.frame, sets up GL and ImGui and culls up
    // to options.frame. False and `error` when it cannot (no display, bad view).
    bool open(const Scene& scene, const ViewOptions& options, std::string& error);
    Debugger& debugger() { return *debugger_; }
    // Draws the debugger's current frame: width * height * 4 bytes, the top row
    // first, opaque.
    bool draw(std::vector<uint8_t>& rgba, std::string& error);
    int width() const { return width_; }
    int height() const { return height_; }

private:
    // Declared in the order they are made; destroyed the other way round, the
    // GL context last.
    GlWindow window_;
    OffscreenTarget target_;
    ImGuiRuntime imgui_;
    std::unique_ptr<Debugger> debugger_;
    bool panels_ = true;
    int width_ = 0, height_ = 0;
    WindowLayout layout_;
};

}  // namespace gridcull
