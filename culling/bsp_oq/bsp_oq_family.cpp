#include "culling/bsp_oq/bsp_oq_family.h"

#include <memory>

#include "culling/bsp_oq/bsp_oq_culler.h"
#include "culling/bsp_oq/bsp_oq_options.h"
#include "culling/raster/id_depth_buffer.h"

namespace gridcull {

const KnobTable<BspOqOptions>& bspOqKnobs() {
    static const KnobTable<BspOqOptions> table{
        swept(derivedKnob(
                  "bsp-res", &BspOqOptions::resolution, kMinBspResolution, kMaxImageResolution,
                  "oracle", "the --oracle-res value",
                  "pixels on the long side of the image the culler draws and queries; another "
                  "value than the oracle's samples other pixel centres, so an object the "
                  "oracle sees through a gap may be dropped"),
              {256, 512, 1024, 2048}),
        swept(knob("bsp-leaf-triangles", &BspOqOptions::leaf_triangles, 1, 1 << 20,
                   "triangles an object's BSP leaf may hold (a mesh with no more gets no tree); "
                   "smaller: more parts, each culled on its own, more queries and split triangles"),
              {64, 256, 1024}),
        swept(knob("bsp-node-objects", &BspOqOptions::node_objects, 1, 1 << 20,
                   "objects a scene-tree node may hold before it is split; smaller: a deeper tree, "
                   "more nodes to query"),
              {1, 4, 16}),
        swept(
            knob(
                "bsp-rebuild-delay", &BspOqOptions::rebuild_delay, -1, kMaxBspDelayFrames,
                "frames before a scene-tree node that moving objects made too full or too empty is "
                "rebuilt (the lazy reconstruction); -1: never"),
            {-1, 0, 8, 32}),
        readBy(
            swept(
                knob("bsp-history", &BspOqOptions::history, 0, kMaxBspHistory,
                     "bsp-oq: after a visible answer, a node's query is skipped for as many frames "
                     "as "
                     "there were visible answers among its last N queries; 0: a query every frame"),
                {0, 4, 8, 16}),
            {"bsp-oq"}),
        readBy(
            swept(
                knob(
                    "bsp-skip-spread", &BspOqOptions::skip_spread, 0, 1,
                    "bsp-oq: 1 lengthens each skip by a pseudo-random 0 to half of itself, so that "
                    "nodes seen together are not all queried again in one frame (a stall); 0: the "
                    "count of visible answers alone"),
                {0, 1}),
            {"bsp-oq"}),
        readBy(swept(knob("bsp-batch", &BspOqOptions::batch, 1, kMaxBspBatch,
                          "bsp-oq: queries issued at once (non-overlapping screen rectangles) "
                          "before their "
                          "answers are read; 1: one at a time"),
                     {1, 16, 64, 256}),
               {"bsp-oq"}),
        readBy(
            swept(
                knob(
                    "bsp-shrink-delay", &BspOqOptions::shrink_delay, -1, kMaxBspDelayFrames,
                    "bsp-oq: frames a scene node's contents must stay unchanged before it is "
                    "queried "
                    "on its objects' box instead of its cell; -1: never shrink (object parts too)"),
                {-1, 0, 4, 16}),
            {"bsp-oq"}),
    };
    return table;
}

FamilyEntry bspOqFamily() {
    FamilyEntry family;
    family.id = "bsp";
    family.title = "BSP trees with occlusion queries (Kovalčík & Sochor)";
    family.algorithms = {
        {"bsp-oq", kRuns3d,
         "scene and object BSP trees, occlusion queries batched and skipped by temporal "
         "coherence, shrunk query boxes (the paper's Full)"},
        {"bsp-oq-simple", kRuns3d,
         "the same trees, one occlusion query for every node in the frustum (Simple OC)"},
        {"bsp-vfc", kRuns3d, "the same trees, frustum culling only (VFC only)"},
    };
    family.knobs = bspOqKnobs().knobs();
    family.draws_image = true;
    family.make = [](CullerRequest& request) -> std::unique_ptr<Culler> {
        const BspOqOptions options = bspOqKnobs().read(*request.knobs);
        BspOqMode mode;
        if (request.algorithm == "bsp-oq")
            mode = BspOqMode::Full;
        else if (request.algorithm == "bsp-oq-simple")
            mode = BspOqMode::Simple;
        else if (request.algorithm == "bsp-vfc")
            mode = BspOqMode::Vfc;
        else
            return nullptr;
        return std::make_unique<BspOqCuller>(
            request.name, mode, options, request.reference_resolution, std::move(request.target));
    };
    return family;
}

}  // namespace gridcull
