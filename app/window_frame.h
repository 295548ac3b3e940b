// One frame of the debugger window: queued key events into ImGui, the panels,
// the pointer and keys applied to the debugger, playback, the scene and the
// panels drawn into the default framebuffer, the panels' actions applied. The
// window calls it once per frame; tests call it to drive a hidden window with
// synthetic input (pushed into the InputQueue).
#pragma once
struct GLFWwindow;

namespace gridcull {

class Debugger;
class InputQueue;

// The window's background, behind the scene view and the panels (shots too).
constexpr float kWindowClear[4] = {0.10f, 0.11f, 0.13f, 1.0f};

// Window size in screen coordinates and framebuffer size in pixels (they
// differ on high-DPI screens). Does not swap buffers.
void drawWindowFrame(Debugger& debugger, GLFWwindow* window, InputQueue& input, int width,
                     int height, int fb_width, int fb_height);

}  // namespace gridcull
