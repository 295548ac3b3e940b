// The object under the mouse: id, shape, state, bounds at the current time, in
// the column's panel and in a tooltip by the cursor (where the eye is: the
// panel may be below the fold of a small screen).
#pragma once
#include "ui/frame_snapshot.h"

namespace gridcull {

// Draws into the current ImGui window.
void drawHoverPanel(const FrameSnapshot& snapshot);
// A tooltip at the mouse with the same details, while an object is under it.
void drawHoverTooltip(const FrameSnapshot& snapshot);

}  // namespace gridcull
