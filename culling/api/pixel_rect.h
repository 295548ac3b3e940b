// A rectangle of an image's pixels, as the image-space algorithms, their image
// targets and the window's overlays name them: pixel (px, py) from the top-left,
// its centre at continuous coordinates (px + 0.5, py + 0.5).
#pragma once
#include <algorithm>

namespace gridcull {

// Inclusive pixel rectangle [x0, x1] x [y0, y1]; empty when x0 > x1 or y0 > y1.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    bool empty() const { return x0 > x1 || y0 > y1; }
    long long area() const { return empty() ? 0 : (long long)(x1 - x0 + 1) * (y1 - y0 + 1); }
    bool contains(const PixelRect& r) const {
        return r.x0 >= x0 && r.x1 <= x1 && r.y0 >= y0 && r.y1 <= y1;
    }
    PixelRect intersect(const PixelRect& r) const {
        return {std::max(x0, r.x0), std::max(y0, r.y0), std::min(x1, r.x1), std::min(y1, r.y1)};
    }
};

}  // namespace gridcull
