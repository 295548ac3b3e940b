#include "culling/rgvc/rgvc_family.h"

#include "culling/rgvc/rgvc_culler.h"
#include "culling/rgvc/rgvc_options.h"

namespace gridcull {

const KnobTable<RgvcOptions>& rgvcKnobs() {
    static const KnobTable<RgvcOptions> table{
        swept(knob("rgvc-validity", &RgvcOptions::validity_s, kMinRgvcValidity, kMaxRgvcValidity,
                   "seconds a TBV stays valid (the first period when adaptive); shorter: fewer "
                   "TBVs revealed but more object updates"),
              {0.125, 0.25, 0.5, 1, 2}),
        swept(knob("rgvc-adaptive", &RgvcOptions::adaptive_validity, 0, 1,
                   "1: each object's TBV validity adapts (doubled after an expiry, halved after a "
                   "reveal); 0: fixed at --rgvc-validity"),
              {0, 1}),
        swept(derivedKnob("rgvc-grid-res", &RgvcOptions::grid_resolution, 1, kMaxRgvcGridResolution,
                          "scene", "the scene's grid.resolution",
                          "voxels along the world's longest axis; finer: more voxels to traverse, "
                          "tighter occlusion"),
              {32, 64, 128, 256}),
        swept(
            knob("rgvc-extension", &RgvcOptions::extension, 0, 1,
                 "2D occluder extension: 0, the convex L (step 3 only when step 1 added nothing); "
                 "1, the staircase (step 3 always, following concave occluders; up to 4 occlusion "
                 "polygons an occluder instead of 2)"),
            {0, 1}),
    };
    return table;
}

FamilyEntry rgvcFamily() {
    FamilyEntry family;
    family.id = "rgvc";
    family.title = "Regular-grid culling (Batagelo & Wu)";
    family.algorithms = {
        {"rgvc", kRuns2d | kRuns3d, "regular-grid culling with temporal bounding volumes"}};
    family.knobs = rgvcKnobs().knobs();
    family.make = [](CullerRequest& request) -> std::unique_ptr<Culler> {
        return std::make_unique<RgvcCuller>(rgvcKnobs().read(*request.knobs));
    };
    return family;
}

}  // namespace gridcull
