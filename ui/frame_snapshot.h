// Everything the debugger panels show about one frame, as a const view that the
// app fills before drawing the panels. Pointers borrow from the app and stay
// valid only while the panels are drawn; the panels never keep them.
#pragma once
#include <string>
#include <vector>

#include "culling/api/culler.h"
#include "culling/api/knobs.h"
#include "culling/scene/scene.h"
#include "grid/aabb.h"
#include "ui/layout.h"
#include "ui/object_state.h"
#include "ui/view_mode.h"

namespace gridcull {

struct TradeCurveView;  // ui/trade_panel.h

// Per-frame values for the plots, one slot per scene frame; slots 0..frame are
// filled (culling always runs from frame 0 up to the current frame).
struct FrameHistory {
    std::vector<float> pvs_size;
    std::vector<float> exact_visible;
    std::vector<float> false_culls;
    std::vector<float> cull_ms;    // the selected culler's, wall clock
    std::vector<float> draw_ms;    // 0 for frames that were never drawn
    std::vector<CullStats> stats;  // the selected culler's counters

    // Sizes every series to `frames` slots of 0 (allocates only when it grows).
    void resize(int frames);
    // Copies slot `frame` of every series from `from` (the same size).
    void copyFrame(const FrameHistory& from, int frame);
};

// The object under the mouse in the 3D / 2D view.
struct HoverInfo {
    int id = -1;  // -1: nothing under the mouse
    ShapeKind shape = ShapeKind::Sphere;
    ObjectState state = ObjectState::Culled;
    Aabb bounds;  // world bounds at the current t
    MotionKind motion = MotionKind::Static;
    double max_speed = 0.0;
    double distance = 0.0;  // 3D: along the mouse ray; 2D: 0
};

// The session's checkpoints, as the playback panel reports them.
struct Checkpointing {
    int count = 0;  // 0: none (the culler cannot be copied, or nothing run yet)
    int interval = 0;
    size_t bytes = 0;
    size_t budget = 0;
};

// What the last change of knobs in the window cost (shown beside the knobs).
struct KnobApplyCost {
    bool valid = false;
    int frames = 0;                 // frames re-run to come back to where the user was
    double rerun_ms = 0.0;          // wall time of that re-run
    double cull_ms_before = 0.0;    // median cull time over those frames, old knobs
    double cull_ms_after = 0.0;     // the same with the new ones
    double pvs_ratio_before = 0.0;  // PVS over exact visible, summed over those frames
    double pvs_ratio_after = 0.0;
};

// One part of the scene view and what its caption says (ui/scene_panes.h).
struct PaneCaption {
    WindowRect rect;
    std::string title;   // "A: " and the algorithm's name, "culling camera"
    std::string detail;  // a line of figures, "" for none
};

class LessonPlayer;

// A camera path being flown (ui/flight_recorder.h), for the cameras panel.
struct FlightState {
    bool recording = false;
    int keys = 0;          // kept so far (0: nothing flown)
    double seconds = 0.0;  // flown so far
};

struct FrameSnapshot {
    const Scene* scene = nullptr;
    int frame = 0;
    double t = 0.0;
    bool playing = false;
    int seek_target = -1;        // a background seek's target, or -1
    double seek_progress = 0.0;  // its share of frames culled, 0 to 1
    Checkpointing checkpointing;

    // The algorithms the window offers for this scene (those of the registry that
    // run on its dimension), and the selected one.
    const std::vector<std::string>* algo_names = nullptr;
    int algo_index = 0;                              // into algo_names
    int compare_index = -1;  // the culler shown beside it (into algo_names), -1: none
    const FrameResult* result = nullptr;             // the selected culler at `frame`
    const FrameResult* exact = nullptr;              // the oracle at `frame`
    const std::vector<int>* false_culled = nullptr;  // ids, ascending
    const FrameHistory* history = nullptr;           // frames 0..frame (and more, once visited)
    // The run computed ahead (frames 0..timeline_frames-1; null: none).
    const FrameHistory* timeline = nullptr;
    int timeline_frames = 0;
    const KnobValues* knobs = nullptr;  // the values the cullers were made with
    KnobApplyCost knob_cost;
    const TradeCurveView* trade = nullptr;  // the window's trade sweep (null: none)

    HoverInfo hover;
    double draw_ms = 0.0;      // CPU time of the last scene draw, up to glFinish
    bool show_timings = true;  // false in shots: times differ from run to run

    ViewMode view_mode = ViewMode::Overview;
    bool culling_camera_frozen = false;
    FlightState flight;

    const std::string* scene_file = nullptr;  // "" for the built-in scene
    // Scene files to pick from: those opened in this window, most recent first
    // (recent_scene_count of them), then the scene files found beside the
    // current one and in ./scenes (may be null: no picker).
    const std::vector<std::string>* scene_choices = nullptr;
    int recent_scene_count = 0;
    const std::vector<std::string>* scene_errors = nullptr;  // of the last failed open
    // What the window did on its own that the user should know, e.g. that opening
    // a 2D scene switched the culler from a 3D-only one ("" for nothing).
    const std::string* note = nullptr;

    // The scene view's panes when it is split (A/B, or both cameras); null or
    // empty when it is one.
    const std::vector<PaneCaption>* panes = nullptr;
    // The lesson playing (null: none).
    const LessonPlayer* lesson = nullptr;
};

}  // namespace gridcull
