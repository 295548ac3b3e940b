// Regular-grid culling in the window (the ui registry's entry for the "rgvc"
// family): the rgvc panel, the matrices and traversal over the 2D view, the voxel
// under the pointer, a click that picks the extended occluder there, and the view
// flags --rgvc-layer and --rgvc-occluder.
#pragma once
#include "ui/family_view.h"

namespace gridcull {

FamilyViewEntry rgvcFamilyView();

}  // namespace gridcull
