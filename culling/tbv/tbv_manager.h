// The temporal bounding volumes of a dynamic scene, apart from any spatial
// structure (Sudarsky & Gotsman, "Dynamic scene occlusion culling", IEEE TVCG
// 1999, sections 3.2 to 3.7). A culler owns its spatial structure T (an octree,
// a grid, ...) and calls this manager at the four steps of section 3.3; the
// manager keeps the paper's other data:
//  - D: per dynamic object its state (TbvObjectState), its TBV (shape, creation
//    time, expiry: TbvRecord) and its validity period (section 3.4);
//  - Q: the queue of TBV expirations (TbvExpiryQueue);
//  - V: the dynamic objects without a TBV, (potentially) visible ones, kept as a
//    dense list with O(1) insertion and removal, so that step 2 and step 4 visit
//    V alone, never every object.
// It also counts the frame's work and messages (TbvFrameCounters, section 3.7).
//
// ---------------------------------------------------------------------------
// A frame, as the culler calls it (the paper's steps):
//
//   tbv.beginFrame(t, [&](int id, TbvDropReason why) {   // step 1
//       // del_TBV(id) happened: take the TBV's volume out of T.
//   });
//   for (int id : tbv.objectsToUpdate()) {                // step 2
//       tbv.updVis(id);  // write the object at its current configuration in T
//   }
//   // step 3: traverse T. At an object: if it is visible, draw it and call
//   // tbv.observe(id). At a TBV's volume found visible: tbv.reveal(id)
//   // (del_TBV + upd_vis), take the volume out of T, write the object at its
//   // current configuration in T, and test it like any object met there.
//   tbv.endFrame([&](int id, double& validity) {          // step 4
//       // id was in V and nobody observed it: take it out of T, and return its
//       // TBV for `validity` seconds from now (may be shortened, > 0), e.g.
//       TbvShape s = sphereTbv(3, position(id), radius(id), speed(id), validity);
//       insertIntoT(id, tbvBounds(s));
//       return s;
//   });
//
// Between frames, the object's controller (its motion model) may call
// reportViolation(id) when it finds the object outside its fuzzy TBV
// (violates(id, box)); the TBV is dropped in the next beginFrame's step 1, that
// is in the frame whose positions the controller checked.
//
// Only what the paper touches is touched: step 1 pops the TBVs that end (Q,
// violations, the random invalidations), steps 2 and 4 visit V, step 3 the
// objects the culler meets. A hidden object under a valid TBV costs nothing
// between its TBV's creation and its end (TbvFrameCounters::objects_visited).
//
// ---------------------------------------------------------------------------
// Explicit and implicit update (section 3.6):
//  - TBVe (TbvUpdateMode::Explicit): step 2 rewrites every object of V in T at
//    its current configuration each frame; a hidden object's TBV is in T in the
//    object's place.
//  - TBVi (TbvUpdateMode::Implicit): step 2 is omitted (objectsToUpdate() is
//    empty after the first frame). An object is written in T only when its TBV
//    is revealed (or on the first frame), and stays there at that configuration
//    while it is in V (writtenTime() tells when); T is updated implicitly by the
//    TBVs of step 4. Which frame an object coming into view shows up in:
//      * hidden under a valid TBV: the frame its TBV is revealed, in both modes
//        (as long as the culler tests the object right after reveal(); if it
//        postpones changes of T to the end of the traversal, one frame later,
//        in both modes: section 3.3's remark on step 3);
//      * its TBV expired or was violated in step 1 of frame f: TBVe writes it
//        in step 2 and shows it in frame f; TBVi has it in no node of T in frame
//        f, gives it a TBV at its current position in step 4, reveals that TBV
//        in frame f + 1 and shows it then: one frame late;
//      * already in V but no longer in the nodes it was written in (it moved
//        while in view, TBVi only): lost in that frame, which gives it a TBV in
//        step 4, revealed and shown in the next frame: one frame late.
//    So in TBVi an object is omitted for at most one frame (section 3.6).
//
// Messages (section 3.7, tbv_messages.h): a state fetch when the object's
// configuration is needed (upd_vis; in TBVi also observe(), since drawing an
// object needs its configuration though T is not updated), at most one per
// object per frame; a TBV message per TBV made; a violation message per report.
//
// ---------------------------------------------------------------------------
// Departures from the paper, and why:
//  - Static objects are not managed (the paper: "the algorithm treats static
//    objects differently from dynamic ones"); only objects given to
//    addDynamic() are.
//  - "Time of last observation" is kept as the frame number of the last
//    observe(): frames go in order, and an integer compares exactly.
//  - Q is a binary heap with deferred deletion (TbvExpiryQueue) instead of a skip
//    list: O(log i) per insertion and per cancellation, no allocation after
//    reset(). A TBV expires in the first frame whose time is past its expiry
//    (expiry < t), so a TBV is trusted for its whole validity period.
//  - A violation report is queued and applied at the next step 1, as the paper
//    says ("it calls del_TBV(ID) in step 1"), not at the moment it arrives.
//  - Adaptive validity (section 3.4) changes an object's period only on an
//    expiry (doubled) or a reveal (halved, from the period that TBV used); a
//    violated or randomly invalidated TBV says nothing about its period being
//    too short or too long, so the period stays.
//  - Fig. 14's experiment (a fraction of the valid TBVs invalidated each frame)
//    is a knob, invalidate_fraction: round(fraction * valid TBVs), rounded up or
//    down at random so the mean is exact, TBVs picked uniformly without
//    repetition by a seeded SplitMix64 (deterministic runs), in O(picked).
//  - TBVi's first frame writes every dynamic object in T (objectsToUpdate() is
//    V on frame 1 in both modes): the paper's initial state has every dynamic
//    object marked visible, i.e. in T, and without this every object would be
//    one frame late at the start.
//  - renew() gives an object whose TBV just expired its next TBV at once, for
//    a culler that follows Batagelo & Wu's regular grid ("a new validity
//    period is attributed") rather than looking at the object again.
//  - Optional spread of validity periods (spreadValidity, off by default: the
//    paper has none) so that TBVs made in one frame do not all expire together;
//    a spread period never falls below validity_floor (one frame), or TBVi
//    could lose an object for two frames in a row.
//
// Costs: reset() O(n) and allocates everything; after it no call allocates.
// Object ids are [0, n); an id out of range, or a call out of the frame order,
// fails an assert (asserts stay on in every build).
#pragma once
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/tbv/tbv_expiry_queue.h"
#include "culling/tbv/tbv_messages.h"
#include "culling/tbv/tbv_shapes.h"
#include "culling/tbv/tbv_validity.h"

