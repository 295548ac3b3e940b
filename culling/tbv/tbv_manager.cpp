// The TBV manager (Sudarsky & Gotsman, "Dynamic scene occlusion culling",
// sections 3.3 to 3.7: the data D, Q and V, del_TBV, upd_vis and the four steps
// of a frame). tbv_manager.h says where it departs from the paper and why.
#include "culling/tbv/tbv_manager.h"

#include <algorithm>
#include <cmath>

namespace gridcull {

const char* tbvUpdateModeName(TbvUpdateMode mode) {
    return mode == TbvUpdateMode::Explicit ? "TBVe" : "TBVi";
}

const char* tbvObjectStateName(TbvObjectState state) {
    switch (state) {
        case TbvObjectState::Static:
            return "static";
        case TbvObjectState::Visible:
            return "visible";
        case TbvObjectState::Hidden:
            return "hidden";
        case TbvObjectState::Expired:
            return "expired";
        case TbvObjectState::Revealed:
            return "revealed";
        case TbvObjectState::Violated:
            return "violated";
    }
    return "?";
}

const char* tbvDropReasonName(TbvDropReason reason) {
    switch (reason) {
        case TbvDropReason::Expired:
            return "expired";
        case TbvDropReason::Revealed:
            return "revealed";
        case TbvDropReason::Violated:
            return "violated";
        case TbvDropReason::Invalidated:
            return "invalidated";
    }
    return "?";
}

void TbvManager::reset(size_t n, const TbvManagerOptions& options) {
    assert(n <= size_t(std::numeric_limits<int32_t>::max()) && "too many objects for TBV ids");
    assert(options.initial_validity > 0.0 && std::isfinite(options.initial_validity));
    assert(options.validity_floor >= 0.0);
    assert(options.invalidate_fraction >= 0.0 && options.invalidate_fraction <= 1.0);
    options_ = options;
    queue_.reset(n);
    validity_.reset(n, options.validity_mode, options.initial_validity, options.validity_floor);
    state_.assign(n, TbvObjectState::Static);
    tbv_.assign(n, TbvRecord{});
    live_.clear();
    live_.reserve(n);
    live_slot_.assign(n, -1);
    hidden_.clear();
    hidden_.reserve(n);
    hidden_slot_.assign(n, -1);
    pending_violations_.clear();
    pending_violations_.reserve(n);
    violation_pending_.assign(n, 0);
    violation_serial_.assign(n, 0);
    made_.assign(n, 0);
    observed_frame_.assign(n, 0);  // "earlier than the first frame" (frame 1)
    fetched_frame_.assign(n, 0);
    touched_frame_.assign(n, 0);
    drop_frame_.assign(n, 0);
    drop_reason_.assign(n, TbvDropReason::Expired);
    written_time_.assign(n, -std::numeric_limits<double>::infinity());
    dynamic_count_ = 0;
    frame_ = 0;
    now_ = -std::numeric_limits<double>::infinity();
    in_frame_ = false;
    random_state_ = options.seed;
    counters_ = TbvFrameCounters{};
    totals_ = TbvFrameCounters{};
}

void TbvManager::addDynamic(int object) {
    const size_t i = checked(object);
    assert(frame_ == 0 && "addDynamic after the first frame");
    if (state_[i] != TbvObjectState::Static) return;
    state_[i] = TbvObjectState::Visible;
    ++dynamic_count_;
    addLive(object);
}

void TbvManager::startFrame(double t) {
    assert(!in_frame_ && "beginFrame twice without endFrame");
    assert(!(t < now_) && "frames go in order");
    ++frame_;
    now_ = t;
    in_frame_ = true;
    counters_ = TbvFrameCounters{};
    counters_.frame = frame_;
    counters_.naive_fetches = int64_t(dynamic_count_);
}

TbvIds TbvManager::objectsToUpdate() const {
    assert(in_frame_);
    if (options_.mode == TbvUpdateMode::Implicit && frame_ > 1) return {&empty_, &empty_};
    return liveObjects();
}

void TbvManager::touch(int object) {
    int64_t& stamp = touched_frame_[size_t(object)];
    if (stamp == frame_) return;
    stamp = frame_;
    ++counters_.objects_visited;
}

void TbvManager::fetch(int object) {
    int64_t& stamp = fetched_frame_[size_t(object)];
    if (stamp == frame_) return;
    stamp = frame_;
    ++counters_.state_fetches;
}

void TbvManager::updVis(int object) {
    const size_t i = checked(object);
    assert(in_frame_ && "updVis outside a frame");
    assert(live_slot_[i] >= 0 && "updVis of an object under a TBV: reveal it first");
    touch(object);
    fetch(object);
    ++counters_.object_updates;
    written_time_[i] = now_;
}

void TbvManager::observe(int object) {
    const size_t i = checked(object);
    assert(in_frame_ && "observe outside a frame");
    assert(live_slot_[i] >= 0 && "observe of an object under a TBV: reveal it first");
    touch(object);
    // Drawing the object needs its configuration; in TBVe step 2 or reveal()
    // fetched it already this frame.
    fetch(object);
    observed_frame_[i] = frame_;
}

bool TbvManager::reveal(int object) {
    checked(object);
    assert(in_frame_ && "reveal outside a frame");
    if (!hasTbv(object)) return false;
    delTbv(object, TbvDropReason::Revealed);
    updVis(object);
    return true;
}

void TbvManager::delTbv(int object, TbvDropReason reason) {
    const size_t i = checked(object);
    assert(in_frame_ && "del_TBV outside a frame");
    assert(hidden_slot_[i] >= 0 && "del_TBV of an object without a TBV");
    touch(object);
    const TbvRecord& b = tbv_[i];
    queue_.cancel(object);  // nothing to do when Q has just popped it
    removeHidden(object);
    addLive(object);
    drop_frame_[i] = frame_;
    drop_reason_[i] = reason;
    switch (reason) {
        case TbvDropReason::Expired:
            state_[i] = TbvObjectState::Expired;
            validity_.expired(object);
            ++counters_.tbv_expired;
            break;
        case TbvDropReason::Revealed:
            state_[i] = TbvObjectState::Revealed;
            validity_.revealed(object, b.expiry - b.created);
            ++counters_.tbv_revealed;
            break;
        case TbvDropReason::Violated:
            state_[i] = TbvObjectState::Violated;
            ++counters_.tbv_violated;
            break;
        case TbvDropReason::Invalidated:
            state_[i] = TbvObjectState::Violated;
            ++counters_.tbv_invalidated;
            break;
    }
}

double TbvManager::nextValidity(int object) const {
    const double period = validity_.period(object);
    if (!options_.spread_validity) return period;
    // Spread, but never below the floor: a TBV that ends before the next frame
    // saves nothing, and in TBVi an object whose TBV expires in step 1 is out
    // of T for that frame, so an object lost in view one frame would be lost
    // the next as well (two frames late).
    return std::max(spreadValidity(period, object, made_[size_t(object)]),
                    std::min(period, options_.validity_floor));
}

void TbvManager::makeTbv(int object, const TbvShape& shape, double validity) {
    const size_t i = size_t(object);
    assert(validity > 0.0 && "a TBV's validity must be > 0");
    TbvRecord& b = tbv_[i];
    b.serial = made_[i]++;
    b.shape = shape;
    b.created = now_;
    b.expiry = now_ + validity;
    removeLive(object);
    addHidden(object);
    state_[i] = TbvObjectState::Hidden;
    written_time_[i] = -std::numeric_limits<double>::infinity();
    if (std::isfinite(b.expiry)) queue_.schedule(object, b.expiry);
    ++counters_.tbv_created;
    ++counters_.tbv_messages;
}

bool TbvManager::reportViolation(int object) {
    const size_t i = checked(object);
    assert(state_[i] != TbvObjectState::Static && "violation reported for a static object");
    if (hidden_slot_[i] < 0) return false;
    violation_serial_[i] = tbv_[i].serial;
    if (violation_pending_[i]) return true;
    violation_pending_[i] = 1;
    pending_violations_.push_back(object);  // one entry per object, reserved for n
    return true;
}

bool TbvManager::violates(int object, const TbvBox& current_box) const {
    if (!hasTbv(object)) return false;
    return !tbvContainsBox(tbv_[size_t(object)].shape, current_box);
}

bool TbvManager::violates(int object, const glm::dvec3& centre, double radius) const {
    if (!hasTbv(object)) return false;
    return !tbvContainsBall(tbv_[size_t(object)].shape, centre, radius);
}

double TbvManager::remaining(int object) const {
    if (!hasTbv(object)) return 0.0;
    const TbvRecord& b = tbv_[size_t(object)];
    if (!std::isfinite(b.expiry)) return std::numeric_limits<double>::infinity();
    return b.expiry - now_;
}

TbvObjectView TbvManager::view(int object) const {
    const size_t i = checked(object);
    TbvObjectView v;
    v.state = state_[i];
    if (v.state == TbvObjectState::Static) return v;
    v.has_tbv = hidden_slot_[i] >= 0;
    v.period = validity_.period(object);
    if (v.has_tbv) {
        v.created = tbv_[i].created;
        v.expiry = tbv_[i].expiry;
        v.remaining = remaining(object);
    }
    v.dropped = drop_frame_[i] != 0;
    v.last_drop = drop_reason_[i];
    v.last_drop_frame = drop_frame_[i];
    v.written_time = written_time_[i];
    return v;
}

void TbvManager::addLive(int object) {
    assert(live_slot_[size_t(object)] < 0);
    live_slot_[size_t(object)] = int32_t(live_.size());
    live_.push_back(object);  // reserved for n: no allocation
}

void TbvManager::removeLive(int object) {
    const int32_t slot = live_slot_[size_t(object)];
    assert(slot >= 0);
    const int last = live_.back();
    live_[size_t(slot)] = last;
    live_slot_[size_t(last)] = slot;
    live_.pop_back();
    live_slot_[size_t(object)] = -1;
}

void TbvManager::addHidden(int object) {
    assert(hidden_slot_[size_t(object)] < 0);
    hidden_slot_[size_t(object)] = int32_t(hidden_.size());
    hidden_.push_back(object);  // reserved for n: no allocation
}

void TbvManager::removeHidden(int object) {
    const int32_t slot = hidden_slot_[size_t(object)];
    assert(slot >= 0);
    const int last = hidden_.back();
    hidden_[size_t(slot)] = last;
    hidden_slot_[size_t(last)] = slot;
    hidden_.pop_back();
    hidden_slot_[size_t(object)] = -1;
}

uint64_t TbvManager::nextRandom() {
    // SplitMix64: the same sequence on every platform.
    uint64_t z = (random_state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

size_t TbvManager::reservedBytes() const {
    return state_.capacity() * sizeof(TbvObjectState) + tbv_.capacity() * sizeof(TbvRecord) +
           live_.capacity() * sizeof(int) + live_slot_.capacity() * sizeof(int32_t) +
           hidden_.capacity() * sizeof(int) + hidden_slot_.capacity() * sizeof(int32_t) +
           pending_violations_.capacity() * sizeof(int) + violation_pending_.capacity() +
           violation_serial_.capacity() * sizeof(uint64_t) + made_.capacity() * sizeof(uint64_t) +
           observed_frame_.capacity() * sizeof(int64_t) +
           fetched_frame_.capacity() * sizeof(int64_t) +
           touched_frame_.capacity() * sizeof(int64_t) + drop_frame_.capacity() * sizeof(int64_t) +
           drop_reason_.capacity() * sizeof(TbvDropReason) +
           written_time_.capacity() * sizeof(double);
}

bool TbvManager::consistent() const {
    size_t dynamic = 0;
    for (size_t i = 0; i < state_.size(); ++i) {
        const int object = int(i);
        const bool in_v = live_slot_[i] >= 0;
        const bool hidden = hidden_slot_[i] >= 0;
        if (state_[i] == TbvObjectState::Static) {
            if (in_v || hidden || queue_.scheduled(object)) return false;
            continue;
        }
        ++dynamic;
        if (in_v == hidden) return false;  // exactly one of V and the hidden set
        if (in_v && live_[size_t(live_slot_[i])] != object) return false;
        if (hidden && hidden_[size_t(hidden_slot_[i])] != object) return false;
        if (hidden != (state_[i] == TbvObjectState::Hidden)) return false;
        const bool should_be_queued = hidden && std::isfinite(tbv_[i].expiry);
        if (queue_.scheduled(object) != should_be_queued) return false;
        if (should_be_queued && queue_.expiryOf(object) != tbv_[i].expiry) return false;
    }
    return dynamic == dynamic_count_ && live_.size() + hidden_.size() == dynamic_count_ &&
           queue_.size() <= hidden_.size();
}

}  // namespace gridcull
