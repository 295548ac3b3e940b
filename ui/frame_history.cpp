#include "ui/frame_snapshot.h"

namespace gridcull {

void FrameHistory::resize(int frames) {
    const size_t n = frames > 0 ? size_t(frames) : 0;
    for (std::vector<float>* series : {&pvs_size, &exact_visible, &false_culls, &cull_ms, &draw_ms})
        series->assign(n, 0.0f);
    stats.assign(n, CullStats{});
}

void FrameHistory::copyFrame(const FrameHistory& from, int frame) {
    const size_t i = size_t(frame);
    pvs_size[i] = from.pvs_size[i];
    exact_visible[i] = from.exact_visible[i];
    false_culls[i] = from.false_culls[i];
    cull_ms[i] = from.cull_ms[i];
    draw_ms[i] = from.draw_ms[i];
    stats[i] = from.stats[i];
}

}  // namespace gridcull
