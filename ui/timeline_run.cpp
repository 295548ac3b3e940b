#include "ui/timeline_run.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <utility>

namespace gridcull {

namespace {

// The window's own thread comes first: the timeline is filled with what CPU is left.
constexpr int kTimelineNice = 10;

}  // namespace

void TimelineRun::start(const Scene& scene, std::unique_ptr<Culler> culler,
                        std::unique_ptr<Culler> exact, int frozen_from, const Camera& frozen_camera,
                        CullerCheckpoints* checkpoints) {
    stop();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        published_.resize(scene.frames);
        done_ = 0;
    }
    stop_.store(false);
    auto run = std::make_shared<CullingRun>();
    run->culler = std::move(culler);
    run->exact = std::move(exact);
    RunContext context;
    context.scene = &scene;
    context.frozen_from = frozen_from;
    context.frozen_camera = frozen_camera;
    context.checkpoints = checkpoints;
    worker_ = std::thread([this, run, context]() mutable {
        setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), kTimelineNice);
        FrameHistory history;
        history.resize(context.scene->frames);
        context.history = &history;
        for (int frame = 0; frame < context.scene->frames; ++frame) {
            if (stop_.load(std::memory_order_relaxed)) return;
            runFrame(*run, context, frame, true);
            std::lock_guard<std::mutex> lock(mutex_);
            published_.copyFrame(history, frame);
            done_ = frame + 1;
        }
    });
}

void TimelineRun::stop() {
    stop_.store(true);
    if (worker_.joinable()) worker_.join();
}

int TimelineRun::copyTo(FrameHistory& history) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (history.pvs_size.size() != published_.pvs_size.size())
        history.resize(int(published_.pvs_size.size()));
    for (int frame = 0; frame < done_; ++frame) history.copyFrame(published_, frame);
    return done_;
}

}  // namespace gridcull
