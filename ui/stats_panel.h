// Statistics of the current frame: PVS size, exact visible count, false culls,
// times, the culler's own counters (their history is the timeline's).
#pragma once
#include "ui/frame_snapshot.h"

namespace gridcull {

// Draws into the current ImGui window.
void drawStatsPanel(const FrameSnapshot& snapshot);

}  // namespace gridcull
