// Checkpoints of the debugger's selected culler: copies of its state
// (Culler::clone) taken before every `interval`-th frame, so that a seek
// restores the latest checkpoint at or before its target and replays at most
// the frames from there instead of every frame from 0.
//
// The copies are kept within a memory budget. When they outgrow it,
// checkpoints far from the user's frame (the focus) go first, each time the one
// whose removal leaves the smallest gap, so the spacing stays `interval` near
// where the user is (a step back costs at most that) and widens evenly with
// distance (a long jump replays up to the widest gap). Memory is measured as the
// heap's growth while a copy is made (glibc's mallinfo2; a sanitized build,
// whose allocator it does not see, reports 0 and so never thins).
//
// Thread-safe: the session, its background seek and the run computed ahead for
// the timeline offer and restore checkpoints concurrently; a restore hands out a
// copy, never a reference into the store.
#pragma once
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "culling/api/culler.h"

namespace gridcull {

constexpr int kDefaultCheckpointInterval = 4;
constexpr size_t kDefaultCheckpointBudget = size_t(768) << 20;  // bytes
// Checkpoints within this many frames of the focus are kept at `interval`
// spacing while farther ones can go: a user stepping back and forth around a
// frame never waits for more than an interval of culls.
constexpr int kNearCheckpointFrames = 64;

struct CullerCheckpoint {
    int frame = 0;                   // the state before this frame was culled
    std::unique_ptr<Culler> culler;  // never culled itself: restore() hands out copies
    size_t bytes = 0;                // heap taken by the copy
};

class CullerCheckpoints {
public:
    explicit CullerCheckpoints(size_t budget_bytes = kDefaultCheckpointBudget,
                               int interval = kDefaultCheckpointInterval);

    // Forgets every checkpoint (a new culler, scene or knobs).
    void clear();
    // Called with the culler as it is before `frame` is culled: saves a copy when
    // `frame` is on the interval and has none yet. A culler that cannot be copied
    // (its clone() is null) turns checkpoints off until clear().
    void offer(int frame, const Culler& culler);
    // The frame of the latest checkpoint at or before `frame`, or -1.
    int latestAtOrBefore(int frame) const;
    // A copy of the culler saved before `frame`, or null when none is saved there.
    std::unique_ptr<Culler> restore(int frame) const;
    // Drops the checkpoints of frames after `frame` (the camera changed there).
    void dropAfter(int frame);
    // The frame the user is at: over budget, checkpoints far from it go first.
    void setFocus(int frame);

    int count() const;
    int interval() const { return interval_; }
    // The most frames between two checkpoints (or after the last one saved,
    // `interval`): the most a seek replays.
    int widestGap() const;
    size_t bytes() const;
    size_t budget() const { return budget_; }
    // False once a culler refused to be copied (say, one drawing with OpenGL).
    bool enabled() const;

private:
    // Drops checkpoints, far from the focus first, until within budget.
    void thin();

    const size_t budget_;
    const int interval_;
    mutable std::mutex mutex_;  // guards what follows
    int focus_ = 0;
    size_t bytes_ = 0;
    bool enabled_ = true;
    std::vector<CullerCheckpoint> saved_;  // ascending frame
};

}  // namespace gridcull
