// The colour key of the scene view: one swatch per object state and the
// culling camera's colour, with what each means.
#pragma once
#include "ui/frame_snapshot.h"

namespace gridcull {

// Draws into the current ImGui window.
void drawLegendPanel(const FrameSnapshot& snapshot);

}  // namespace gridcull
