#include "culling/api/culler.h"

#include <chrono>

namespace gridcull {

void timedCull(Culler& culler, const Scene& scene, const Camera& camera, double t,
               FrameResult& out) {
    out.sub_sample_visible.clear();  // only a culler that has such objects fills them
    out.sub_sample_undecided.clear();
    const auto start = std::chrono::steady_clock::now();
    culler.cull(scene, camera, t, out);
    const auto stop = std::chrono::steady_clock::now();
    out.stats.cull_ms = std::chrono::duration<double, std::milli>(stop - start).count();
}

}  // namespace gridcull
