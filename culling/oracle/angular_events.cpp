#include "culling/oracle/angular_events.h"

#include <algorithm>
#include <cmath>

namespace gridcull {

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

struct Events {
    const AngularFrame& frame;
    double from, to;
    std::vector<double>& out;

    void angle(double a) {
        a = std::fmod(a, kTwoPi);
        if (a < 0.0) a += kTwoPi;
        if (from < a && a < to) out.push_back(a);
    }
    void point(double x, double y) {
        // The camera itself has no direction.
        if (x == frame.origin.x && y == frame.origin.y) return;
        angle(frame.angleOf({x, y, 0.0}));
    }
};

double cross(double ax, double ay, double bx, double by) {
    return ax * by - ay * bx;
}

// Segment [a, b] against segment [c, d]; parallel segments give no point (where
// they overlap their ends are vertex events already).
void segmentSegment(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                    const glm::dvec3& d, Events& ev) {
    const double rx = b.x - a.x, ry = b.y - a.y, sx = d.x - c.x, sy = d.y - c.y;
    const double denom = cross(rx, ry, sx, sy);
    if (denom == 0.0) return;
    const double qx = c.x - a.x, qy = c.y - a.y;
    const double t = cross(qx, qy, sx, sy) / denom;
    const double u = cross(qx, qy, rx, ry) / denom;
    if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0) return;
    ev.point(a.x + t * rx, a.y + t * ry);
}

// Segment [a, b] against the circle (center, radius): the roots of
// |a + t (b - a) - center|^2 = radius^2 in [0, 1].
void segmentCircle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& center,
                   double radius, Events& ev) {
    const double dx = b.x - a.x, dy = b.y - a.y, fx = a.x - center.x, fy = a.y - center.y;
    const double qa = dx * dx + dy * dy;
    if (!(qa > 0.0)) return;
    const double qb = fx * dx + fy * dy;  // half the linear coefficient
    const double qc = fx * fx + fy * fy - radius * radius;
    const double disc = qb * qb - qa * qc;
    if (disc < 0.0) return;
    const double root = std::sqrt(disc);
    for (const double t : {(-qb - root) / qa, (-qb + root) / qa})
        if (t >= 0.0 && t <= 1.0) ev.point(a.x + t * dx, a.y + t * dy);
}

void circleCircle(const glm::dvec3& c0, double r0, const glm::dvec3& c1, double r1, Events& ev) {
    const double dx = c1.x - c0.x, dy = c1.y - c0.y;
    const double d = std::hypot(dx, dy);
    if (d == 0.0 || d > r0 + r1 || d < std::abs(r0 - r1)) return;
    const double along = (d * d + r0 * r0 - r1 * r1) / (2.0 * d);
    const double h = std::sqrt(std::max(0.0, r0 * r0 - along * along));
    const double mx = c0.x + along * dx / d, my = c0.y + along * dy / d;
    ev.point(mx - h * dy / d, my + h * dx / d);
    ev.point(mx + h * dy / d, my - h * dx / d);
}

// Every edge of a polygon shape against `hit(a, b)`.
template <typename Hit>
void forEdges(const AngularShape& shape, Hit&& hit) {
    const size_t n = shape.vertexCount();
    for (size_t i = 0; i < n; ++i) hit(shape.vertex(i), shape.vertex((i + 1) % n));
}

}  // namespace

void silhouetteEvents(const AngularShape& shape, const AngularExtent& extent,
                      const AngularFrame& frame, double from, double to, std::vector<double>& out) {
    Events ev{frame, from, to, out};
    if (shape.circle) {
        ev.angle(extent.lo);
        ev.angle(extent.hi);
        return;
    }
    const size_t n = shape.vertexCount();
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3 v = shape.vertex(i);
        ev.point(v.x, v.y);
    }
}

void farEvents(const AngularShape& shape, const AngularFrame& frame, double from, double to,
               std::vector<double>& out) {
    Events ev{frame, from, to, out};
    if (shape.circle) {
        circleCircle(shape.center, shape.radius, frame.origin, frame.far, ev);
        return;
    }
    forEdges(shape, [&](const glm::dvec3& a, const glm::dvec3& b) {
        segmentCircle(a, b, frame.origin, frame.far, ev);
    });
}

void crossingEvents(const AngularShape& a, const AngularShape& b, const AngularFrame& frame,
                    double from, double to, std::vector<double>& out) {
    Events ev{frame, from, to, out};
    if (a.circle && b.circle) {
        circleCircle(a.center, a.radius, b.center, b.radius, ev);
    } else if (a.circle || b.circle) {
        const AngularShape& circle = a.circle ? a : b;
        forEdges(a.circle ? b : a, [&](const glm::dvec3& p, const glm::dvec3& q) {
            segmentCircle(p, q, circle.center, circle.radius, ev);
        });
    } else {
        forEdges(a, [&](const glm::dvec3& p, const glm::dvec3& q) {
            forEdges(b, [&](const glm::dvec3& r, const glm::dvec3& s) {
                segmentSegment(p, q, r, s, ev);
            });
        });
    }
}

}  // namespace gridcull
