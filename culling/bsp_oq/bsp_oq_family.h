// The registry entry of BSP culling with occlusion queries (Kovalčík &
// Sochor): `bsp-oq` (Full), `bsp-oq-simple` (Simple OC) and `bsp-vfc` (VFC
// only), 3D scenes, with their knobs (culling/bsp_oq/bsp_oq_options.h). They
// draw into an image target: the software rasterizer, or OpenGL as NAME-gl.
#pragma once
#include "culling/api/family.h"

namespace gridcull {

FamilyEntry bspOqFamily();

}  // namespace gridcull
