#include "ui/culling_run.h"

#include <algorithm>

#include "ui/object_states.h"

namespace gridcull {

Camera RunContext::cameraOfFrame(int frame) const {
    if (frozen_from >= 0 && frame >= frozen_from) return frozen_camera;
    return cameraAt(*scene, scene->timeOfFrame(frame));
}

void runFrame(CullingRun& run, const RunContext& context, int frame, bool full) {
    const Scene& scene = *context.scene;
    if (context.checkpoints) context.checkpoints->offer(frame, *run.culler);
    run.frame = frame;
    ++run.replayed;
    const double t = scene.timeOfFrame(frame);
    run.culling_camera = context.cameraOfFrame(frame);
    timedCull(*run.culler, scene, run.culling_camera, t, run.result);
    if (!full) return;
    run.known_until = std::max(run.known_until, frame);
    if (run.exact) timedCull(*run.exact, scene, run.culling_camera, t, run.exact_result);
    const FrameResult& exact = run.exactResult();
    classifyObjects(scene, run.result.pvs, exact, run.states, run.false_culled);

    FrameHistory& history = *context.history;
    const size_t slot = size_t(frame);
    history.pvs_size[slot] = float(run.result.pvs.size());
    history.exact_visible[slot] = float(exact.pvs.size());
    history.false_culls[slot] = float(run.false_culled.size());
    history.cull_ms[slot] = float(run.result.stats.cull_ms);
    history.stats[slot] = run.result.stats;
    history.draw_ms[slot] = 0.0f;
}

bool runFrames(CullingRun& run, const RunContext& context, int first, int last,
               const std::atomic<bool>* cancel, std::atomic<int>* done) {
    for (int f = first; f <= last; ++f) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return false;
        runFrame(run, context, f, f == last || f > run.known_until);
        if (done) done->fetch_add(1, std::memory_order_relaxed);
    }
    return true;
}

}  // namespace gridcull
