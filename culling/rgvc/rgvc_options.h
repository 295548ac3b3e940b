// Regular-grid culling's knobs (culling/rgvc/rgvc_culler.h).
#pragma once
#include "culling/api/knobs.h"

namespace gridcull {

// A TBV valid for less than a millisecond or longer than a day means nothing in
// a scene of frames; 8192 is the 2D grid budget's side.
constexpr double kMinRgvcValidity = 0.001;
constexpr double kMaxRgvcValidity = 86400.0;
constexpr int kMaxRgvcGridResolution = 8192;

struct RgvcOptions {
    // Validity period of a temporal bounding volume, seconds (> 0); with
    // adaptive validity the first period of each object.
    double validity_s = 0.5;
    // 1: adaptive validity periods (Sudarsky & Gotsman, s3.4: doubled after an
    // expiry, halved after a reveal); 0: every TBV gets validity_s.
    int adaptive_validity = 1;
    // Voxels along the world's longest axis, the other axis in proportion;
    // 0 keeps the scene's grid.resolution.
    int grid_resolution = 0;
    // 2D occluder extension (s4.3, culling/rgvc/rgvc_occlusion.h): 0, the convex
    // L; 1, the staircase (step 3 always runs). An RgvcExtension value. 0 by
    // default: on the 2D scenes of scenes/ (gridcull bench) the staircase shrank
    // the PVS by 1% at most (none on hidden-movers-2d) for -1% to +4% cull time
    // (medians of paired runs per scene); both are conservative.
    int extension = 0;
};

const KnobTable<RgvcOptions>& rgvcKnobs();

}  // namespace gridcull
