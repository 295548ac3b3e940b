// Bresenham's digital line in 3D on voxel indices: the 3D counterpart of
// BresenhamLine (grid/bresenham.h).
//
// Batagelo & Wu's 3D view-frustum traversal (section 5.2) "starts at the
// seed-voxels of the line-of-sight discretized by a 3D Bresenham's algorithm",
// one seed voxel per chess layer; this line gives them. Integer arithmetic
// throughout, no allocation.
#pragma once
#include <cstdint>

#include <glm/vec3.hpp>

namespace gridcull {

// The 26-connected Bresenham line from (0, 0, 0) towards the integer offset
// `delta`, extended past it without end. Its k-th voxel lies at chess distance
// (max of |x|, |y|, |z|) exactly k from the start: the dominant axis advances by
// one per step and each other axis by its slope against the dominant one,
// rounded to the nearest integer (halves round to the larger magnitude), so
// there is one voxel per chess layer. The dominant axis is the one of largest
// |delta| component, x before y before z on ties. This is BresenhamLine's rule
// per axis, so with delta.z == 0 the two lines agree voxel for voxel.
class BresenhamLine3 {
public:
    // delta == (0, 0, 0) is taken as (1, 0, 0). Precondition: every component
    // of delta has magnitude at most kMaxComponent, which keeps at() free of
    // overflow for every k >= 0.
    explicit BresenhamLine3(glm::i64vec3 delta);
    // The line towards a real direction (x, y, z), not all zero: the direction
    // is scaled so that its largest component becomes +-2^24 and the others are
    // rounded to integers, which keeps each slope to 24 bits (an error of at
    // most 2^-25 voxels per step). A zero or non-finite direction gives the line
    // towards (1, 0, 0).
    static BresenhamLine3 towards(double x, double y, double z);

    // Offset of the k-th voxel (k >= 0) from the start; chess distance k.
    glm::i64vec3 at(int64_t k) const;
    glm::i64vec3 delta() const { return delta_; }

    static constexpr int64_t kMaxComponent = (int64_t(1) << 31) - 1;

private:
    glm::i64vec3 delta_;
};

}  // namespace gridcull
