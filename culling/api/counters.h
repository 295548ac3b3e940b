// The counters a culler reports per frame, besides cull_ms: one table of names
// and meanings (kCounters), the one place a counter is defined. Names are
// snake_case and appear verbatim in `cull`'s JSON, `bench`'s table and CSV and
// the window's statistics; each algorithm reports the ones its paper measures.
//
// Words that sound alike mean one thing each:
//   occlusion_tests  bounding volumes tested for occlusion against an image
//                    (one decision each, however it is reached);
//   pixel_queries    reads of pixels from that image (a read-back each on a
//                    GPU), to decide a test or to refresh cells after a draw;
//   cell_updates     the pixel queries that read a whole grid cell to refresh
//                    its state, a subset of pixel_queries.
// A counter is added here with its meaning when an algorithm first reports it,
// never ahead of one (a registry test checks that some algorithm reports each).
// `gridcull counters` prints the table.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

namespace gridcull {

enum class Counter : uint8_t {
    VoxelsVisited,
    TbvCreated,
    TbvExpired,
    TbvRevealed,
    ObjectUpdates,
    PixelQueries,
    NodesVisited,
    TrianglesDrawn,
    ObjectsTested,
    PixelsSampled,
    OcclusionTests,
    PixelsRead,
    CellUpdates,
    BvhRebuilds,
    ProbabilitySkips,
    StateFetches,
    TbvMessages,
    OctreeUpdateNodes,
    OcclusionQueries,
    QueryBatches,
    CoherenceSkips,
    PartsDrawn,
    QueriesHidden,
    SubSampleCandidates,
    SubSampleVisible,
    SubSampleUndecided,
    RefineRays,
    Count
};
constexpr int kCounterCount = int(Counter::Count);

struct CounterInfo {
    Counter counter;
    const char* name;     // JSON and CSV name, e.g. "voxels_visited"
    const char* meaning;  // one line, for help, the window and the docs
};

// Every counter, in Counter order (a static_assert in counters.cpp keeps it so).
extern const std::array<CounterInfo, kCounterCount> kCounters;

inline const char* counterName(Counter counter) {
    return kCounters[size_t(counter)].name;
}
inline const char* counterMeaning(Counter counter) {
    return kCounters[size_t(counter)].meaning;
}

struct CullStats {
    double cull_ms = 0.0;
    std::array<int64_t, kCounterCount> values{};
    uint32_t present = 0;  // bit i set when counter i was reported
    static_assert(kCounterCount <= 32, "present is a 32-bit mask");

    void set(Counter c, int64_t v) {
        values[size_t(c)] = v;
        present |= 1u << int(c);
    }
    void add(Counter c, int64_t v) {
        values[size_t(c)] += v;
        present |= 1u << int(c);
    }
    bool has(Counter c) const { return (present >> int(c)) & 1u; }
    int64_t get(Counter c) const { return values[size_t(c)]; }
};

}  // namespace gridcull
