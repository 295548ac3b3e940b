#include "ui/background_seek.h"

#include <cassert>
#include <utility>

namespace gridcull {

void BackgroundSeek::start(CullingRun run, RunContext context, const FrameHistory& history,
                           int first, int last) {
    cancel();
    assert(first <= last);
    run_ = std::move(run);
    history_ = history;
    context.history = &history_;
    cancel_.store(false);
    finished_.store(false);
    done_.store(0);
    total_ = last - first + 1;
    target_ = last;
    active_ = true;
    run_.replayed = 0;
    worker_ = std::thread([this, context, first, last] {
        runFrames(run_, context, first, last, &cancel_, &done_);
        finished_.store(true, std::memory_order_release);
    });
}

double BackgroundSeek::progress() const {
    return total_ > 0 ? double(done_.load(std::memory_order_relaxed)) / double(total_) : 0.0;
}

void BackgroundSeek::cancel() {
    if (!active_) return;
    cancel_.store(true);
    if (worker_.joinable()) worker_.join();
    active_ = false;
    target_ = -1;
    run_ = CullingRun{};
}

void BackgroundSeek::take(CullingRun& run, FrameHistory& history) {
    assert(active_ && finished());
    worker_.join();
    run = std::move(run_);
    std::swap(history, history_);
    active_ = false;
    target_ = -1;
    run_ = CullingRun{};
}

}  // namespace gridcull
