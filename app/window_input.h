// Mouse and keyboard of the debugger window, applied to the Debugger: camera
// controls in the scene view, hover, and playback keys. Input that ImGui wants
// (over a panel, typing in a field) is left to ImGui.
#pragma once
#include "ui/layout.h"

struct GLFWwindow;

namespace gridcull {

class Debugger;

// Call once per frame after ImGui::NewFrame(). Keys: Space play/pause, Right /
// Left step, Home first frame, F freeze the culling camera, Esc cancel a seek
// running in the background, Ctrl+plus / Ctrl+minus scale the panels; Fly view: WASD move,
// Q/E down/up, Shift faster. Mouse: right-drag orbits / looks / pans, the wheel
// zooms, a left click picks (what it picks is the selected family's view's to say).
void handleWindowInput(Debugger& debugger, GLFWwindow* window, const WindowLayout& layout);

}  // namespace gridcull
