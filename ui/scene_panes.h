// The scene view split in two, side by side: two cullers on the same frame (A
// left, B right), or, in 3D, the orbit view beside the culling camera's. Each
// pane is drawn as the whole view would be, from its own camera.
#pragma once
#include "ui/layout.h"
#include "ui/view_mode.h"

namespace gridcull {

struct ScenePane {
    WindowRect rect;
    ViewMode mode = ViewMode::Overview;  // never ViewMode::Cameras
    bool compared = false;               // shows the culler compared with (B)
};

struct ScenePanes {
    ScenePane pane[2];
    int count = 1;
};

// Window pixels between two panes, left as the window's clear colour.
constexpr int kPaneGap = 4;

// `view`: the whole scene view; `mode`: the view mode chosen; `comparing`: a
// second culler is shown. Comparing, both panes look the same way (through the
// culling camera when both cameras were asked for); else both cameras split
// the view; else one pane is the whole view.
ScenePanes splitSceneView(const WindowRect& view, ViewMode mode, bool comparing);

}  // namespace gridcull
