#include "culling/api/cull_stats.h"

namespace gridcull {

const char* counterName(Counter counter) {
    // The names of shared/spec/cli.md; JSON and CSV output depend on them verbatim.
    switch (counter) {
        case Counter::VoxelsVisited:
            return "voxels_visited";
        case Counter::TbvCreated:
            return "tbv_created";
        case Counter::TbvExpired:
            return "tbv_expired";
        case Counter::TbvRevealed:
            return "tbv_revealed";
        case Counter::ObjectUpdates:
            return "object_updates";
        case Counter::UpdateMessages:
            return "update_messages";
        case Counter::PixelQueries:
            return "pixel_queries";
        case Counter::OcclusionQueries:
            return "occlusion_queries";
        case Counter::NodesVisited:
            return "nodes_visited";
        case Counter::TrianglesDrawn:
            return "triangles_drawn";
        case Counter::ObjectsTested:
            return "objects_tested";
        case Counter::PixelsSampled:
            return "pixels_sampled";
        case Counter::OcclusionTests:
            return "occlusion_tests";
        case Counter::PixelsRead:
            return "pixels_read";
        case Counter::CellUpdates:
            return "cell_updates";
        case Counter::BvhRebuilds:
            return "bvh_rebuilds";
        case Counter::ProbabilitySkips:
            return "probability_skips";
        case Counter::Count:
            break;
    }
    return "unknown";
}

}  // namespace gridcull