namespace gridcull {

enum class TbvUpdateMode { Explicit, Implicit };  // TBVe, TBVi (section 3.6)
const char* tbvUpdateModeName(TbvUpdateMode mode);

// Where a dynamic object stands. Between frames (after endFrame) an object is
// Visible or Hidden; Expired, Revealed and Violated last from the TBV's end to
// that frame's step 4, which resolves them (view()'s last_drop remembers them).
enum class TbvObjectState : uint8_t {
    Static,    // not managed (never given to addDynamic)
    Visible,   // in V, observed in the last frame (or not yet looked at)
    Hidden,    // under a valid TBV
    Expired,   // its TBV expired in this frame's step 1; in V
    Revealed,  // its TBV was found visible in this frame's step 3; in V
    Violated,  // its fuzzy TBV was reported violated (or invalidated at random); in V
};
const char* tbvObjectStateName(TbvObjectState state);

enum class TbvDropReason : uint8_t { Expired, Revealed, Violated, Invalidated };
const char* tbvDropReasonName(TbvDropReason reason);

struct TbvManagerOptions {
    TbvUpdateMode mode = TbvUpdateMode::Explicit;
    TbvValidityMode validity_mode = TbvValidityMode::Adaptive;
    double initial_validity = 1.0;     // seconds, > 0: every object's first period
    double validity_floor = 0.0;       // seconds: adaptive periods never go below (one frame, say)
    bool spread_validity = false;      // spreadValidity() on each period
    double invalidate_fraction = 0.0;  // [0, 1]: Fig. 14's fraction of valid TBVs dropped per frame
    uint64_t seed = 1;                 // for invalidate_fraction
};

// An object's TBV: the current one while the object is Hidden, else the last.
struct TbvRecord {
    TbvShape shape;
    double created = 0.0;  // seconds
    double expiry = 0.0;   // seconds; +infinity: never expires
    uint64_t serial = 0;   // how many TBVs the object had before this one
};

// What the window shows of one object (read-only, O(1)).
struct TbvObjectView {
    TbvObjectState state = TbvObjectState::Static;
    bool has_tbv = false;
    double period = 0.0;     // the validity period its next TBV gets, seconds
    double created = 0.0;    // of its TBV (has_tbv)
    double expiry = 0.0;     // of its TBV (has_tbv)
    double remaining = 0.0;  // expiry - now (has_tbv), else 0
    bool dropped = false;    // its TBV ended at some frame
    TbvDropReason last_drop = TbvDropReason::Expired;                // how (dropped)
    int64_t last_drop_frame = 0;                                     // when (dropped)
    double written_time = -std::numeric_limits<double>::infinity();  // see writtenTime()
};

// A read-only list of object ids (valid until the manager's next non-const call).
struct TbvIds {
    const int* first = nullptr;
    const int* last = nullptr;
    const int* begin() const { return first; }
    const int* end() const { return last; }
    size_t size() const { return size_t(last - first); }
    bool empty() const { return first == last; }
    int operator[](size_t i) const {
        assert(i < size());
        return first[i];
    }
};

class TbvManager {
public:
    // Forgets everything and reserves for objects [0, n), none of them dynamic.
    void reset(size_t n, const TbvManagerOptions& options);
    // Makes `object` dynamic: Visible, in V. Before the first frame only.
    void addDynamic(int object);

