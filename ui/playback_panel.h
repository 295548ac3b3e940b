// Playback: play / pause, step one frame, scrub to any frame; while a long
// seek runs in the background, its progress and a button that cancels it.
#pragma once
#include "ui/frame_snapshot.h"

namespace gridcull {

struct PlaybackAction {
    bool toggle_play = false;
    bool step = false;         // one frame forward (pauses)
    int seek_frame = -1;       // >= 0: show this frame (pauses when it came from the slider)
    bool cancel_seek = false;  // stop the seek running in the background
};

// Draws into the current ImGui window. Cost: a few widgets.
PlaybackAction drawPlaybackPanel(const FrameSnapshot& snapshot);

}  // namespace gridcull
