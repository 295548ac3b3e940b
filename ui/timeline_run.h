// The whole run's statistics computed ahead for the timeline, on a worker
// thread at low priority: a copy of the selected culler as it was before frame
// 0 and a copy of the oracle cull every frame of the scene in order, so the
// timeline shows PVS/exact, false culls and counters of frames the user has not
// reached yet. Shares with the session the const scene and the checkpoints
// (thread-safe), which it fills as it goes; what is done so far is copied out
// under a lock.
#pragma once
#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

#include "ui/culling_run.h"

namespace gridcull {

class TimelineRun {
public:
    TimelineRun() = default;
    TimelineRun(const TimelineRun&) = delete;
    TimelineRun& operator=(const TimelineRun&) = delete;
    ~TimelineRun() { stop(); }

    // Starts over: `culler` holds the state before frame 0, `exact` is the
    // oracle (null when the culler is the oracle); a frozen culling camera as
    // in RunContext. Its states are offered to `checkpoints` (may be null).
    void start(const Scene& scene, std::unique_ptr<Culler> culler, std::unique_ptr<Culler> exact,
               int frozen_from, const Camera& frozen_camera,
               CullerCheckpoints* checkpoints = nullptr);
    // Stops the worker and waits for it; nothing is computed any more.
    void stop();
    // Copies the frames done so far into `history` (sized to the scene's
    // frames) and returns how many: frames 0 to that count - 1.
    int copyTo(FrameHistory& history) const;

private:
    std::thread worker_;
    std::atomic<bool> stop_{false};
    mutable std::mutex mutex_;
    FrameHistory published_;  // under mutex_
    int done_ = 0;            // under mutex_
};

}  // namespace gridcull
