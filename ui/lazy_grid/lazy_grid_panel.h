// The lazy occlusion grid panel (lazy-grid, lazy-grid-z, busy-grid in a 3D
// scene): the variant and update, image and cell size with a cell-size slider,
// the frame's counters, the cells per state at frame end with their colour key,
// the focused object's deciding test, and a toggle per overlay layer. Reads the
// snapshot, never changes it; changes only the view and panel state it is given.
#pragma once
#include "culling/lazy_grid/lazy_grid_snapshot.h"
#include "culling/scene/scene.h"
#include "ui/family_view.h"
#include "ui/lazy_grid/lazy_grid_view.h"

namespace gridcull {

// The cell-size slider's range: powers of two from 2^3 to 2^6 pixels.
constexpr int kLazyCellSizeMinLog2 = 3;
constexpr int kLazyCellSizeMaxLog2 = 6;

// The slider's value while it is being dragged (the snapshot's cell size is
// the value otherwise).
struct LazyGridPanelState {
    int cell_size_log2 = 0;
    bool dragging = false;
};

// What the panel shows besides the snapshot.
struct LazyGridPanelInput {
    const Scene* scene = nullptr;
    const char* algo = "";
    ViewMode view_mode = ViewMode::Overview;
    // The object (index into scene->objects, -1: none) whose deciding test the
    // panel details: the one under the mouse, else the picked one (`pinned`).
    int focus_object = -1;
    bool focus_pinned = false;
};

// Draws into the current ImGui window. A new cell size, set when the slider is
// let go (each change re-runs every frame so far), goes into `action` as the
// knob lazy-cell-size.
void drawLazyGridPanel(const LazyGridSnapshot& lazy, const LazyGridPanelInput& input,
                       LazyGridViewState& view, LazyGridPanelState& state, FamilyAction& action);

}  // namespace gridcull
