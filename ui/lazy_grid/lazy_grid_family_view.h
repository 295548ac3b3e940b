// The lazy occlusion grid in the window (the ui registry's entry for the
// "lazy-grid" family): its panel, its cells over the view through the culling
// camera, the focused object (under the pointer, else the one a click or
// --lazy-object picked) with the cells its deciding test touched, the image
// cell under the pointer outlined (ui/lazy_grid/lazy_grid_hovered_cell.h), the
// overlay presets (ui/lazy_grid/lazy_grid_view.h) and the view flag
// --lazy-object.
#pragma once
#include "ui/family_view.h"

namespace gridcull {

FamilyViewEntry lazyGridFamilyView();

}  // namespace gridcull
