#include "grid/bresenham3d.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>

namespace gridcull {

namespace {

// round(k * minor / major) for 0 <= minor <= major, 0 < major <= 2^31 - 1 and
// k >= 0, halves up, as Bresenham's error term gives it. BresenhamLine forms
// 2 * k * minor directly, which stays below 2^63 only while k * minor < 2^62
// (k < 2^38 for its 2^24 deltas); splitting k = t * major + s keeps every
// product below 2^63 for any k and any delta within kMaxComponent:
// k * minor / major = t * minor + s * minor / major, with s * minor < 2^62.
int64_t minorStep(int64_t k, int64_t minor, int64_t major) {
    const int64_t t = k / major, s = k % major;
    return t * minor + (2 * s * minor + major) / (2 * major);
}

}  // namespace

BresenhamLine3::BresenhamLine3(glm::i64vec3 delta) : delta_(delta) {
    if (delta_.x == 0 && delta_.y == 0 && delta_.z == 0) delta_ = {1, 0, 0};
    for (int i = 0; i < 3; ++i) assert(delta_[i] >= -kMaxComponent && delta_[i] <= kMaxComponent);
}

BresenhamLine3 BresenhamLine3::towards(double x, double y, double z) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
        return BresenhamLine3({1, 0, 0});
    const double m = std::max({std::abs(x), std::abs(y), std::abs(z)});
    if (!(m > 0.0)) return BresenhamLine3({1, 0, 0});
    // Divide first, then scale: x / m is in [-1, 1] even for subnormal m, where
    // 2^24 / m would overflow to infinity.
    const double scale = double(1 << 24);
    return BresenhamLine3({int64_t(std::llround(x / m * scale)),
                           int64_t(std::llround(y / m * scale)),
                           int64_t(std::llround(z / m * scale))});
}

glm::i64vec3 BresenhamLine3::at(int64_t k) const {
    assert(k >= 0);
    const glm::i64vec3 a{std::llabs(delta_.x), std::llabs(delta_.y), std::llabs(delta_.z)};
    const int major = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    glm::i64vec3 p;
    for (int i = 0; i < 3; ++i) {
        const int64_t step = i == major ? k : minorStep(k, a[i], a[major]);
        p[i] = delta_[i] < 0 ? -step : step;
    }
    return p;
}

}  // namespace gridcull
