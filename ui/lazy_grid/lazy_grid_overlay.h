// Draws the lazy occlusion grid (culling/lazy_grid/lazy_grid_snapshot.h) over the
// view through the culling camera: every cell filled by its state at the end of
// the frame, the grid lines and the image's border, and for the focused object
// (the one under the mouse, or `shot --lazy-object`) the cells its deciding test
// touched (internal cells filled and outlined solid, border cells dashed, those
// found free in the "free" colour), a cross on each cell whose pixels it read,
// and its screen rectangle. Colours and toggles: ui/lazy_grid/lazy_grid_view.h.
//
// Geometry is in View space (view pixels, origin top left) through an
// ImageFrame (ui/image_frame.h), so the grid sits on the objects whatever the
// view's aspect. Cost per draw: O(cells + touches of the focused test); the
// scratch keeps its capacity, so a steady state allocates nothing.
#pragma once
#include <cstdint>
#include <vector>

#include "culling/lazy_grid/lazy_grid_snapshot.h"
#include "ui/debug_draw.h"
#include "ui/image_frame.h"
#include "ui/lazy_grid/lazy_grid_view.h"

namespace gridcull {

// Per-cell bookkeeping of the focused test, kept between draws.
struct LazyGridOverlayScratch {
    std::vector<int32_t> slot;  // per cell, its entry in `touched` or -1
    struct Touched {
        int32_t cell = 0;
        CellRole role = CellRole::Internal;
        bool free = false, queried = false, probability = false;
    };
    std::vector<Touched> touched;  // the focused test's cells, first touch order
};

// One cell of class `c` over view rectangle `r`: its fill at `fill_alpha`,
// hatching, outline. The overlay draws every cell with it and the panel's key
// draws its swatches with it (ui/legend_swatch.h), so the two cannot differ.
void drawLazyCell(LazyCellClass c, float fill_alpha, const ViewRect& r, DebugDraw& draw);
// The fill the key shows for class `c` (zfar < zmax: the nearest, densest).
float lazyCellLegendAlpha(LazyCellClass c);

// The view rectangle of cell (cx, cy) of the snapshot's image in `frame`.
ViewRect lazyCellInView(const ImageFrame& frame, const LazyGridSnapshot& snapshot, int cx, int cy);

// Emits the overlay for `snapshot` as `view` asks, with the deciding test of
// object index `focus_object` (-1: none). Nothing when the snapshot is not
// valid. `frame` must be made for the snapshot's image size.
void drawLazyGridOverlay(const LazyGridSnapshot& snapshot, const LazyGridViewState& view,
                         int focus_object, const ImageFrame& frame, DebugDraw& draw,
                         LazyGridOverlayScratch& scratch);

}  // namespace gridcull
