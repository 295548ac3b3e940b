// The registry entry of octree + hierarchical z-buffer culling (Sudarsky &
// Gotsman): `hzb-tbv` (temporal bounding volumes, explicit update: TBVe),
// `hzb-tbvi` (implicit update: TBVi) and `hzb` (every dynamic object updated
// every frame, the paper's HZB), 3D scenes, with their knobs
// (culling/hzb_tbv/hzb_tbv_options.h). They draw into their own software
// z-buffer, not into an app-given image.
#pragma once
#include "culling/api/family.h"

namespace gridcull {

FamilyEntry hzbTbvFamily();

}  // namespace gridcull
