// Bresenham's digital line and a 4-connected Bresenham circle on voxel indices.
//
// Batagelo & Wu use the line to find the seed voxels of the view-frustum
// traversal (section 4.2: the line of sight discretized from the viewer's voxel,
// one voxel per chess layer) and the circle to write a TBV's boundary into the
// TBV matrix (section 4.1: "a modification of Bresenham's circle algorithm for
// 4-connected curves"). Integer arithmetic throughout, no allocation.
#pragma once
#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include <glm/vec2.hpp>

namespace gridcull {

// The 8-connected Bresenham line from (0, 0) towards the integer offset `delta`,
// extended past it without end. Its k-th voxel lies at chess distance exactly k
// from (0, 0): the dominant axis advances by one per step and the other by the
// slope rounded to the nearest integer (halves round to the larger magnitude),
// so there is one voxel per chess layer.
class BresenhamLine {
public:
    // delta == (0, 0) is taken as (1, 0).
    explicit BresenhamLine(glm::i64vec2 delta);
    // The line towards a real direction (x, y): the direction is scaled to
    // integers of about 2^24 so the slope is kept to 24 bits, whatever its
    // magnitude (subnormal to DBL_MAX); a zero, infinite or NaN component gives +x.
    static BresenhamLine towards(double x, double y);

    // Offset of the k-th voxel (k >= 0) from the start.
    glm::i64vec2 at(int64_t k) const;
    glm::i64vec2 delta() const { return delta_; }

private:
    glm::i64vec2 delta_;
};

// Calls visit(x, y) for each voxel of the 8-connected Bresenham line from a to b,
// both ends included, |b - a|_inf + 1 voxels in order from a.
template <typename Visit>
void bresenhamSegment(glm::i64vec2 a, glm::i64vec2 b, Visit&& visit) {
    const BresenhamLine line(b - a);
    const int64_t steps = std::max(std::llabs(b.x - a.x), std::llabs(b.y - a.y));
    for (int64_t k = 0; k <= steps; ++k) {
        const glm::i64vec2 p = a + line.at(k);
        visit(p.x, p.y);
    }
}

// Calls visit(x, y) once for each voxel of the 4-connected digital circle of
// integer radius r >= 0 around (0, 0): 8r voxels (one voxel for r = 0), in
// counter-clockwise order starting at (r, 0). Consecutive voxels (and the last
// and the first) share an edge. Each step goes to the one of the two candidate
// voxels (towards the next quadrant) whose centre's x^2 + y^2 is nearer r^2, so
// every voxel satisfies (r - 1)^2 < x^2 + y^2 <= (r + 1)^2.
template <typename Visit>
void bresenhamCircle4(int r, Visit&& visit) {
    if (r <= 0) {
        visit(int64_t(0), int64_t(0));
        return;
    }
    // Trace the first quadrant from (r, 0) to (0, r), then rotate it by 90 degree
    // steps; each quadrant omits its last voxel, the next one's first.
    for (int quadrant = 0; quadrant < 4; ++quadrant) {
        int64_t x = r, y = 0;
        const int64_t rr = int64_t(r) * r;
        while (!(x == 0 && y == r)) {
            // (x, y) rotated quadrant times by 90 degrees counter-clockwise.
            switch (quadrant) {
                case 0:
                    visit(x, y);
                    break;
                case 1:
                    visit(-y, x);
                    break;
                case 2:
                    visit(-x, -y);
                    break;
                default:
                    visit(y, -x);
                    break;
            }
            if (x == 0) {
                ++y;
            } else if (y == r) {
                --x;
            } else {
                const int64_t up = std::llabs(x * x + (y + 1) * (y + 1) - rr);
                const int64_t left = std::llabs((x - 1) * (x - 1) + y * y - rr);
                if (up <= left)
                    ++y;
                else
                    --x;
            }
        }
    }
}

}  // namespace gridcull
