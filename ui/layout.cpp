#include "ui/layout.h"

#include <algorithm>

namespace gridcull {

WindowLayout computeLayout(int width, int height, bool with_panels, double ui_scale) {
    width = std::max(width, 1);
    height = std::max(height, 1);
    WindowLayout layout;
    if (!with_panels) {
        layout.scene_view = {0, 0, width, height};
        return layout;
    }
    const int column = std::min(int(kPanelColumnWidth * ui_scale), width * 45 / 100);
    const int strip = std::min(int(kTimelineHeight * ui_scale), height * 30 / 100);
    layout.scene_view = {0, 0, std::max(width - column, 1), std::max(height - strip, 1)};
    layout.timeline = {0, height - strip, layout.scene_view.width, strip};
    layout.panels = {width - column, 0, column, height};
    return layout;
}

}  // namespace gridcull
