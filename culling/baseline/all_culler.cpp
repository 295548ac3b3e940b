#include "culling/baseline/all_culler.h"

#include <algorithm>

namespace gridcull {

void AllCuller::reset(const Scene& /*scene*/) {}

void AllCuller::cull(const Scene& scene, const Camera& /*camera*/, double /*t*/, FrameResult& out) {
    out.stats = CullStats{};
    out.pvs.clear();
    for (const SceneObject& object : scene.objects) out.pvs.push_back(object.id);
    // Loaded scenes list objects in id order already; hand-built ones may not.
    if (!std::is_sorted(out.pvs.begin(), out.pvs.end())) std::sort(out.pvs.begin(), out.pvs.end());
}

}  // namespace gridcull
