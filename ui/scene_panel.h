// The scene: what is loaded, and opening another scene file by typing its path
// or picking it from a list (the files opened recently, the scenes beside the
// current one and in ./scenes).
// A file that fails to load leaves the current scene in place; its messages
// (scene-format.md "Errors") are shown here.
#pragma once
#include <string>

#include "ui/frame_snapshot.h"

namespace gridcull {

struct ScenePanelState {
    char path[1024] = "";
};

struct SceneAction {
    bool open = false;
    std::string path;  // set with open
};

// Draws into the current ImGui window.
SceneAction drawScenePanel(const FrameSnapshot& snapshot, ScenePanelState& state);

}  // namespace gridcull
