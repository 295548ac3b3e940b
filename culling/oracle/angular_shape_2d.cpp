#include "culling/oracle/angular_shape_2d.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "culling/oracle/angle_turn.h"
#include "culling/scene/ray_intersect.h"

namespace gridcull {

namespace {


constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

void AngularFrame::set(const Camera& camera, double fov_rad) {
    const glm::dvec3 fwd = camera.forward();
    const double start = std::atan2(fwd.y, fwd.x) - 0.5 * fov_rad;
    start_cos = std::cos(start);
    start_sin = std::sin(start);
    origin = {camera.position.x, camera.position.y, 0.0};
    fov = fov_rad;
    far = camera.far;
}

double AngularFrame::angleOf(const glm::dvec3& p) const {
    const double x = p.x - origin.x, y = p.y - origin.y;
    const double a = std::atan2(y * start_cos - x * start_sin, x * start_cos + y * start_sin);
    return a < 0.0 ? a + kTwoPi : a;
}

glm::dvec3 AngularFrame::direction(double a) const {
    const double c = std::cos(a), s = std::sin(a);
    return {c * start_cos - s * start_sin, s * start_cos + c * start_sin, 0.0};
}

AngularShape AngularShape::makeCircle(const glm::dvec3& center, double radius) {
    AngularShape shape;
    shape.circle = true;
    shape.center = {center.x, center.y, 0.0};
    shape.radius = radius;
    return shape;
}

AngularShape AngularShape::makeBox(const Aabb& box) {
    AngularShape shape;
    shape.corners[0] = {box.min.x, box.min.y, 0.0};
    shape.corners[1] = {box.max.x, box.min.y, 0.0};
    shape.corners[2] = {box.max.x, box.max.y, 0.0};
    shape.corners[3] = {box.min.x, box.max.y, 0.0};
    return shape;
}

AngularShape AngularShape::makePolygon(const glm::dvec3* points, size_t count,
                                       const glm::dvec3& offset) {
    AngularShape shape;
    shape.points = points;
    shape.count = count;
    shape.offset = offset;
    return shape;
}

glm::dvec3 AngularShape::vertex(size_t i) const {
    const glm::dvec3 p = points ? points[i] + offset : corners[i];
    return {p.x, p.y, 0.0};
}

AngularExtent angularExtent(const AngularShape& shape, const AngularFrame& frame) {
    AngularExtent extent;
    if (shape.circle) {
        const double dist =
            std::hypot(shape.center.x - frame.origin.x, shape.center.y - frame.origin.y);
        extent.min_distance = dist - shape.radius;
        extent.max_distance = dist + shape.radius;
        if (dist <= shape.radius) {
            extent.contains_camera = true;
            return extent;
        }
        const double half = std::asin(shape.radius / dist);
        const double mid = frame.angleOf(shape.center);
        extent.lo = mid - half;
        extent.hi = mid + half;
        return extent;
    }
    // As the sampled sweep's drawPolygon: the running angle of the direction to
    // each vertex turns 2 pi * winding number in all; with the camera outside, its
    // range is the angular interval (beyond pi for a polygon wrapped around the
    // camera). A turn of +-pi puts the camera on an edge between its ends.
    const size_t n = shape.vertexCount();
    if (n < 3) return extent;
    double angle = frame.angleOf(shape.vertex(0));
    const double first = angle;
    double lo = angle, hi = angle, d_min = kInfinity, d_max = 0.0;
    bool on_boundary = false;
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3 a = shape.vertex(i), b = shape.vertex((i + 1) % n);
        const double turn = wrapTurn(frame.angleOf(b) - frame.angleOf(a));
        if (std::abs(turn) >= kPi * (1.0 - 1e-12)) on_boundary = true;
        angle += turn;
        lo = std::min(lo, angle);
        hi = std::max(hi, angle);
        const glm::dvec3 e = b - a, w = frame.origin - a;
        const double len2 = glm::dot(e, e);
        const double f = len2 > 0.0 ? std::clamp(glm::dot(w, e) / len2, 0.0, 1.0) : 0.0;
        d_min = std::min(d_min, glm::length(w - e * f));
        d_max = std::max(d_max, glm::length(w));
    }
    extent.min_distance = d_min;
    extent.max_distance = d_max;
    extent.contains_camera = on_boundary || d_min == 0.0 || std::abs(angle - first) > kPi;
    extent.lo = lo;
    extent.hi = hi;
    return extent;
}

double rayDistance(const AngularShape& shape, const AngularFrame& frame, const glm::dvec3& dir) {
    double s = kInfinity;
    if (shape.circle) {
        double s0, s1;
        if (!lineSphere(frame.origin, dir, shape.center, shape.radius, s0, s1) ||
            !solidEntry(s0, s1, 0.0, frame.far, s))
            return kInfinity;
        return s;
    }
    const bool hit =
        shape.points
            ? rayPolygonEdges2d(frame.origin, dir, shape.points, shape.count, shape.offset, s)
            : rayPolygonEdges2d(frame.origin, dir, shape.corners, 4, glm::dvec3(0.0), s);
    return hit && s <= frame.far ? s : kInfinity;
}

}  // namespace gridcull
