// The rgvc panel (regular-grid culling, 2D and 3D scenes): a toggle and colour
// key per overlay layer, the chess-layer stepper, in 3D the boxes-or-slice
// choice (ui/rgvc/rgvc_panel3d.h), the occluder picker, the bytes of each
// matrix, the voxel under the mouse and the object under it
// (ui/rgvc/rgvc_voxel_panel.h). Reads the snapshot, never changes it; changes
// only the view state it is given.
#pragma once
#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/object_state.h"
#include "ui/rgvc/rgvc_cap3d.h"
#include "ui/rgvc/rgvc_object_voxels.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {

// What the panel shows beside the snapshot; null: nothing to show.
struct RgvcPanelInput {
    const RgvcVoxelInfo* voxel = nullptr;      // the voxel under the mouse, or the one clicked last
    bool voxel_hovered = false;                // ... under the mouse now
    const RgvcObjectVoxels* object = nullptr;  // the object under the mouse, or the one picked
    ObjectState object_state = ObjectState::Culled;
    const RgvcCap3d* cap = nullptr;  // 3D: the picked occluder's cap
};

// Draws into the current ImGui window; returns whether `view` changed.
bool drawRgvcPanel(const RgvcSnapshot& snapshot, RgvcViewState& view, const RgvcPanelInput& input);
// The voxel under the mouse only (null: none).
inline bool drawRgvcPanel(const RgvcSnapshot& snapshot, RgvcViewState& view,
                          const RgvcVoxelInfo* voxel) {
    RgvcPanelInput input;
    input.voxel = voxel;
    input.voxel_hovered = voxel != nullptr;
    return drawRgvcPanel(snapshot, view, input);
}

}  // namespace gridcull
