// Classifies every object of a frame by comparing a culler's PVS with the exact
// visible set (ui/object_state.h says what each state means).
#pragma once
#include <vector>

#include "culling/scene/scene.h"
#include "ui/object_state.h"

namespace gridcull {

// Fills `states` (indexed like scene.objects) and `false_culled` (ids ascending:
// in `exact` but not in `pvs`). Ids in either list that the scene does not have
// are ignored. Both outputs are resized and reuse their capacity. O(n) with the
// scene's id index.
void classifyObjects(const Scene& scene, const std::vector<int>& pvs, const std::vector<int>& exact,
                     std::vector<ObjectState>& states, std::vector<int>& false_culled);

}  // namespace gridcull
