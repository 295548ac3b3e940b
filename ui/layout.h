// Where the scene view and the panel column go in the window. Fixed, so that a
// shot of a given size always lays out the same, and the window matches it.
// Rectangles are in window pixels with the origin at the top left.
#pragma once

namespace gridcull {

// Window pixels (x, y, size); not culling's PixelRect, which is an inclusive
// rectangle of an image's pixels (culling/api/pixel_rect.h).
struct WindowRect {
    int x = 0, y = 0, width = 0, height = 0;
    bool contains(double px, double py) const {
        return px >= x && py >= y && px < x + width && py < y + height;
    }
};

struct WindowLayout {
    WindowRect scene_view;  // the 3D / 2D view
    WindowRect panels;      // the column of panels; width 0 when there are none
    WindowRect timeline;    // under the view, as wide; height 0 without panels
};

// Panel column width in pixels at UI scale 1, at window widths >= 2x this;
// narrower windows give the column at most 45% of the width.
constexpr int kPanelColumnWidth = 380;
// Timeline height in pixels at UI scale 1, at most 30% of the window's height.
constexpr int kTimelineHeight = 116;

// with_panels == false: the scene view fills the window (shot --view scene).
// ui_scale: the panels' scale (--ui-scale), which widens the column with it.
WindowLayout computeLayout(int width, int height, bool with_panels, double ui_scale = 1.0);

}  // namespace gridcull
