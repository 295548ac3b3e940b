// The lazy occlusion grid panel (lazy-grid, lazy-grid-z, busy-grid in a 3D
// scene): the variant and update, image and cell size with a cell-size slider,
// the frame's counters, the cells per state at frame end with their colour key,
// the focused object's deciding test, and a toggle per overlay layer. Shown only
// when the snapshot carries a lazy grid snapshot; reads it, never changes it.
#pragma once
#include <optional>

#include "ui/frame_snapshot.h"
#include "ui/lazy_grid/lazy_grid_view.h"

namespace gridcull {

// The cell-size slider's range: powers of two from 2^3 to 2^6 pixels.
constexpr int kLazyCellSizeMinLog2 = 3;
constexpr int kLazyCellSizeMaxLog2 = 6;

struct LazyGridAction {
    std::optional<LazyGridViewState> view;  // the new view state, when the user changed it
    // A new CullerOptions::lazy_cell_size: the app re-creates the culler with it
    // and re-runs up to the current frame. Set when the slider is let go, not
    // while it is dragged, as each change re-runs every frame so far.
    std::optional<int> cell_size;
};

// The slider's value while it is being dragged (the snapshot's cell size is
// the value otherwise).
struct LazyGridPanelState {
    int cell_size_log2 = 0;
    bool dragging = false;
};

// Draws into the current ImGui window; nothing when snapshot.lazy_grid is null.
LazyGridAction drawLazyGridPanel(const FrameSnapshot& snapshot, LazyGridPanelState& state);

}  // namespace gridcull
