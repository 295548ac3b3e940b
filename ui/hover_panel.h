// The object under the mouse: id, shape, state, bounds at the current time.
#pragma once
#include "ui/frame_snapshot.h"

namespace gridcull {

// Draws into the current ImGui window.
void drawHoverPanel(const FrameSnapshot& snapshot);

}  // namespace gridcull
