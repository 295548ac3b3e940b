// Draws the lazy occlusion grid (culling/lazy_grid/lazy_grid_snapshot.h) over the view
// through the culling camera: every cell filled by its state at the end of the
// frame, the grid lines and the image's border, and for the focused object (the
// one under the mouse, or `shot --lazy-object`) the cells its deciding test
// touched (internal cells filled and outlined solid, border cells dashed, those
// found free in the "free" colour), a cross on each cell whose pixels it read,
// and its screen rectangle. Colours and toggles: ui/lazy_grid/lazy_grid_view.h.
//
// Geometry is in view pixels (origin top left) through an ImageFrame
// (app/camera_image_frame.h), so the grid sits on the objects whatever the
// view's aspect. Cost per draw: O(cells + touches of the focused test); vectors
// keep their capacity, so a steady state allocates nothing. Needs a current GL
// 3.3 core context.
#pragma once
#include <string>
#include <vector>

#include "app/camera_image_frame.h"
#include "app/line_renderer.h"
#include "app/overlay_geometry.h"
#include "culling/lazy_grid/lazy_grid_snapshot.h"
#include "ui/lazy_grid/lazy_grid_view.h"

namespace gridcull {

// The overlay's triangles (GL_TRIANGLES) and lines (GL_LINES), without GL, so
// tests can check the mapping; positions are view pixels at z = 0.
struct LazyGridOverlayGeometry {
    std::vector<ColorVertex> fill;         // cell states, then touched internal cells
    std::vector<ColorVertex> lines;        // 1 pixel: grid lines, image border
    std::vector<ColorVertex> thick_lines;  // touched cells' outlines, crosses, the rectangle
    std::vector<int32_t> slot;             // scratch: per cell, its entry in `touched` or -1
    struct Touched {
        int32_t cell = 0;
        CellRole role = CellRole::Internal;
        bool free = false, queried = false, probability = false;
    };
    std::vector<Touched> touched;  // scratch: the focused test's cells, first touch order
};

// The view rectangle of cell (cx, cy) of the snapshot's image in `frame`.
ViewRect lazyCellInView(const ImageFrame& frame, const LazyGridSnapshot& snapshot, int cx, int cy);

// Rebuilds `out` (keeping capacities) for `snapshot` as `view` asks, with the
// deciding test of object index `focus_object` (-1: none). Nothing when the
// snapshot is not valid. `frame` must be made for the snapshot's image size.
void buildLazyGridOverlay(const LazyGridSnapshot& snapshot, const LazyGridViewState& view,
                          int focus_object, const ImageFrame& frame, LazyGridOverlayGeometry& out);

class LazyGridOverlay {
public:
    bool init(std::string& error) { return line_renderer_.init(error); }
    // Draws into the current viewport, which is view_width x view_height pixels.
    void draw(const LazyGridSnapshot& snapshot, const LazyGridViewState& view, int focus_object,
              const ImageFrame& frame, int view_width, int view_height);

private:
    LineRenderer line_renderer_;
    LazyGridOverlayGeometry geometry_;
};

}  // namespace gridcull
