// Statistics of the current frame (PVS size, exact visible count, false culls,
// times, the culler's own counters) and their history over frames as plots.
#pragma once
#include "ui/frame_snapshot.h"

namespace gridcull {

// Which series the second plot shows; the first always overlays PVS size and
// the exact visible count.
enum class StatsSeries { FalseCulls, CullMs, DrawMs };

struct StatsPanelState {
    StatsSeries series = StatsSeries::FalseCulls;
};

// Draws into the current ImGui window. Cost: O(frames) for the plots.
void drawStatsPanel(const FrameSnapshot& snapshot, StatsPanelState& state);

}  // namespace gridcull
