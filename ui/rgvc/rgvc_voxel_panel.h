// The rgvc panel's account of single things (ui/rgvc/rgvc_panel.h): the voxel
// under the mouse (its matrices, the layer it entered H at and the occluder
// that hid it, a button that picks that occluder), the object under the mouse
// or picked (its I voxels and what the traversal found in each, with buttons
// that pick the occluders that hid them), and the bytes each matrix holds.
// Each draws into the current ImGui window; those with buttons return whether
// `view` changed.
#pragma once
#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/object_state.h"
#include "ui/rgvc/rgvc_object_voxels.h"
#include "ui/rgvc/rgvc_view.h"
#include "ui/rgvc/rgvc_voxel_info.h"

namespace gridcull {

// `info` null: no voxel; `hovered`: under the mouse now (else the one clicked last).
bool drawRgvcVoxelInfo(const RgvcSnapshot& snapshot, RgvcViewState& view, const RgvcVoxelInfo* info,
                       bool hovered);
// `object` null or without an object: nothing shown.
bool drawRgvcObjectVoxels(const RgvcSnapshot& snapshot, RgvcViewState& view,
                          const RgvcObjectVoxels* object, ObjectState state);
// KiB of every matrix (3D: with the direction map).
void drawRgvcMemory(const RgvcMatrixMemory& memory, int dimensions);

// The occluder picker button's label for occluder `index`, e.g. "occluder 12".
// Returns whether it was clicked (then view.occluder is `index`).
bool rgvcOccluderButton(RgvcViewState& view, int32_t index);

// The most voxels of an object the panel lists one by one.
constexpr int kRgvcListedObjectVoxels = 8;

}  // namespace gridcull
