// The timeline under the view: the whole run, frame by frame, with axes (frames
// along the bottom, each series' largest value in its label), the current
// frame as a cursor, the frames with false culls marked in the false-cull
// colour, and the frames not computed yet shaded. Several series at once:
// PVS size over the exact visible count (their gap is the culler's
// over-estimation), PVS/exact, cull and draw times (not in shots), one of the
// culler's counters.
// A click or a drag seeks; hovering tells the frame's values.
#pragma once
#include <vector>

#include "ui/frame_snapshot.h"
#include "ui/layout.h"

namespace gridcull {

struct TimelineState {
    bool counts = true;  // PVS size and exact visible count, on one scale
    bool ratio = false;  // PVS / exact visible (spikes where few objects are visible)
    bool cull_ms = false;
    bool draw_ms = false;
    int counter = -1;            // a Counter shown, -1: none
    std::vector<float> scratch;  // one series' points, reused
};

struct TimelineAction {
    int seek_frame = -1;  // >= 0: go to that frame
};

// Draws its own ImGui window over `rect` (nothing when rect is empty).
TimelineAction drawTimeline(const FrameSnapshot& snapshot, TimelineState& state,
                            const WindowRect& rect);

// The frame under x in a plot spanning [left, right) over `frames` frames
// (clamped), as a click on the timeline picks it.
int timelineFrameAt(float x, float left, float right, int frames);

}  // namespace gridcull
