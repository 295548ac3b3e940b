// What a frame of temporal bounding volumes costs, as counted by TbvManager
// (culling/tbv/tbv_manager.h): the manager's own work, and the messages a
// distributed virtual environment would send for it (Sudarsky & Gotsman,
// "Dynamic scene occlusion culling", section 3.7 and Fig. 15b).
//
// Messages, after section 3.7: a workstation that runs the algorithm asks for a
// dynamic object's current configuration (upd_vis step 1, "through a
// communication link") only when it needs it, and asks the object's controller
// for a TBV (step 4c) when the object goes out of sight. So:
//  - state_fetches: objects whose current configuration was needed this frame,
//    one message per object per frame at most (Fig. 15b's "DSVC Upd"). An object
//    updated normally costs one every frame; a hidden object under a valid TBV
//    costs none until its TBV expires, is revealed, or is violated.
//  - tbv_messages: TBVs received (Fig. 15b's "DSVC TBV"), one per TBV made.
//  - violation_messages: violations of fuzzy TBVs reported by the objects'
//    controllers (section 3.5), one per report.
//  - naive_fetches: what updating every dynamic object every frame would send
//    (Fig. 15b's "BSP Proj Upd"): the number of dynamic objects.
//
// Departure from the paper: Fig. 15b counts object updates and TBVs only; the
// violation reports of section 3.5 are counted apart so that the fuzzy TBV
// experiments (Fig. 14) show their traffic too. The randomly invalidated TBVs
// of Fig. 14 are a simulation knob, not a message, and cost none.
#pragma once
#include <cstdint>

namespace gridcull {

struct TbvFrameCounters {
    int64_t frame = 0;  // 1 for the first frame after reset()

    // The manager's work: distinct dynamic objects it looked at this frame (one
    // count per object however many times it was touched). Hidden objects under
    // valid TBVs are not looked at between their expiries: this stays at the
    // number of objects in V plus those whose TBVs ended this frame.
    int64_t objects_visited = 0;

    // TBV events this frame.
    int64_t tbv_created = 0;      // step 4: TBVs made for objects that went out of sight
    int64_t tbv_expired = 0;      // step 1: TBVs whose validity ran out
    int64_t tbv_revealed = 0;     // step 3: TBVs the traversal found visible
    int64_t tbv_violated = 0;     // step 1: fuzzy TBVs whose object was reported outside
    int64_t tbv_invalidated = 0;  // step 1: TBVs dropped at random (Fig. 14's experiment)
    int64_t object_updates = 0;   // upd_vis calls: objects (re)written into the structure

    // Messages (see the header comment).
    int64_t state_fetches = 0;
    int64_t tbv_messages = 0;
    int64_t violation_messages = 0;
    int64_t naive_fetches = 0;

    int64_t messages() const { return state_fetches + tbv_messages + violation_messages; }
};

// Adds `frame`'s counts into `total` (its `frame` becomes the last frame's).
inline void accumulate(TbvFrameCounters& total, const TbvFrameCounters& frame) {
    total.frame = frame.frame;
    total.objects_visited += frame.objects_visited;
    total.tbv_created += frame.tbv_created;
    total.tbv_expired += frame.tbv_expired;
    total.tbv_revealed += frame.tbv_revealed;
    total.tbv_violated += frame.tbv_violated;
    total.tbv_invalidated += frame.tbv_invalidated;
    total.object_updates += frame.object_updates;
    total.state_fetches += frame.state_fetches;
    total.tbv_messages += frame.tbv_messages;
    total.violation_messages += frame.violation_messages;
    total.naive_fetches += frame.naive_fetches;
}

}  // namespace gridcull
