// A seek run on a worker thread, so that the window stays responsive (and can
// cancel) while a long one culls its frames. The worker owns copies: the
// cullers (Culler::clone), the frame's results and a copy of the history; it
// shares the const scene and the checkpoints, which are thread-safe.
#pragma once
#include <atomic>
#include <thread>

#include "ui/culling_run.h"

namespace gridcull {

class BackgroundSeek {
public:
    BackgroundSeek() = default;
    BackgroundSeek(const BackgroundSeek&) = delete;
    BackgroundSeek& operator=(const BackgroundSeek&) = delete;
    ~BackgroundSeek() { cancel(); }

    // Runs frames first..last on `run` against `context`, whose history is
    // replaced by the job's own copy of `history`.
    void start(CullingRun run, RunContext context, const FrameHistory& history, int first,
               int last);
    // Started and neither taken nor cancelled yet.
    bool active() const { return active_; }
    bool finished() const { return finished_.load(std::memory_order_acquire); }
    // Frames culled so far over the frames to cull.
    double progress() const;
    int target() const { return target_; }
    // Stops the worker and waits for it; the job's run is dropped.
    void cancel();
    // Once finished(): the run at the target frame and the history it filled.
    void take(CullingRun& run, FrameHistory& history);

private:
    std::thread worker_;
    std::atomic<bool> cancel_{false};
    std::atomic<bool> finished_{false};
    std::atomic<int> done_{0};
    bool active_ = false;
    int total_ = 0;
    int target_ = -1;
    CullingRun run_;
    FrameHistory history_;
};

}  // namespace gridcull