    // --- The frame -------------------------------------------------------
    // Step 1: starts the frame at time t (>= the last frame's) and ends the TBVs
    // that end now, each by del_TBV then on_drop(object, reason): first the
    // reported violations, then the expirations from Q (earliest first), then
    // the random invalidations. The objects join V.
    template <typename OnDrop>
    void beginFrame(double t, OnDrop&& on_drop);
    // Step 2: the objects to write in T at their current configuration, each
    // with updVis(): V in TBVe, nothing in TBVi (but on the first frame).
    TbvIds objectsToUpdate() const;
    // upd_vis: the object's current configuration is fetched (a message) and
    // the culler writes the object in T. The object must be in V.
    void updVis(int object);
    // Step 3: the culler found the object (in V) visible: its time of last
    // observation is now. Idempotent within a frame.
    void observe(int object);
    // Step 3: the culler found the object's TBV visible: del_TBV and upd_vis
    // (the culler takes the TBV out of T and writes the object in). False, and
    // nothing done, if the object has no TBV (already revealed at another node).
    bool reveal(int object);
    // Step 4: every object of V not observed this frame leaves V, becomes
    // Hidden, and gets a TBV from make_tbv(object, validity&) -> TbvShape for
    // `validity` seconds from now (the culler may shorten it, keeping it > 0,
    // or make it +infinity for an object that cannot move; it takes the object
    // out of T and puts the shape in). Ends the frame.
    template <typename MakeTbv>
    void endFrame(MakeTbv&& make_tbv);
    // Renewal, for a culler that gives an object whose TBV just expired its
    // next TBV at once instead of looking at it again (Batagelo & Wu's regular
    // grid, section 4.1: "if TBV validity period is expired, a new validity
    // period is attributed"): the object, in V, gets its TBV now, exactly as
    // step 4 would give it (make_tbv as there), and leaves V. Inside a frame.
    template <typename MakeTbv>
    void renew(int object, MakeTbv&& make_tbv);

    // del_TBV: drops the object's TBV (which it must have) for `reason`: it
    // leaves Q, joins V, and its period adapts (section 3.4: doubled on Expired,
    // halved on Revealed). Inside a frame only. The culler takes the TBV out of T.
    void delTbv(int object, TbvDropReason reason);

