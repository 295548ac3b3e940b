#include "grid/bresenham.h"

#include <algorithm>
#include <cmath>

namespace gridcull {

namespace {

// floor(a / b) for b > 0.
int64_t floorDiv(int64_t a, int64_t b) {
    const int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

}  // namespace

BresenhamLine::BresenhamLine(glm::i64vec2 delta) : delta_(delta) {
    if (delta_.x == 0 && delta_.y == 0) delta_ = {1, 0};
}

BresenhamLine BresenhamLine::towards(double x, double y) {
    // A NaN in either component (std::max would drop it) or an infinite one has
    // no direction to keep: +x, like the zero direction.
    if (!std::isfinite(x) || !std::isfinite(y)) return BresenhamLine({1, 0});
    const double m = std::max(std::abs(x), std::abs(y));
    if (!(m > 0.0)) return BresenhamLine({1, 0});
    // Divide first, then scale: x / m is in [-1, 1] even for subnormal m, where
    // 2^24 / m would overflow to infinity (as BresenhamLine3::towards).
    const double scale = double(1 << 24);
    return BresenhamLine(
        {int64_t(std::llround(x / m * scale)), int64_t(std::llround(y / m * scale))});
}

glm::i64vec2 BresenhamLine::at(int64_t k) const {
    const int64_t ax = std::llabs(delta_.x), ay = std::llabs(delta_.y);
    const int64_t sx = delta_.x < 0 ? -1 : 1, sy = delta_.y < 0 ? -1 : 1;
    // The minor coordinate is round(k * minor / major), ties up, as Bresenham's
    // error term gives it; k * minor stays below 2^63 for k < 2^38.
    if (ax >= ay) return {sx * k, sy * floorDiv(2 * k * ay + ax, 2 * ax)};
    return {sx * floorDiv(2 * k * ax + ay, 2 * ay), sy * k};
}

}  // namespace gridcull
