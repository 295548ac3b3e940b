// The 3D parts of the rgvc panel (ui/rgvc/rgvc_panel.h): boxes or a slice and
// which slice, and the picker of 3D occluders with what the picked one's cap
// holds. Each draws into the current ImGui window and returns whether `view`
// changed.
#pragma once
#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/rgvc/rgvc_cap3d.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {

bool drawRgvcVoxelModeControls(const RgvcSnapshot& snapshot, RgvcViewState& view);
// `cap`: the picked occluder's, built (null: not known).
bool drawRgvcOccluderPicker3d(const RgvcSnapshot& snapshot, RgvcViewState& view,
                              const RgvcCap3d* cap);

}  // namespace gridcull
