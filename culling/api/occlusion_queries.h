// Occlusion queries on an image target (culling/api/image_target.h), in the
// terms of Kovalčík & Sochor, "Fast rendering of complex dynamic scenes",
// section 3.4 and Algorithm 2, and of OpenGL's GL_ANY_SAMPLES_PASSED: a query
// rasterizes an axis-aligned world-space box (a BSP node's box, an object's box)
// against the depth drawn so far this frame, writing nothing, and answers
// whether any sample passes the depth test.
//
// Meaning. The answer is "visible" when some pixel centre (the centres of
// raster/id_depth_buffer.h) sees the box at a depth in [near, far] strictly
// nearer ("<", as draws compare) than what is drawn there, or sees it where
// nothing is drawn; else "hidden". Two cases answer "visible" without any
// rasterization (occlusionQueryTriviallyVisible, the paper's ViewerInside): a
// box that contains the eye, and a box that crosses the near plane (some corner
// nearer than near, some at or beyond it). A box wholly behind the near plane,
// beyond far or off screen is hidden. Hidden is conservative for everything
// inside the box: an object in it that the exact oracle would see at some pixel
// centre, not hidden there by what was drawn, makes the box visible.
//
// Lifecycle. issueQuery (between the target's begin() and end()) tests the box
// against the depth as it is at that moment (later draws do not change the
// answer, as a GPU executes commands in order) and returns its id. Several
// queries may be outstanding at once (the paper's batches of non-overlapping
// boxes). queryAvailable polls without blocking; queryResult returns the answer
// and releases the id (a GPU target may block there until it is ready; the
// software target returns it at once and counts a stall when it is read before
// it was available). queryLatencyFrames says how many begin() calls after the
// issue the answer becomes available: 0 means within the frame. Ids are checked:
// reading an id twice, one from before resetQueries(), or one never issued
// fails an assert (on in every build).
//
// Cap and cost. Outstanding queries live in a pool of slots reserved when the
// target is prepared (kOcclusionQueryReserve); issuing beyond it doubles the
// pool, which allocates (and on a GPU creates query objects) once, so that a
// culler's later frames issue without allocating. More than
// kMaxOutstandingOcclusionQueries outstanding at once is a broken contract
// (assert): a culler must read or reset its queries. Issue, poll and result are
// O(1) apart from the rasterization (software: O(pixels of the box's screen
// rectangle), stopping at the first passing pixel; GPU: a draw call of 12
// triangles, and a round trip for the result).
#pragma once
#include <algorithm>
#include <cassert>
#include <cstdint>
#include <vector>

#include "culling/scene/camera.h"
#include "grid/aabb.h"

namespace gridcull {

// Outstanding queries the pool holds without growing after prepare().
constexpr int kOcclusionQueryReserve = 1024;
// The most queries outstanding at once (a broken contract beyond).
constexpr int kMaxOutstandingOcclusionQueries = 1 << 16;

// A query's id: its slot in the pool and the serial number of its issue, so that
// a stale id (already read, or from before resetQueries) is caught.
struct OcclusionQuery {
    int32_t slot = -1;
    uint32_t serial = 0;
};

// Totals since the target was prepared (a culler takes differences per frame).
struct OcclusionQueryCounts {
    long long issued = 0;   // issueQuery calls
    long long trivial = 0;  // of those, answered visible without rasterizing
    long long read = 0;     // queryResult calls
    long long stalled = 0;  // of those, read before they were available
};

// Does `box` answer visible without rasterizing, seen by `camera`? True when it
// contains the eye or crosses the near plane. The one rule every target shares.
bool occlusionQueryTriviallyVisible(const Camera& camera, const Aabb& box);

class OcclusionQueries {
public:
    virtual ~OcclusionQueries() = default;
    // Tests `box` (world space) against the depth drawn so far this frame.
    // Precondition: inside a frame (after begin(), before end()).
    virtual OcclusionQuery issueQuery(const Aabb& box) = 0;
    // Is the answer ready? Never blocks.
    virtual bool queryAvailable(const OcclusionQuery& query) = 0;
    // The answer (true: visible) and the end of the id. May block on a GPU.
    virtual bool queryResult(const OcclusionQuery& query) = 0;
    // Frames (begin() calls) between an issue and its answer's availability.
    virtual int queryLatencyFrames() const = 0;
    virtual OcclusionQueryCounts queryCounts() const = 0;
    // Queries issued and not yet read.
    virtual int outstandingQueries() const = 0;
    // Forgets every outstanding query (their ids become invalid); prepare()
    // does this too.
    virtual void resetQueries() = 0;
};

// The slot pool behind a target's queries: ids, their checks, the free list and
// the counts. Payload is what a target keeps per query. Not virtual; the
// software and OpenGL targets each hold one.
template <class Payload>
class OcclusionQueryPool {
public:
    // Makes room for `capacity` outstanding queries (allocates; never shrinks).
    // Returns the first new slot, so that a target can set up slots
    // [returned, capacity()).
    int reserve(int capacity) {
        assert(capacity <= kMaxOutstandingOcclusionQueries && "too many outstanding queries");
        const int old = this->capacity();
        if (capacity <= old) return old;
        slots_.resize(size_t(capacity));
        free_.reserve(size_t(capacity));
        for (int s = capacity - 1; s >= old; --s) free_.push_back(s);
        return old;
    }
    int capacity() const { return int(slots_.size()); }
    int outstanding() const { return capacity() - int(free_.size()); }
    // A new id; the caller fills payload(id). Grows the pool (doubling) when full.
    OcclusionQuery acquire() {
        if (free_.empty()) {
            const int grown = std::max(kOcclusionQueryReserve, 2 * capacity());
            assert(capacity() < kMaxOutstandingOcclusionQueries &&
                   "more than kMaxOutstandingOcclusionQueries outstanding queries");
            reserve(std::min(grown, kMaxOutstandingOcclusionQueries));
        }
        const int32_t slot = free_.back();
        free_.pop_back();
        Slot& s = slots_[size_t(slot)];
        s.busy = true;
        s.serial = ++serial_;
        return {slot, s.serial};
    }
    // The payload of a live id (asserts that it is one).
    Payload& payload(const OcclusionQuery& query) { return slots_[size_t(check(query))].payload; }
    // Ends a live id.
    void release(const OcclusionQuery& query) {
        Slot& s = slots_[size_t(check(query))];
        s.busy = false;
        free_.push_back(query.slot);
    }
    // Ends every id.
    void releaseAll() {
        free_.clear();
        for (int s = capacity() - 1; s >= 0; --s) {
            slots_[size_t(s)].busy = false;
            free_.push_back(s);
        }
    }
    // The payload of slot s, live or not (for setting up and tearing down).
    Payload& slotPayload(int s) { return slots_[size_t(s)].payload; }

private:
    struct Slot {
        Payload payload{};
        uint32_t serial = 0;
        bool busy = false;
    };
    int check(const OcclusionQuery& query) const {
        assert(query.slot >= 0 && query.slot < capacity() && "not an occlusion query id");
        const Slot& s = slots_[size_t(query.slot)];
        assert(s.busy && s.serial == query.serial && "stale occlusion query id (read or reset)");
        (void)s;
        return query.slot;
    }
    std::vector<Slot> slots_;
    std::vector<int32_t> free_;
    uint32_t serial_ = 0;
};

}  // namespace gridcull
