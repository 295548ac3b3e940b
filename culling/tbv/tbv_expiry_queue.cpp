#include "culling/tbv/tbv_expiry_queue.h"

#include <algorithm>

namespace gridcull {

namespace {

// std::push_heap and friends build a max-heap; this order makes it a min-heap.
struct Later {
    template <typename E>
    bool operator()(const E& a, const E& b) const {
        return a.expiry > b.expiry;
    }
};

}  // namespace

void TbvExpiryQueue::reset(size_t n) {
    heap_.clear();
    // Room for every object's live entry and as many stale ones before compacting.
    capacity_ = 2 * n + 16;
    heap_.reserve(capacity_);
    generation_.assign(n, 0);
    expiry_.assign(n, 0.0);
    live_.assign(n, 0);
    live_count_ = 0;
}

void TbvExpiryQueue::schedule(int object, double expiry) {
    const size_t i = size_t(object);
    if (!live_[i]) ++live_count_;
    live_[i] = 1;
    ++generation_[i];
    expiry_[i] = expiry;
    if (heap_.size() >= capacity_) compact();
    heap_.push_back(Entry{expiry, int32_t(object), generation_[i]});
    std::push_heap(heap_.begin(), heap_.end(), Later{});
}

void TbvExpiryQueue::cancel(int object) {
    const size_t i = size_t(object);
    if (!live_[i]) return;
    live_[i] = 0;
    ++generation_[i];
    --live_count_;
}

TbvExpiryQueue::Entry TbvExpiryQueue::popTop() {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    const Entry e = heap_.back();
    heap_.pop_back();
    return e;
}

void TbvExpiryQueue::compact() {
    heap_.erase(std::remove_if(heap_.begin(), heap_.end(),
                               [&](const Entry& e) { return !isCurrent(e); }),
                heap_.end());
    std::make_heap(heap_.begin(), heap_.end(), Later{});
}

void TbvExpiryQueue::nextExpiries(size_t count, std::vector<std::pair<int, double>>& out) const {
    out.clear();
    for (const Entry& e : heap_)
        if (isCurrent(e)) out.emplace_back(int(e.object), e.expiry);
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second < b.second : a.first < b.first;
    });
    if (out.size() > count) out.resize(count);
}

double spreadValidity(double validity, int object, uint64_t serial) {
    // SplitMix64 of (object, serial): a well-mixed 64-bit hash.
    uint64_t z = (uint64_t(uint32_t(object)) << 32) ^ serial;
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    const double unit = double(z >> 11) * (1.0 / 9007199254740992.0);  // [0, 1)
    if (serial == 0) return validity * (kTbvFirstSpread + (1.0 - kTbvFirstSpread) * unit);
    return validity * (1.0 - kTbvValiditySpread * unit);
}

}  // namespace gridcull
