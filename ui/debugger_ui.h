// All the debugger's panels for one frame, in one column at a fixed place on the
// right: the lesson (while one plays), scene, playback, algorithm and cameras,
// the overlay presets and the selected family's own panel (ui/family_view.h), the knobs (collapsed until opened), statistics, the object under the mouse,
// legend. Returns what the user asked for; the app applies it after the frame.
#pragma once
#include "ui/algorithm_panel.h"
#include "ui/family_view.h"
#include "ui/frame_snapshot.h"
#include "ui/knobs_panel.h"
#include "ui/layout.h"
#include "ui/lesson_panel.h"
#include "ui/playback_panel.h"
#include "ui/scene_panel.h"
#include "ui/stats_panel.h"
#include "ui/timeline_panel.h"

namespace gridcull {

// Panel state that belongs to the UI alone (text being typed, plot choice).
struct UiState {
    ScenePanelState scene;
    KnobsPanelState knobs;
    TimelineState timeline;
};

struct UiActions {
    PlaybackAction playback;
    AlgorithmAction algorithm;
    SceneAction scene;
    FamilyAction family;
    KnobsAction knobs;
    TimelineAction timeline;
    LessonAction lesson;
    std::optional<OverlayPreset> overlay_preset;  // for the selected family's overlay
};

// Call between ImGui::NewFrame() and ImGui::Render(). Precondition: the
// snapshot's pointers are all set. `family` is the selected algorithm's family
// view (null for a family without one), drawn with `family_context`.
UiActions drawDebuggerUi(const FrameSnapshot& snapshot, UiState& state, const WindowLayout& layout,
                         FamilyView* family = nullptr,
                         const FamilyViewContext& family_context = {});

}  // namespace gridcull
