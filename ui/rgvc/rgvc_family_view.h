// Regular-grid culling in the window (the ui registry's entry for the "rgvc"
// family), 2D and 3D: the rgvc panel, the matrices and traversal over the view
// (2D: ui/rgvc/rgvc_overlay.h; 3D: ui/rgvc/rgvc_overlay3d.h), the voxel under
// the pointer (3D: picked along the pointer's ray, ui/rgvc/rgvc_pick3d.h),
// outlined (ui/rgvc/rgvc_hovered_voxel.h), the overlay presets, which follow
// the scene's dimension (ui/rgvc/rgvc_view.h), a click that picks the occluder
// there and keeps that voxel and the object under the pointer in the panel,
// and the view flags --rgvc-layer,
// --rgvc-occluder, --rgvc-slice, --rgvc-slice-axis, --rgvc-object and --rgvc-tbv.
#pragma once
#include "ui/family_view.h"

namespace gridcull {

FamilyViewEntry rgvcFamilyView();

}  // namespace gridcull
