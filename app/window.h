// The desktop debugger and its off-screen twin. Both draw the same frame the same
// way, so `gridcull shot` is a picture of what the window shows.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "culling/api/knobs.h"
#include "culling/registry/registry.h"
#include "culling/scene/scene.h"
#include "ui/lesson.h"
#include "ui/overlay_preset.h"

namespace gridcull {

// The range of --ui-scale and of Ctrl+plus / Ctrl+minus.
constexpr double kMinUiScale = 0.5, kMaxUiScale = 4.0;

struct ViewOptions {
    std::string algo = defaultAlgorithm();  // the culler whose PVS colours the objects
    std::string compare;                   // a second culler shown beside it ("": none)
    // The overlay preset family views start with (--overlays; unset: each
    // family's first, or its first when it does not offer this one).
    std::optional<OverlayPreset> overlays;
    int width = 1280;                      // window / image size in pixels
    int height = 720;
    int frame = 0;              // first frame shown (shot: the frame drawn)
    std::string view = "main";  // shot: which view to draw, see viewNames()
    KnobValues knobs;           // every culler the window makes is made with these
    KnobValues view_flags;      // the families' view flags (ui/registry/family_views.h)
    double ui_scale = 1.0;      // panels' font and sizes (--ui-scale; Ctrl+plus/minus)
    bool compute_ahead = false;  // the timeline computed ahead in the background (window)
    bool play = false;          // window: start playing instead of paused
    int exit_after_frames = 0;  // window: close by itself after this many frames (0: never)
    // A lesson to play (app/lesson_file.h checked it), from step lesson_step;
    // lesson_step_finished: that step's animation at its end (shots).
    std::shared_ptr<const Lesson> lesson;
    int lesson_step = 0;
    bool lesson_step_finished = false;
};

// The names `shot --view` accepts ("main": the whole window with its panels, ...).
const char* viewNamesHelp();

// Opens the window on `scene` and runs until it is closed. Returns the process
// exit status (0, or 1 with a message on stderr when no window can be opened).
int runWindow(const Scene& scene, const ViewOptions& options);

// Renders frame options.frame exactly as the window would show it (culling run
// from frame 0 up to it, fixed ImGui state, mouse far away) to a PNG at out_png.
// Returns false and sets `error` when it cannot (no display, bad view name, file).
// Never leaves a partial PNG behind.
bool renderShot(const Scene& scene, const ViewOptions& options, const std::string& out_png,
                std::string& error);

}  // namespace gridcull
