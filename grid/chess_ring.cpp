#include "grid/chess_ring.h"

#include <cassert>

namespace gridcull {

glm::i64vec2 ringOffset(int64_t k, int64_t p) {
    assert(k >= 0);
    if (k == 0) return {0, 0};
    const int64_t n = 8 * k;
    p %= n;
    if (p < 0) p += n;
    const int64_t side = p / (2 * k), along = p % (2 * k);
    switch (side) {
    case 0: return {k, along - k};
    case 1: return {k - along, k};
    case 2: return {-k, k - along};
    default: return {along - k, -k};
    }
}

int64_t ringIndex(glm::i64vec2 offset) {
    const int64_t k = chessDistance(offset);
    if (k == 0) return 0;
    const int64_t x = offset.x, y = offset.y;
    // Corners belong to the side that starts at them: (k,-k) side 0, (k,k) side 1,
    // (-k,k) side 2, (-k,-k) side 3.
    if (x == k && y < k) return y + k;
    if (y == k && x > -k) return 2 * k + (k - x);
    if (x == -k && y > -k) return 4 * k + (k - y);
    assert(y == -k);
    return 6 * k + (x + k);
}

void chessRingDirections(glm::i64vec2 offset, glm::i64vec2& ccw, glm::i64vec2& cw) {
    const int64_t x = offset.x, y = offset.y;
    const int64_t ax = x < 0 ? -x : x, ay = y < 0 ? -y : y;
    assert(ax > 0 || ay > 0);
    if (ax > ay) {  // rule 1: the right (x > 0) or left side
        ccw = {0, x > 0 ? 1 : -1};
    } else if (ay > ax) {  // rule 2: the top (y > 0) or bottom side
        ccw = {y > 0 ? -1 : 1, 0};
    } else if (x > 0 && y > 0) {  // rule 3
        ccw = {-1, 0};
    } else if (x < 0 && y < 0) {  // rule 4
        ccw = {1, 0};
    } else if (x < 0) {  // rule 5: top-left corner
        ccw = {0, -1};
    } else {  // rule 6: bottom-right corner
        ccw = {0, 1};
    }
    // The other direction of the same rule.
    if (ax != ay) {
        cw = -ccw;
    } else if (x > 0 && y > 0) {
        cw = {0, -1};
    } else if (x < 0 && y < 0) {
        cw = {0, 1};
    } else if (x < 0) {
        cw = {1, 0};
    } else {
        cw = {-1, 0};
    }
}

}  // namespace gridcull
