// The counter table (culling/api/counters.h): the names `cull`, `bench` and the
// window print, each in snake_case, each once, each with a meaning.
#include <algorithm>
#include <cctype>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/api/counters.h"

namespace gridcull {
namespace {

TEST(Counters, AreTheOutputNamesInSnakeCaseWithAMeaningEach) {
    // The names of `cull`'s JSON and bench's CSV: changing one breaks readers.
    const std::vector<std::string> expected = {
        "voxels_visited", "tbv_created",    "tbv_expired",      "tbv_revealed",
        "object_updates", "pixel_queries",  "nodes_visited",    "triangles_drawn",
        "objects_tested", "pixels_sampled", "occlusion_tests",  "pixels_read",
        "cell_updates",   "bvh_rebuilds",   "probability_skips", "state_fetches",
        "tbv_messages",   "octree_update_nodes", "occlusion_queries", "query_batches",
        "coherence_skips", "parts_drawn", "queries_hidden", "sub_sample_candidates",
        "sub_sample_visible", "sub_sample_undecided", "refine_rays"};
    ASSERT_EQ(int(expected.size()), kCounterCount);
    std::set<std::string> seen;
    for (int i = 0; i < kCounterCount; ++i) {
        const std::string name = counterName(Counter(i));
        EXPECT_EQ(name, expected[size_t(i)]);
        EXPECT_EQ(kCounters[size_t(i)].counter, Counter(i));
        EXPECT_TRUE(std::all_of(name.begin(), name.end(), [](char c) {
            return std::islower(c) || c == '_';
        })) << name;
        EXPECT_GT(std::string(counterMeaning(Counter(i))).size(), 10u) << name;
        seen.insert(name);
    }
    EXPECT_EQ(int(seen.size()), kCounterCount);
}

TEST(Counters, StatsRecordWhichWereReported) {
    CullStats stats;
    EXPECT_FALSE(stats.has(Counter::PixelQueries));
    stats.set(Counter::PixelQueries, 3);
    stats.add(Counter::PixelQueries, 4);
    stats.add(Counter::CellUpdates, 0);
    EXPECT_TRUE(stats.has(Counter::PixelQueries));
    EXPECT_TRUE(stats.has(Counter::CellUpdates));
    EXPECT_FALSE(stats.has(Counter::OcclusionTests));
    EXPECT_EQ(stats.get(Counter::PixelQueries), 7);
}

}  // namespace
}  // namespace gridcull
