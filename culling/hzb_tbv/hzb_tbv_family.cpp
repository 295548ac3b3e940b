#include "culling/hzb_tbv/hzb_tbv_family.h"

#include <memory>

#include "culling/hzb_tbv/hzb_tbv_culler.h"
#include "culling/hzb_tbv/hzb_tbv_options.h"
#include "culling/raster/id_depth_buffer.h"

namespace gridcull {

const KnobTable<HzbTbvOptions>& hzbTbvKnobs() {
    static const KnobTable<HzbTbvOptions> table{
        swept(
            derivedKnob("hzb-res", &HzbTbvOptions::resolution, kMinHzbResolution,
                        kMaxImageResolution, "oracle", "the --oracle-res value",
                        "pixels on the long side of the z-buffer and its Z-pyramid; another value "
                        "than the oracle's samples other pixel centres, so an object the oracle "
                        "sees through a gap may be dropped"),
            {256, 512, 1024, 2048}),
        swept(knob("hzb-validity", &HzbTbvOptions::validity_s, kMinHzbValidity, kMaxHzbValidity,
                   "seconds a TBV stays valid (the first period when adaptive); longer: fewer "
                   "expiries, bigger TBVs revealed sooner"),
              {0.25, 0.5, 1, 2, 4}),
        swept(knob("hzb-adaptive", &HzbTbvOptions::adaptive_validity, 0, 1,
                   "1: each object's TBV validity adapts (doubled after an expiry, halved after a "
                   "reveal); 0: fixed at --hzb-validity"),
              {0, 1}),
        swept(knob("hzb-tbv-shape", &HzbTbvOptions::tbv_shape, 0, 2,
                   "0: spheres from the maximum speed; 1: the object's box grown by it; 2: the "
                   "swept box of a keyframed path (others get spheres)"),
              {0, 1, 2}),
        swept(
            knob("hzb-invalidate", &HzbTbvOptions::invalidate_fraction, 0.0, 1.0,
                 "fraction of the valid TBVs dropped each frame, as fuzzy TBVs whose motion bound "
                 "was broken (the paper's Fig. 14); costs object updates, not correctness"),
            {0, 0.1, 0.5}),
        swept(knob("hzb-octree-depth", &HzbTbvOptions::octree_depth, 0, kMaxHzbOctreeDepth,
                   "the octree's maximum depth; deeper: tighter nodes to test, more nodes to walk"),
              {4, 6, 8, 10}),
        swept(
            knob("hzb-octree-update", &HzbTbvOptions::octree_update_from_root, 0, 1,
                 "0: a moved object or TBV is updated under the least common ancestor of its old "
                 "and new boxes; 1: deleted and reinserted from the root (the paper's comparison; "
                 "same octree, more nodes visited)"),
            {0, 1}),
    };
    return table;
}

FamilyEntry hzbTbvFamily() {
    FamilyEntry family;
    family.id = "hzb";
    family.title = "Octree and hierarchical z-buffer with TBVs (Sudarsky & Gotsman)";
    family.algorithms = {
        {"hzb-tbv", kRuns3d, "octree + hierarchical z-buffer, TBVs, explicit update (TBVe)"},
        {"hzb-tbvi", kRuns3d,
         "the same, implicit update (TBVi): an object coming into view may show a frame late", 1},
        {"hzb", kRuns3d, "octree + hierarchical z-buffer, every moving object updated every frame"},
    };
    family.knobs = hzbTbvKnobs().knobs();
    family.make = [](CullerRequest& request) -> std::unique_ptr<Culler> {
        const HzbTbvOptions options = hzbTbvKnobs().read(*request.knobs);
        if (request.algorithm == "hzb-tbv")
            return std::make_unique<HzbTbvCuller>(request.name, true, TbvUpdateMode::Explicit,
                                                  options, request.reference_resolution);
        if (request.algorithm == "hzb-tbvi")
            return std::make_unique<HzbTbvCuller>(request.name, true, TbvUpdateMode::Implicit,
                                                  options, request.reference_resolution);
        if (request.algorithm == "hzb")
            return std::make_unique<HzbTbvCuller>(request.name, false, TbvUpdateMode::Explicit,
                                                  options, request.reference_resolution);
        return nullptr;
    };
    return family;
}

}  // namespace gridcull
