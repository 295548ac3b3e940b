// BSP trees with occlusion queries in the window (the ui registry's entry for
// the "bsp" family: bsp-oq, bsp-oq-simple, bsp-vfc): its panel
// (ui/bsp_oq/bsp_oq_panel.h), the scene tree's and the picked object's tree's
// nodes over the scene in World space and the frame's query rectangles over
// the view through the culling camera (ui/bsp_oq/bsp_oq_overlay.h), the
// focused object (under the pointer, else the one a click or --bsp-object
// picked) and node (the box under the pointer, else the one a click or
// --bsp-node picked), and the view flags --bsp-show-nodes, --bsp-show-queries,
// --bsp-show-batch, --bsp-object and --bsp-node.
#pragma once
#include "ui/family_view.h"

namespace gridcull {

FamilyViewEntry bspOqFamilyView();

}  // namespace gridcull
