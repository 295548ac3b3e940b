// Playback: play / pause, step one frame, scrub to any frame.
#pragma once
#include "ui/frame_snapshot.h"

namespace gridcull {

struct PlaybackAction {
    bool toggle_play = false;
    bool step = false;    // one frame forward (pauses)
    int seek_frame = -1;  // >= 0: show this frame (pauses when it came from the slider)
};

// Draws into the current ImGui window. Cost: a few widgets.
PlaybackAction drawPlaybackPanel(const FrameSnapshot& snapshot);

}  // namespace gridcull
