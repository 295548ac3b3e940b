#include "grid/polygon_triangulate.h"
#include "grid/polygon_area.h"

#include <algorithm>
#include <cmath>

namespace gridcull {

namespace {

double cross2(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Closed triangle test for a counter-clockwise triangle abc. Points on an edge
// count as inside: a vertex touching a candidate ear's edge makes clipping it
// unsafe for polygons that touch themselves at a point.
bool inTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                const glm::dvec3& c, double eps) {
    return cross2(a, b, p) >= -eps && cross2(b, c, p) >= -eps && cross2(c, a, p) >= -eps;
}

bool samePoint(const glm::dvec3& a, const glm::dvec3& b) { return a.x == b.x && a.y == b.y; }


}  // namespace

bool triangulatePolygon(const std::vector<glm::dvec3>& points, std::vector<uint32_t>& triangles) {
    triangles.clear();
    const double area2 = signedDoubleArea(points);
    if (points.size() < 3 || !(std::abs(area2) > 0.0) || !std::isfinite(area2)) return false;

    // The remaining outline as indices, counter-clockwise, without repeated points.
    std::vector<uint32_t> ring;
    ring.reserve(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        if (!ring.empty() && samePoint(points[ring.back()], points[i])) continue;
        ring.push_back(uint32_t(i));
    }
    while (ring.size() > 1 && samePoint(points[ring.front()], points[ring.back()])) ring.pop_back();
    if (ring.size() < 3) return false;
    if (area2 < 0.0) std::reverse(ring.begin(), ring.end());

    // Tolerances scale with the polygon's size so that huge and tiny polygons behave alike.
    double extent = 0.0;
    for (uint32_t i : ring)
        extent = std::max({extent, std::abs(points[i].x), std::abs(points[i].y)});
    const double eps = 1e-12 * std::max(1.0, extent * extent);

    size_t misses = 0;  // consecutive vertices that were not ears
    size_t i = 0;
    while (ring.size() > 3) {
        const size_t n = ring.size();
        const size_t ip = (i + n - 1) % n;
        const size_t in = (i + 1) % n;
        const glm::dvec3& a = points[ring[ip]];
        const glm::dvec3& b = points[ring[i]];
        const glm::dvec3& c = points[ring[in]];
        const double turn = cross2(a, b, c);
        bool remove = false;
        bool emit = false;
        if (std::abs(turn) <= eps) {
            // Collinear (or a zero-width spike): dropping b loses no area.
            remove = true;
        } else if (turn > 0.0) {
            bool blocked = false;
            for (size_t k = 0; k < n && !blocked; ++k) {
                if (k == ip || k == i || k == in) continue;
                const glm::dvec3& p = points[ring[k]];
                if (samePoint(p, a) || samePoint(p, b) || samePoint(p, c)) continue;
                blocked = inTriangle(p, a, b, c, eps);
            }
            remove = emit = !blocked;
        }
        if (remove) {
            if (emit) {
                triangles.push_back(ring[ip]);
                triangles.push_back(ring[i]);
                triangles.push_back(ring[in]);
            }
            ring.erase(ring.begin() + std::ptrdiff_t(i));
            if (i >= ring.size()) i = 0;
            // Step back so the previous vertex, whose neighbour changed, is re-tested.
            i = (i + ring.size() - 1) % ring.size();
            misses = 0;
        } else {
            i = (i + 1) % n;
            if (++misses > n) return false;  // no ear left: the outline crosses itself
        }
    }
    if (cross2(points[ring[0]], points[ring[1]], points[ring[2]]) > eps) {
        triangles.insert(triangles.end(), ring.begin(), ring.end());
    }
    return true;
}

}  // namespace gridcull
