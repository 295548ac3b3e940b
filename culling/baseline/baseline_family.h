// The baselines' registry entry: `all` (no culling, the plain z-buffer) and
// `vfc` (view-frustum culling), which every occlusion culler is compared with.
// They have no knobs.
#pragma once
#include "culling/api/family.h"

namespace gridcull {

FamilyEntry baselineFamily();

}  // namespace gridcull
