#include "grid/conservative_raster.h"

namespace gridcull {

bool segmentMeetsRect(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& lo,
                      const glm::dvec3& hi) {
    double t0 = 0.0, t1 = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
        const double delta = b[axis] - a[axis];
        if (delta == 0.0) {
            if (a[axis] < lo[axis] || a[axis] > hi[axis]) return false;
            continue;
        }
        double ta = (lo[axis] - a[axis]) / delta, tb = (hi[axis] - a[axis]) / delta;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

bool pointInPolygonXY(const glm::dvec3& p, const glm::dvec3* points, size_t count,
                      const glm::dvec3& offset) {
    bool in = false;
    for (size_t i = 0, j = count - 1; i < count; j = i++) {
        const double xi = points[i].x + offset.x, yi = points[i].y + offset.y;
        const double xj = points[j].x + offset.x, yj = points[j].y + offset.y;
        if ((yi > p.y) != (yj > p.y)) {
            const double x_cross = xi + (p.y - yi) * (xj - xi) / (yj - yi);
            if (p.x < x_cross) in = !in;
        }
    }
    return in;
}

void classifyVoxelAgainstPolygon(const glm::dvec3& lo, const glm::dvec3& hi,
                                 const glm::dvec3& voxel, const glm::dvec3* points, size_t count,
                                 const glm::dvec3& offset, bool& touches, bool& inside) {
    // If no edge meets a square, the square lies wholly inside or wholly outside
    // the polygon, and its centre tells which.
    const glm::dvec3 grow{kRasterSlack * voxel.x, kRasterSlack * voxel.y, 0.0};
    const glm::dvec3 shrink{kOpaqueSnap * voxel.x, kOpaqueSnap * voxel.y, 0.0};
    bool meets_grown = false, meets_shrunk = false;
    for (size_t i = 0, j = count - 1; i < count && !meets_shrunk; j = i++) {
        const glm::dvec3 a = points[j] + offset, b = points[i] + offset;
        if (!segmentMeetsRect(a, b, lo - grow, hi + grow)) continue;
        meets_grown = true;
        meets_shrunk = segmentMeetsRect(a, b, lo + shrink, hi - shrink);
    }
    const bool centre_in = pointInPolygonXY((lo + hi) * 0.5, points, count, offset);
    touches = meets_grown || centre_in;
    inside = !meets_shrunk && centre_in;
}

}  // namespace gridcull
