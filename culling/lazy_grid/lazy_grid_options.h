// The lazy occlusion grid's knobs (culling/lazy_grid/lazy_grid_culler.h), after
// Hey, Tobler & Purgathofer: the image's resolution, the cell size, and the three
// extensions of their section 6, each off (0) by default.
#pragma once
#include "culling/api/knobs.h"

namespace gridcull {

// The smallest image side: below it the grid has a handful of cells. A cell of
// one pixel is the finest; 1024 is more than any view needs (a cell larger than
// the image is one cell).
constexpr int kMinLazyResolution = 16;
constexpr int kMaxLazyCellSize = 1024;
// The cell size's flag, which the window's cell-size slider sets too.
constexpr const char* kLazyCellSizeFlag = "lazy-cell-size";

struct LazyGridOptions {
    // Pixels on the long side of the image, the other side from the camera's
    // aspect; 0 follows the oracle's resolution (so that the window's false-cull
    // check compares like with like).
    int resolution = 0;
    // Cell side in pixels (Hey et al. used 32).
    int cell_size = 32;
    // Section 6: rate a cell free without a pixel query while the area drawn into
    // it is below this fraction of it...
    double probability_threshold = 0.0;
    // ...query a border cell whole when the box covers more than this fraction of it...
    double border_whole_fraction = 0.0;
    // ...treat border cells as internal for a box covering more than this
    // fraction of the image.
    double large_box_fraction = 0.0;
};

const KnobTable<LazyGridOptions>& lazyGridKnobs();

}  // namespace gridcull
