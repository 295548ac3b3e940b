// Octree + hierarchical z-buffer culling with TBVs in the window (the ui
// registry's entry for the "hzb" family: hzb-tbv, hzb-tbvi, hzb): its panel
// (ui/hzb_tbv/hzb_tbv_panel.h), the TBVs and octree nodes over the scene in
// World space (ui/hzb_tbv/hzb_tbv_overlay.h), the Z-pyramid images in the
// view's corner (ui/hzb_tbv/hzb_pyramid_images.h), the focused object (under
// the pointer, else the one a click or --hzb-object picked), and the view flags
// --hzb-show-tbvs, --hzb-show-nodes, --hzb-show-pyramid, --hzb-pyramid-level and
// --hzb-object.
#pragma once
#include "ui/family_view.h"

namespace gridcull {

FamilyViewEntry hzbTbvFamilyView();

}  // namespace gridcull
