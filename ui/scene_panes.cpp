#include "ui/scene_panes.h"

#include <algorithm>

namespace gridcull {

ScenePanes splitSceneView(const WindowRect& view, ViewMode mode, bool comparing) {
    ScenePanes panes;
    if (!comparing && mode != ViewMode::Cameras) {
        panes.pane[0] = {view, mode, false};
        return panes;
    }
    panes.count = 2;
    const int left = std::max((view.width - kPaneGap) / 2, 1);
    const int right = std::max(view.width - left - kPaneGap, 1);
    panes.pane[0].rect = {view.x, view.y, left, view.height};
    panes.pane[1].rect = {view.x + view.width - right, view.y, right, view.height};
    if (comparing) {
        const ViewMode both = mode == ViewMode::Cameras ? ViewMode::CullingCamera : mode;
        panes.pane[0].mode = panes.pane[1].mode = both;
        panes.pane[1].compared = true;
    } else {
        panes.pane[0].mode = ViewMode::Overview;
        panes.pane[1].mode = ViewMode::CullingCamera;
    }
    return panes;
}

}  // namespace gridcull
