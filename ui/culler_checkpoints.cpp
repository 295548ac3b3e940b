#include "ui/culler_checkpoints.h"

#include <algorithm>
#include <cstdlib>

#include "ui/heap_bytes.h"

namespace gridcull {

namespace {

std::vector<CullerCheckpoint>::const_iterator firstAtOrAfter(
    const std::vector<CullerCheckpoint>& saved, int frame) {
    return std::lower_bound(saved.begin(), saved.end(), frame,
                            [](const CullerCheckpoint& c, int f) { return c.frame < f; });
}

}  // namespace

CullerCheckpoints::CullerCheckpoints(size_t budget_bytes, int interval)
    : budget_(budget_bytes), interval_(std::max(interval, 1)) {}

void CullerCheckpoints::clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    saved_.clear();
    bytes_ = 0;
    enabled_ = true;
}

void CullerCheckpoints::offer(int frame, const Culler& culler) {
    if (frame % interval_ != 0) return;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!enabled_) return;
        const auto at = firstAtOrAfter(saved_, frame);
        if (at != saved_.end() && at->frame == frame) return;
    }
    // Copied outside the lock: the copy is of the caller's own culler.
    const size_t before = heapBytesInUse();
    std::unique_ptr<Culler> copy = culler.clone();
    const size_t after = heapBytesInUse();
    std::lock_guard<std::mutex> lock(mutex_);
    if (!copy) {
        saved_.clear();
        bytes_ = 0;
        enabled_ = false;
        return;
    }
    const auto at = firstAtOrAfter(saved_, frame);
    if (at != saved_.end() && at->frame == frame) return;  // saved meanwhile by another thread
    const size_t bytes = after > before ? after - before : 0;
    saved_.insert(at, CullerCheckpoint{frame, std::move(copy), bytes});
    bytes_ += bytes;
    if (bytes_ > budget_) thin();
}

int CullerCheckpoints::latestAtOrBefore(int frame) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto after =
        std::upper_bound(saved_.begin(), saved_.end(), frame,
                         [](int f, const CullerCheckpoint& c) { return f < c.frame; });
    return after == saved_.begin() ? -1 : (after - 1)->frame;
}

std::unique_ptr<Culler> CullerCheckpoints::restore(int frame) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto at = firstAtOrAfter(saved_, frame);
    if (at == saved_.end() || at->frame != frame) return nullptr;
    return at->culler->clone();
}

void CullerCheckpoints::setFocus(int frame) {
    std::lock_guard<std::mutex> lock(mutex_);
    focus_ = frame;
}

int CullerCheckpoints::count() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return int(saved_.size());
}

size_t CullerCheckpoints::bytes() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return bytes_;
}

bool CullerCheckpoints::enabled() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return enabled_;
}

void CullerCheckpoints::dropAfter(int frame) {
    std::lock_guard<std::mutex> lock(mutex_);
    while (!saved_.empty() && saved_.back().frame > frame) {
        bytes_ -= saved_.back().bytes;
        saved_.pop_back();
    }
}

int CullerCheckpoints::widestGap() const {
    std::lock_guard<std::mutex> lock(mutex_);
    int widest = interval_;
    for (size_t i = 1; i < saved_.size(); ++i)
        widest = std::max(widest, saved_[i].frame - saved_[i - 1].frame);
    return widest;
}

void CullerCheckpoints::thin() {
    const int current = focus_;
    // Frame 0's checkpoint and the last stay: every seek has a start, and the
    // last marks how far the run has gone.
    while (bytes_ > budget_ && saved_.size() > 2) {
        size_t drop = 0;
        int best_gap = 0, best_distance = 0;
        for (size_t i = 1; i + 1 < saved_.size(); ++i) {
            const int distance = std::abs(saved_[i].frame - current);
            const int gap = saved_[i + 1].frame - saved_[i - 1].frame;
            const bool far = distance > kNearCheckpointFrames;
            const bool best_far = best_distance > kNearCheckpointFrames;
            // Far before near; then the smallest gap left; then the farthest.
            const bool better = drop == 0 || (far && !best_far) ||
                                (far == best_far &&
                                 (gap < best_gap || (gap == best_gap && distance > best_distance)));
            if (better) {
                drop = i;
                best_gap = gap;
                best_distance = distance;
            }
        }
        bytes_ -= saved_[drop].bytes;
        saved_.erase(saved_.begin() + std::ptrdiff_t(drop));
    }
}

}  // namespace gridcull
