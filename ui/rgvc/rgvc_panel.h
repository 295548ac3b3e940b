// The rgvc panel (regular-grid culling in a 2D scene): a toggle and colour key
// per overlay layer, the chess-layer stepper, the occluder picker, the bytes of
// each matrix and the voxel under the mouse. Reads the snapshot, never changes
// it; changes only the view state it is given.
#pragma once
#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {

// Draws into the current ImGui window; returns whether `view` changed. `voxel`
// is the voxel under the mouse, null when there is none.
bool drawRgvcPanel(const RgvcSnapshot& snapshot, RgvcViewState& view, const RgvcVoxelInfo* voxel);

}  // namespace gridcull