    // --- Fuzzy TBVs (section 3.5) -----------------------------------------
    // The object's controller reports that the object left its TBV: the TBV is
    // dropped (Violated) in the next beginFrame's step 1. False if the object
    // has no TBV (nothing to violate). Any time after addDynamic.
    bool reportViolation(int object);
    // Whether the object's current box (or ball) is outside its TBV (false
    // without a TBV): what a controller checks before reporting.
    bool violates(int object, const TbvBox& current_box) const;
    bool violates(int object, const glm::dvec3& centre, double radius) const;

    // --- Reading ------------------------------------------------------------
    size_t objects() const { return state_.size(); }
    size_t dynamicCount() const { return dynamic_count_; }
    const TbvManagerOptions& options() const { return options_; }
    TbvUpdateMode mode() const { return options_.mode; }
    double now() const { return now_; }
    int64_t frame() const { return frame_; }
    bool inFrame() const { return in_frame_; }

    bool isDynamic(int object) const { return state(object) != TbvObjectState::Static; }
    TbvObjectState state(int object) const { return state_[checked(object)]; }
    bool hasTbv(int object) const { return hidden_slot_[checked(object)] >= 0; }
    bool inV(int object) const { return live_slot_[checked(object)] >= 0; }
    // The object's current TBV if hasTbv, else its last one.
    const TbvRecord& tbv(int object) const { return tbv_[checked(object)]; }
    // The box around the object's current TBV, what a structure inserts.
    TbvBox bounds(int object) const {
        assert(hasTbv(object) && "bounds of an object without a TBV");
        return tbvBounds(tbv_[size_t(object)].shape);
    }
    // The validity period the object's next TBV gets (before any spread).
    double period(int object) const { return validity_.period(int(checked(object))); }
    // Seconds left of the object's TBV (+infinity if it never expires); 0 without one.
    double remaining(int object) const;
    // The time of the configuration T holds for the object (its last updVis),
    // -infinity if T does not hold the object itself. In TBVi it lags behind.
    double writtenTime(int object) const { return written_time_[checked(object)]; }
    TbvObjectView view(int object) const;

    TbvIds liveObjects() const { return {live_.data(), live_.data() + live_.size()}; }  // V
    TbvIds hiddenObjects() const { return {hidden_.data(), hidden_.data() + hidden_.size()}; }

    // This frame's counts (since beginFrame), and the sums since reset().
    const TbvFrameCounters& frameCounters() const { return counters_; }
    const TbvFrameCounters& totals() const { return totals_; }
    const TbvExpiryQueue& queue() const { return queue_; }
    const TbvValidityPeriods& validity() const { return validity_; }

    // Bytes reserved by the manager's own arrays (the queue's aside). Constant
    // from reset() on: nothing grows in a frame.
    size_t reservedBytes() const;
    // Checks every invariant (each dynamic object in exactly one of V and the
    // hidden set, the slots, Q against the TBVs). O(n): for tests.
    bool consistent() const;

private:
    size_t checked(int object) const {
        assert(object >= 0 && size_t(object) < state_.size() && "TBV object id out of range");
        return size_t(object);
    }
    void touch(int object);
    void fetch(int object);
    void addLive(int object);
    void removeLive(int object);
    void addHidden(int object);
    void removeHidden(int object);
    void startFrame(double t);
    void dropViolations();
    template <typename OnDrop>
    void dropInvalidated(OnDrop& on_drop);
    void makeTbv(int object, const TbvShape& shape, double validity);
    double nextValidity(int object) const;
    uint64_t nextRandom();

