// Pixel-range helpers of the shared rasterizer (id_depth_buffer.h): turning
// continuous pixel coordinates into clamped integer ranges.
#pragma once
#include <algorithm>
#include <cmath>

namespace gridcull {

// Inclusive range [lo, hi] of pixel indices; empty when lo > hi.
struct ScreenRange {
    int lo = 0;
    int hi = -1;
    bool empty() const { return lo > hi; }
};

// The pixels whose continuous index lies in [from, to], widened by up to one pixel
// on each side (floor / ceil) so that rounding in the bound never drops a pixel
// centre, then clamped to [0, count). The caller's per-pixel test decides; this
// only bounds the work. A NaN bound gives the whole range, which stays correct.
inline ScreenRange pixelRange(double from, double to, int count) {
    if (std::isnan(from) || std::isnan(to)) return {0, count - 1};
    // Clamp in double first: a huge coordinate must not overflow the int cast.
    const double lo = std::clamp(std::floor(from), -1.0, double(count));
    const double hi = std::clamp(std::ceil(to), -1.0, double(count));
    ScreenRange range{std::max(0, int(lo)), std::min(count - 1, int(hi))};
    return range;
}

}  // namespace gridcull
