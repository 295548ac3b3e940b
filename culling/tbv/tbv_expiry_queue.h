// The expiration queue of temporal bounding volumes (Sudarsky & Gotsman,
// "Dynamic scene occlusion culling", section 3.3: Q, the priority queue of TBV
// expiration events), kept apart from any spatial structure so that every
// family with TBVs shares it. A frame pops only the TBVs that expire in it, so
// the cost of hidden objects is paid when their TBVs expire, not every frame.
//
// One entry per object at most: schedule() replaces the object's earlier entry
// and cancel() drops it, both in O(log n) (a binary heap with deferred deletion: a
// replaced entry stays in the heap, marked stale by a generation count, until it
// surfaces or the heap is compacted). Compaction runs when stale entries would
// outgrow the capacity reserved by reset(), so a steady state allocates nothing.
//
// Objects are indices in [0, n) given to reset(). Expiry times are seconds; an
// object expires in the first popExpired(t) with t > its expiry.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gridcull {

class TbvExpiryQueue {
public:
    // Empties the queue for objects [0, n) and reserves its storage.
    void reset(size_t n);
    // Schedules (or moves) the object's expiry.
    void schedule(int object, double expiry);
    // Drops the object's entry, if any.
    void cancel(int object);
    bool scheduled(int object) const { return live_[size_t(object)] != 0; }
    double expiryOf(int object) const { return expiry_[size_t(object)]; }
    size_t size() const { return live_count_; }

    // Calls fn(object) for every object whose expiry is < t, earliest first,
    // removing each before the call (fn may schedule it again).
    template <typename Fn>
    void popExpired(double t, Fn&& fn) {
        while (!heap_.empty() && heap_.front().expiry < t) {
            const Entry top = popTop();
            if (!isCurrent(top)) continue;
            live_[size_t(top.object)] = 0;
            --live_count_;
            fn(int(top.object));
        }
    }

    // Fills `out` with up to `count` (object, expiry) pairs, earliest first, for
    // the window's list of next expiries. O(n log n); not for hot paths.
    void nextExpiries(size_t count, std::vector<std::pair<int, double>>& out) const;

private:
    struct Entry {
        double expiry;
        int32_t object;
        uint32_t generation;
    };
    bool isCurrent(const Entry& e) const {
        return live_[size_t(e.object)] != 0 && generation_[size_t(e.object)] == e.generation;
    }
    Entry popTop();
    void compact();

    std::vector<Entry> heap_;  // min-heap on expiry
    std::vector<uint32_t> generation_;
    std::vector<double> expiry_;
    std::vector<uint8_t> live_;
    size_t live_count_ = 0;
    size_t capacity_ = 0;
};

// Validity periods spread so that TBVs made in the same frame do not all
// expire in the same later frame (a burst of renewals is a stalled frame):
// `validity` scaled by a factor that hashes the object and how many TBVs it has
// had. An object's first TBV (serial 0), when every hidden object gets one at
// once, takes a factor in [kTbvFirstSpread, 1], which scatters the first
// expiries over most of a period; later ones take [1 - kTbvValiditySpread, 1],
// which keeps them scattered. Deterministic, so runs repeat exactly.
constexpr double kTbvValiditySpread = 0.25;
constexpr double kTbvFirstSpread = 0.05;
double spreadValidity(double validity, int object, uint64_t serial);

}  // namespace gridcull
