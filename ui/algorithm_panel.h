// Algorithm and cameras: which culler colours the objects (and which one, if
// any, is shown beside it to compare), freezing the culling camera, and how the
// view looks at the scene.
#pragma once
#include <optional>

#include "ui/frame_snapshot.h"

namespace gridcull {

struct AlgorithmAction {
    std::optional<int> select_algo;      // index into snapshot.algo_names
    std::optional<int> compare_algo;     // index into snapshot.algo_names; -1: compare with none
    std::optional<bool> freeze_culling;  // freeze / release the culling camera
    std::optional<ViewMode> view_mode;
    // Flying: start or stop recording a camera path, save it into the scene
    // file (the culling camera then replays it), or drop it.
    bool flight_record = false;
    bool flight_save = false;
    bool flight_discard = false;
};

// Draws into the current ImGui window.
AlgorithmAction drawAlgorithmPanel(const FrameSnapshot& snapshot);

}  // namespace gridcull
