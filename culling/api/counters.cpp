#include "culling/api/counters.h"

namespace gridcull {

namespace {

constexpr std::array<CounterInfo, kCounterCount> kTable = {{
    {Counter::VoxelsVisited, "voxels_visited",
     "grid voxels the traversal reached in the view, occluded or not"},
    {Counter::TbvCreated, "tbv_created",
     "temporal bounding volumes made for hidden moving objects"},
    {Counter::TbvExpired, "tbv_expired",
     "temporal bounding volumes whose validity ran out (the object is looked at again, or given "
     "its next TBV at once)"},
    {Counter::TbvRevealed, "tbv_revealed",
     "temporal bounding volumes found visible before they expired"},
    {Counter::ObjectUpdates, "object_updates",
     "moving objects written into the culler's spatial structure this frame"},
    {Counter::PixelQueries, "pixel_queries",
     "reads of pixels from the culler's image (a read-back each on a GPU), to decide an "
     "occlusion test or to refresh cells after a draw"},
    {Counter::NodesVisited, "nodes_visited",
     "hierarchy nodes the traversal took up, frustum-culled ones included"},
    {Counter::TrianglesDrawn, "triangles_drawn",
     "triangles of the objects the culler drew into its own image"},
    {Counter::ObjectsTested, "objects_tested",
     "objects examined one by one this frame (against the frustum, or drawn by the oracle: "
     "those it rejects whole by depth or screen bounds are not)"},
    {Counter::PixelsSampled, "pixels_sampled", "pixels (3D) or rays (2D) the oracle evaluated"},
    {Counter::OcclusionTests, "occlusion_tests",
     "bounding volumes tested for occlusion against the culler's image"},
    {Counter::PixelsRead, "pixels_read", "pixels read by the pixel queries"},
    {Counter::CellUpdates, "cell_updates",
     "pixel queries that read a whole grid cell to refresh its state"},
    {Counter::BvhRebuilds, "bvh_rebuilds",
     "bounding volume hierarchies rebuilt from scratch instead of refitted"},
    {Counter::ProbabilitySkips, "probability_skips",
     "pixel queries saved by rating a cell free from how little was drawn into it"},
    {Counter::StateFetches, "state_fetches",
     "moving objects whose current position was needed this frame (one update message each "
     "in a distributed virtual environment)"},
    {Counter::TbvMessages, "tbv_messages",
     "temporal bounding volumes requested from the objects' controllers (one message each)"},
    {Counter::OctreeUpdateNodes, "octree_update_nodes",
     "octree nodes read, made or freed while moving objects and TBVs in the octree (the "
     "work the update under the least common ancestor saves)"},
    {Counter::OcclusionQueries, "occlusion_queries",
     "occlusion queries issued to the image (GL_ANY_SAMPLES_PASSED on a GPU): a box drawn "
     "against the depth so far, its answer read later"},
    {Counter::QueryBatches, "query_batches",
     "batches of occlusion queries issued before their answers were read (boxes whose "
     "screen rectangles do not overlap)"},
    {Counter::CoherenceSkips, "coherence_skips",
     "nodes assumed visible without a query because they were visible recently (temporal "
     "coherence)"},
    {Counter::PartsDrawn, "parts_drawn",
     "object parts drawn: whole objects, and leaves of objects' own BSP trees"},
    {Counter::QueriesHidden, "queries_hidden",
     "occlusion queries answered hidden (the ones that culled something; the others cost "
     "a query and saved nothing)"},
    {Counter::SubSampleCandidates, "sub_sample_candidates",
     "objects no pixel centre saw whose bounds reach a pixel not proven covered in front of "
     "them: the oracle casts finer rays there"},
    {Counter::SubSampleVisible, "sub_sample_visible",
     "objects the oracle's finer rays saw and no pixel centre did: visible between centres"},
    {Counter::SubSampleUndecided, "sub_sample_undecided",
     "candidates no finer ray saw: the oracle cannot tell whether they show below its "
     "finest rays (neither visible nor hidden)"},
    {Counter::RefineRays, "refine_rays", "finer rays the oracle cast (Embree)"},
}};

constexpr bool inCounterOrder() {
    for (size_t i = 0; i < kTable.size(); ++i)
        if (kTable[i].counter != Counter(i) || !kTable[i].name || !kTable[i].meaning) return false;
    return true;
}
// A counter added to the enum needs its row here, in the same place.
static_assert(inCounterOrder(), "kCounters must list every Counter once, in enum order");

}  // namespace

const std::array<CounterInfo, kCounterCount> kCounters = kTable;

}  // namespace gridcull
