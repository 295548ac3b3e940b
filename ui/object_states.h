// Classifies every object of a frame by comparing a culler's PVS with the exact
// visible set (ui/object_state.h says what each state means).
#pragma once
#include <vector>

#include "culling/api/culler.h"
#include "culling/scene/scene.h"
#include "ui/object_state.h"

namespace gridcull {

// Fills `states` (indexed like scene.objects) and `false_culled` (ids ascending:
// in exact.pvs but not in `pvs`); culled objects among the oracle's sub-sample
// ones (visible between pixel centres, or undecided) are SubSample. Ids that
// the scene does not have are ignored. Both outputs are resized and reuse their capacity. O(n) with the
// scene's id index.
void classifyObjects(const Scene& scene, const std::vector<int>& pvs, const FrameResult& exact,
                     std::vector<ObjectState>& states, std::vector<int>& false_culled);

}  // namespace gridcull
