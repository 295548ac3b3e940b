#include "culling/scene/polygon2d.h"

#include <algorithm>

namespace gridcull {

namespace {

double cross(const glm::dvec3& o, const glm::dvec3& a, const glm::dvec3& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

int sign(double v) {
    return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
}

// p lies on segment [a, b], given that the three are collinear.
bool withinBox(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& p) {
    return p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) && p.y >= std::min(a.y, b.y) &&
           p.y <= std::max(a.y, b.y);
}

// Closed segments [a, b] and [c, d] share at least one point.
bool segmentsTouch(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                   const glm::dvec3& d) {
    const int d1 = sign(cross(c, d, a)), d2 = sign(cross(c, d, b));
    const int d3 = sign(cross(a, b, c)), d4 = sign(cross(a, b, d));
    if (d1 * d2 < 0 && d3 * d4 < 0) return true;
    return (d1 == 0 && withinBox(c, d, a)) || (d2 == 0 && withinBox(c, d, b)) ||
           (d3 == 0 && withinBox(a, b, c)) || (d4 == 0 && withinBox(a, b, d));
}

}  // namespace

std::string checkSimpleCounterClockwise(const std::vector<glm::dvec3>& points) {
    const size_t n = points.size();
    if (n < 3) return "it has " + std::to_string(n) + " points, at least 3 are needed";
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3& p = points[i];
        const glm::dvec3& q = points[(i + 1) % n];
        if (p.x == q.x && p.y == q.y)
            return "points " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                   " are the same";
    }
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3& a = points[i];
        const glm::dvec3& b = points[(i + 1) % n];
        // Neighbouring edges share a corner; they must not fold back along each other.
        const glm::dvec3& c = points[(i + 2) % n];
        if (cross(a, b, c) == 0.0 && ((c.x - b.x) * (a.x - b.x) + (c.y - b.y) * (a.y - b.y)) > 0.0)
            return "edges " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                   " fold back over each other";
        for (size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // the closing edge is a neighbour of edge 0
            if (segmentsTouch(a, b, points[j], points[(j + 1) % n]))
                return "edges " + std::to_string(i) + " and " + std::to_string(j) +
                       " cross or touch";
        }
    }
    const double area = signedDoubleArea(points);
    if (area == 0.0) return "it encloses no area";
    if (area < 0.0) return "its points are in clockwise order";
    return {};
}

}  // namespace gridcull
