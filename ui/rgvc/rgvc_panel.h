// The rgvc panel (regular-grid culling in a 2D scene): a toggle and colour key
// per overlay layer, the chess-layer stepper, the occluder picker, the bytes of
// each matrix and the voxel under the mouse. Shown only when the snapshot
// carries an rgvc snapshot; reads it, never changes it.
#pragma once
#include <optional>

#include "ui/frame_snapshot.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {

struct RgvcAction {
    std::optional<RgvcViewState> view;  // the new view state, when the user changed it
};

// Draws into the current ImGui window; nothing when snapshot.rgvc is null.
RgvcAction drawRgvcPanel(const FrameSnapshot& snapshot);

}  // namespace gridcull