    TbvManagerOptions options_;
    TbvExpiryQueue queue_;  // Q
    TbvValidityPeriods validity_;
    std::vector<TbvObjectState> state_;
    std::vector<TbvRecord> tbv_;
    std::vector<int> live_;                   // V
    std::vector<int32_t> live_slot_;          // index in live_, -1 if not in V
    std::vector<int> hidden_;                 // objects under a TBV
    std::vector<int32_t> hidden_slot_;        // index in hidden_, -1 without a TBV
    std::vector<int> pending_violations_;     // reported, applied at the next step 1
    std::vector<uint8_t> violation_pending_;  // in pending_violations_
    std::vector<uint64_t> violation_serial_;  // the serial of the TBV reported violated
    std::vector<uint64_t> made_;              // TBVs made for the object so far
    std::vector<int64_t> observed_frame_;     // time of last observation (a frame number)
    std::vector<int64_t> fetched_frame_;      // last frame whose state fetch was counted
    std::vector<int64_t> touched_frame_;      // last frame counted in objects_visited
    std::vector<int64_t> drop_frame_;         // frame of the last del_TBV, 0 if none
    std::vector<TbvDropReason> drop_reason_;
    std::vector<double> written_time_;
    size_t dynamic_count_ = 0;
    int64_t frame_ = 0;
    double now_ = -std::numeric_limits<double>::infinity();
    bool in_frame_ = false;
    uint64_t random_state_ = 0;
    int empty_ = 0;  // what an empty TbvIds points at
    TbvFrameCounters counters_;
    TbvFrameCounters totals_;
};

// ---------------------------------------------------------------------------
// The templates.

template <typename OnDrop>
void TbvManager::beginFrame(double t, OnDrop&& on_drop) {
    startFrame(t);
    // Violations first: a TBV both violated and expired was violated, and its
    // period must not double for it.
    for (const int object : pending_violations_) {
        violation_pending_[size_t(object)] = 0;
        ++counters_.violation_messages;
        touch(object);
        // A report about a TBV that has ended since (revealed after the report)
        // does not apply to the object's next TBV.
        if (!hasTbv(object) || tbv_[size_t(object)].serial != violation_serial_[size_t(object)])
            continue;
        delTbv(object, TbvDropReason::Violated);
        on_drop(object, TbvDropReason::Violated);
    }
    pending_violations_.clear();
    queue_.popExpired(t, [&](int object) {
        delTbv(object, TbvDropReason::Expired);
        on_drop(object, TbvDropReason::Expired);
    });
    dropInvalidated(on_drop);
}

template <typename OnDrop>
void TbvManager::dropInvalidated(OnDrop& on_drop) {
    const double f = options_.invalidate_fraction;
    if (f <= 0.0 || hidden_.empty()) return;
    // Expected count f * valid: its floor, plus one with the fraction's probability.
    const double expected = f * double(hidden_.size());
    size_t count = size_t(expected);
    const double unit = double(nextRandom() >> 11) * (1.0 / 9007199254740992.0);
    if (unit < expected - double(count)) ++count;
    count = std::min(count, hidden_.size());
    // Uniform picks without repetition: a dropped TBV leaves hidden_ (its slot
    // takes the last entry), so the next pick is among the rest. Objects
    // dropped here join V and get no TBV before step 4, so none is picked twice.
    for (size_t k = 0; k < count; ++k) {
        const int object = hidden_[size_t(nextRandom() % hidden_.size())];
        delTbv(object, TbvDropReason::Invalidated);
        on_drop(object, TbvDropReason::Invalidated);
    }
}

template <typename MakeTbv>
void TbvManager::endFrame(MakeTbv&& make_tbv) {
    assert(in_frame_ && "endFrame without beginFrame");
    // Backwards: removing an object moves V's last entry, already visited, into its slot.
    for (size_t i = live_.size(); i-- > 0;) {
        const int object = live_[i];
        touch(object);
        if (observed_frame_[size_t(object)] == frame_) {
            state_[size_t(object)] = TbvObjectState::Visible;
            continue;
        }
        renew(object, make_tbv);
    }
    in_frame_ = false;
    accumulate(totals_, counters_);
}

template <typename MakeTbv>
void TbvManager::renew(int object, MakeTbv&& make_tbv) {
    assert(in_frame_ && "renew outside a frame");
    assert(inV(object) && "renew of an object under a TBV");
    touch(object);
    double validity = nextValidity(object);
    const TbvShape shape = make_tbv(object, validity);
    makeTbv(object, shape, validity);
}

}  // namespace gridcull
