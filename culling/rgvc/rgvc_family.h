// Regular-grid culling's registry entry: `rgvc`, 2D scenes, with its knobs
// (culling/rgvc/rgvc_options.h).
#pragma once
#include "culling/api/family.h"

namespace gridcull {

FamilyEntry rgvcFamily();

}  // namespace gridcull
