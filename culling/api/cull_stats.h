// Per-frame statistics of a culler. cull_ms is always present; the counters are
// named after the papers' quantities and present only where an algorithm has
// them (shared/spec/cli.md lists the names used in `cull` output).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

namespace gridcull {

enum class Counter : int {
    VoxelsVisited,
    TbvCreated,
    TbvExpired,
    TbvRevealed,
    ObjectUpdates,
    UpdateMessages,
    PixelQueries,
    OcclusionQueries,
    NodesVisited,
    TrianglesDrawn,
    ObjectsTested,  // objects a culler looked at this frame (vfc, exact)
    PixelsSampled,  // rays or pixels the oracle evaluated
    OcclusionTests,    // lazy / busy grid: isOccluded calls (Hey et al. Fig. 2, 3)
    PixelsRead,        // lazy / busy grid: pixels read by its pixel-level queries
    CellUpdates,       // lazy / busy grid: pixel queries that read a whole cell
    BvhRebuilds,       // lazy / busy grid: hierarchy rebuilt from scratch this frame
    ProbabilitySkips,  // lazy / busy grid: pixel queries saved by section 6's threshold
    Count
};
constexpr int kCounterCount = int(Counter::Count);

// The snake_case name used in JSON and CSV, e.g. "voxels_visited".
const char* counterName(Counter counter);

struct CullStats {
    double cull_ms = 0.0;
    std::array<int64_t, kCounterCount> values{};
    uint32_t present = 0;  // bit i set when counter i was reported

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
