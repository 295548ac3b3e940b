#include "ui/frame_snapshot.h"

namespace gridcull {

void FrameHistory::resize(int frames) {
    const size_t n = frames > 0 ? size_t(frames) : 0;
    for (std::vector<float>* series : {&pvs_size, &exact_visible, &false_culls, &cull_ms, &draw_ms})
        series->assign(n, 0.0f);
}

}  // namespace gridcull
