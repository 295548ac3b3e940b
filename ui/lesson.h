// A lesson: a list of steps a lecturer plays in the window (`gridcull view
// --lesson FILE`), each setting up one frame of one scene (culler, cameras,
// overlays, what to highlight) under a caption in plain language that names the
// paper's section. docs/lesson-format.md describes the file; app/lesson_file.h
// reads and checks it; app/lesson_player.h plays it.
#pragma once
#include <string>
#include <vector>

#include "culling/api/knobs.h"
#include "ui/overlay_preset.h"
#include "ui/view_mode.h"

namespace gridcull {

// A family view flag (a layer number, say) counted up one value at a time while
// the step is shown, so chess layers (or any numbered state) appear one by one.
struct LessonAnimation {
    std::string flag;  // "": none
    int from = 0, to = 0;
    double seconds_per_value = 0.6;
};

struct LessonStep {
    std::string title;
    std::string caption;  // sentences, shown under the title
    std::string section;  // the paper and its section, e.g. "Batagelo & Wu, section 3.2"
    std::string scene;    // scene file, resolved against the lesson's folder ("": the lesson's)
    std::string algo;     // the culler ("": the one shown before)
    std::string compare;  // a second culler shown beside it ("": none)
    int frame = 0;
    ViewMode view = ViewMode::Overview;
    bool has_overlays = false;
    OverlayPreset overlays = OverlayPreset::All;
    KnobValues flags;  // family view flags (ui/registry/family_views.h), set for this step
    LessonAnimation animate;
    double seconds = 8.0;  // how long auto-play shows the step (after its animation)
};

struct Lesson {
    std::string file;   // where it was read from
    std::string title;
    std::string scene;  // default scene of its steps, resolved ("": the command line's)
    std::vector<LessonStep> steps;
};

}  // namespace gridcull
