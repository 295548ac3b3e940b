// All the debugger's panels for one frame, in one column at a fixed place on the
// right: scene, playback, algorithm and cameras, statistics, the object under
// the mouse, legend. Returns what the user asked for;
// the app applies it after the frame.
#pragma once
#include "ui/algorithm_panel.h"
#include "ui/frame_snapshot.h"
#include "ui/layout.h"
#include "ui/lazy_grid/lazy_grid_panel.h"
#include "ui/playback_panel.h"
#include "ui/rgvc/rgvc_panel.h"
#include "ui/scene_panel.h"
#include "ui/stats_panel.h"

namespace gridcull {

// Panel state that belongs to the UI alone (text being typed, plot choice).
struct UiState {
    StatsPanelState stats;
    ScenePanelState scene;
    LazyGridPanelState lazy_grid;
};

struct UiActions {
    PlaybackAction playback;
    AlgorithmAction algorithm;
    SceneAction scene;
    RgvcAction rgvc;
    LazyGridAction lazy_grid;
};

// Call between ImGui::NewFrame() and ImGui::Render(). Precondition: the
// snapshot's pointers are all set.
UiActions drawDebuggerUi(const FrameSnapshot& snapshot, UiState& state,
                         const WindowLayout& layout);

}  // namespace gridcull
