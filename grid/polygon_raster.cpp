#include "grid/polygon_raster.h"

#include <array>

namespace gridcull {

bool convexRegionRows(const HalfPlane2* planes, int count, int x_lo, int x_hi, int y_lo, int y_hi,
                      int& row_lo, int& row_hi) {
    row_lo = y_lo;
    row_hi = y_hi;
    constexpr int kMaxPlanes = 12;
    if (count > kMaxPlanes) return true;
    // Sutherland-Hodgman on the box; each plane adds at most one corner.
    std::array<double, 2 * (4 + kMaxPlanes)> a, b;
    int n = 4;
    a = {double(x_lo), double(y_lo), double(x_hi), double(y_lo),
         double(x_hi), double(y_hi), double(x_lo), double(y_hi)};
    for (int i = 0; i < count && n > 0; ++i) {
        const HalfPlane2& p = planes[i];
        int m = 0;
        for (int j = 0; j < n; ++j) {
            const int k = (j + 1) % n;
            const double ax = a[size_t(2 * j)], ay = a[size_t(2 * j + 1)];
            const double bx = a[size_t(2 * k)], by = a[size_t(2 * k + 1)];
            const double da = p.eval(ax, ay), db = p.eval(bx, by);
            if (da >= 0.0) b[size_t(2 * m)] = ax, b[size_t(2 * m + 1)] = ay, ++m;
            if ((da >= 0.0) != (db >= 0.0)) {
                const double f = da / (da - db);
                b[size_t(2 * m)] = ax + (bx - ax) * f, b[size_t(2 * m + 1)] = ay + (by - ay) * f, ++m;
            }
        }
        n = m;
        a = b;
    }
    if (n == 0) return false;
    double lo = a[1], hi = a[1];
    for (int j = 1; j < n; ++j) lo = std::min(lo, a[size_t(2 * j + 1)]), hi = std::max(hi, a[size_t(2 * j + 1)]);
    row_lo = std::max(y_lo, int(std::floor(lo)) - 1);
    row_hi = std::min(y_hi, int(std::ceil(hi)) + 1);
    return row_lo <= row_hi;
}

}  // namespace gridcull
