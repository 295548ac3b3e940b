// The knobs of octree + hierarchical z-buffer culling with temporal bounding
// volumes (Sudarsky & Gotsman; culling/hzb_tbv/hzb_tbv_culler.h).
#pragma once
#include "culling/api/knobs.h"

namespace gridcull {

// The octree's depth bound: 2^12 cells a side are finer than any pixel of the
// largest image (kMaxImageResolution) sees in a world of any size we load.
constexpr int kMaxHzbOctreeDepth = 12;
constexpr int kMinHzbResolution = 16;
// Under a millisecond or over a day means nothing in a scene of frames.
constexpr double kMinHzbValidity = 0.001;
constexpr double kMaxHzbValidity = 86400.0;

// Texels one Z query may read as it descends the pyramid (Greene's refinement):
// enough to settle a box at the edge of an occluder, few enough that a query
// never costs more than a small draw.
constexpr int kHzbQueryReads = 64;

enum class HzbTbvShapeChoice { Sphere = 0, Box = 1, Swept = 2 };

struct HzbTbvOptions {
    // Pixels on the long side of the software z-buffer and its Z-pyramid; 0
    // follows the oracle's resolution, so that false culls compare like with like.
    int resolution = 0;
    // Validity period of a TBV, seconds (> 0): every object's first period when
    // adaptive, every period when not.
    double validity_s = 1.0;
    // 1: adaptive periods (section 3.4: doubled after an expiry, halved after a
    // reveal); 0: fixed at validity_s.
    int adaptive_validity = 1;
    // The TBV's shape (section 3.2), an HzbTbvShapeChoice: 0 a sphere from the
    // maximum speed, 1 the object's box grown by it, 2 the swept box of a
    // keyframed path (objects on other motions get a sphere).
    int tbv_shape = 0;
    // Fig. 14: this fraction of the valid TBVs is dropped each frame, as if their
    // objects had broken a fuzzy TBV's motion bound (0: off).
    double invalidate_fraction = 0.0;
    // The octree's maximum depth (the root is 0).
    int octree_depth = 8;
    // How an entry moves in the octree: 0 under the least common ancestor of
    // its old and new boxes (section 4, Fig. 9); 1 deleted from the root and
    // inserted from the root (Fig. 5), the paper's comparison.
    int octree_update_from_root = 0;
};

const KnobTable<HzbTbvOptions>& hzbTbvKnobs();

}  // namespace gridcull
