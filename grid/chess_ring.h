// Chess rings: the voxels at one chess distance from a centre voxel, the layers
// of Batagelo & Wu's view-frustum traversal (section 4.2). The chess distance
// between voxels (x1, y1) and (x2, y2) is max(|x2 - x1|, |y2 - y1|).
//
// Ring k around (0, 0) is the square loop of 8k voxels (one voxel for k = 0).
// Its voxels are numbered counter-clockwise by a perimeter index p in [0, 8k),
// starting at the corner (k, -k):
//   side 0, x =  k: y from -k up to k - 1      p = y + k
//   side 1, y =  k: x from  k down to -k + 1   p = 2k + (k - x)
//   side 2, x = -k: y from  k down to -k + 1   p = 4k + (k - y)
//   side 3, y = -k: x from -k up to k - 1      p = 6k + (x + k)
// Stepping p by +1 or -1 is exactly a step in one of the two directions the
// paper's six rules give (chessRingDirections). Offsets are 64-bit because a
// viewer far outside the grid gives huge rings.
#pragma once
#include <cstdint>

#include <glm/vec2.hpp>

namespace gridcull {

inline int64_t chessDistance(glm::i64vec2 offset) {
    const int64_t ax = offset.x < 0 ? -offset.x : offset.x;
    const int64_t ay = offset.y < 0 ? -offset.y : offset.y;
    return ax > ay ? ax : ay;
}

// Voxels in ring k: 8k, or 1 for k = 0.
inline int64_t ringSize(int64_t k) { return k == 0 ? 1 : 8 * k; }

// The offset of perimeter index p (taken modulo ringSize(k)) of ring k >= 0.
glm::i64vec2 ringOffset(int64_t k, int64_t p);

// The perimeter index of `offset`, which must lie on ring k = chessDistance(offset).
int64_t ringIndex(glm::i64vec2 offset);

// The paper's six rules (section 4.2): the two directions in which the traversal
// leaves a voxel at `offset` (chess distance >= 1) to stay on its ring.
//  (1) +y and -y if |x| > |y|;  (2) +x and -x if |y| > |x|;
//  (3) -x and -y if x = y > 0;  (4) +x and +y if x = y < 0;
//  (5) +x and -y if -x = y > 0; (6) -x and +y if x = -y > 0.
// `ccw` is the one towards perimeter index p + 1, `cw` towards p - 1.
void chessRingDirections(glm::i64vec2 offset, glm::i64vec2& ccw, glm::i64vec2& cw);

}  // namespace gridcull
