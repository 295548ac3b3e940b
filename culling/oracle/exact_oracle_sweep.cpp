#include "culling/oracle/exact_oracle_sweep.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "culling/oracle/angle_turn.h"
#include "culling/scene/ray_intersect.h"

namespace gridcull {

namespace {


}  // namespace

void OracleAngularSweep::resize(int rays, double fov_deg) {
    assert(rays >= 1);
    const double fov_rad = glm::radians(fov_deg);
    if (size_t(rays) == distance_.size() && fov_rad == fov_rad_) return;
    fov_rad_ = fov_rad;
    step_ = fov_rad / rays;
    distance_.assign(size_t(rays), 0.0);
    index_.assign(size_t(rays), -1);
    bin_cos_.resize(size_t(rays));
    bin_sin_.resize(size_t(rays));
    for (int i = 0; i < rays; ++i) {
        const double angle = (i + 0.5) * step_;
        bin_cos_[size_t(i)] = std::cos(angle);
        bin_sin_[size_t(i)] = std::sin(angle);
    }
}

void OracleAngularSweep::begin(const Camera& camera) {
    assert(!distance_.empty() && "resize() before begin()");
    const glm::dvec3 fwd = camera.forward();
    const double start = std::atan2(fwd.y, fwd.x) - 0.5 * fov_rad_;
    start_cos_ = std::cos(start);
    start_sin_ = std::sin(start);
    origin_ = {camera.position.x, camera.position.y, 0.0};
    far_ = camera.far;
    std::fill(distance_.begin(), distance_.end(), std::numeric_limits<double>::infinity());
    std::fill(index_.begin(), index_.end(), -1);
}

double OracleAngularSweep::relativeAngle(const glm::dvec3& p) const {
    const double x = p.x - origin_.x, y = p.y - origin_.y;
    // Rotate by minus the start angle, then measure.
    const double a = std::atan2(y * start_cos_ - x * start_sin_, x * start_cos_ + y * start_sin_);
    return a < 0.0 ? a + kTwoPi : a;
}

double OracleAngularSweep::minDistanceOfCircle(const glm::dvec3& center, double radius) const {
    return std::hypot(center.x - origin_.x, center.y - origin_.y) - radius;
}

double OracleAngularSweep::minDistanceOfBox(const Aabb& box) const {
    const double dx = std::max({box.min.x - origin_.x, 0.0, origin_.x - box.max.x});
    const double dy = std::max({box.min.y - origin_.y, 0.0, origin_.y - box.max.y});
    return std::hypot(dx, dy);
}

void OracleAngularSweep::fillAll(int index) {
    for (size_t i = 0; i < distance_.size(); ++i) {
        if (0.0 < distance_[i]) {
            distance_[i] = 0.0;
            index_[i] = index;
        }
    }
}

template <typename Hit>
bool OracleAngularSweep::forRaysIn(double from, double width, Hit&& hit) {
    const int rays = int(distance_.size());
    if (width >= kTwoPi) {
        for (int i = 0; i < rays; ++i) hit(i);
        return true;
    }
    // Intervals arrive unwrapped (a circle straddling the wedge's first edge starts
    // below 0, a polygon's running angle may start anywhere): wrap into [0, 2 pi).
    from = std::fmod(from, kTwoPi);
    if (from < 0.0) from += kTwoPi;
    bool any = false;
    // Bin centre i is at (i + 0.5) * step_; the interval may wrap past 2 pi back to
    // the start of the wedge.
    auto range = [&](double lo, double hi) {
        if (hi < 0.0 || lo > fov_rad_) return;
        const double first = std::clamp(std::floor(lo / step_ - 0.5), 0.0, double(rays - 1));
        const double last = std::clamp(std::ceil(hi / step_ - 0.5), 0.0, double(rays - 1));
        for (int i = int(first); i <= int(last); ++i) hit(i);
        any = true;
    };
    range(from, from + width);
    if (from + width > kTwoPi) range(from - kTwoPi, from + width - kTwoPi);
    return any;
}

bool OracleAngularSweep::drawCircle(int index, const glm::dvec3& center, double radius) {
    const glm::dvec3 c{center.x, center.y, 0.0};
    const double dist = std::hypot(c.x - origin_.x, c.y - origin_.y);
    if (dist <= radius) {
        fillAll(index);
        return true;
    }
    const double d_min = dist - radius;
    if (d_min > far_) return false;
    const double half = std::asin(radius / dist);
    const glm::dvec3 oc = c - origin_;
    const double k = glm::dot(oc, oc) - radius * radius;
    return forRaysIn(relativeAngle(c) - half, 2.0 * half, [&](int i) {
        if (distance_[size_t(i)] <= d_min) return;
        const glm::dvec3 dir = rayDirection(i);
        double s0, s1, s;
        if (!solveSphereQuadratic(1.0, glm::dot(dir, oc), k, s0, s1)) return;
        if (!solidEntry(s0, s1, 0.0, far_, s) || !(s < distance_[size_t(i)])) return;
        distance_[size_t(i)] = s;
        index_[size_t(i)] = index;
    });
}

bool OracleAngularSweep::drawBox(int index, const Aabb& box) {
    const glm::dvec3 corners[4] = {{box.min.x, box.min.y, 0.0},
                                   {box.max.x, box.min.y, 0.0},
                                   {box.max.x, box.max.y, 0.0},
                                   {box.min.x, box.max.y, 0.0}};
    return drawPolygon(index, corners, 4, glm::dvec3(0.0));
}

bool OracleAngularSweep::drawPolygon(int index, const glm::dvec3* points, size_t count,
                                     const glm::dvec3& offset) {
    if (count < 3) return false;
    // Walk the boundary accumulating the turn of the direction to each vertex: the
    // total is 2 pi * winding number, and with the camera outside the range of the
    // running angle is the polygon's angular interval (it can exceed pi for a
    // non-convex polygon that wraps around the camera).
    const glm::dvec3 p0 = points[0] + offset;
    double angle = relativeAngle(p0);
    const double first = angle;
    double lo = angle, hi = angle;
    double d_min = std::numeric_limits<double>::infinity();
    bool on_boundary = false;
    for (size_t i = 0; i < count; ++i) {
        const glm::dvec3 a = points[i] + offset;
        const glm::dvec3 b = points[(i + 1) % count] + offset;
        const double turn = wrapTurn(relativeAngle(b) - relativeAngle(a));
        // A turn of +-pi means the camera lies on the edge's line between its ends.
        if (std::abs(turn) >= kPi * (1.0 - 1e-12)) on_boundary = true;
        angle += turn;
        lo = std::min(lo, angle);
        hi = std::max(hi, angle);
        // Exact distance from the camera to this edge.
        const glm::dvec3 e{b.x - a.x, b.y - a.y, 0.0};
        const glm::dvec3 w{origin_.x - a.x, origin_.y - a.y, 0.0};
        const double len2 = glm::dot(e, e);
        const double f = len2 > 0.0 ? std::clamp(glm::dot(w, e) / len2, 0.0, 1.0) : 0.0;
        d_min = std::min(d_min, glm::length(w - e * f));
    }
    if (on_boundary || d_min == 0.0 || std::abs(angle - first) > kPi) {
        fillAll(index);
        return true;
    }
    if (d_min > far_) return false;
    return forRaysIn(lo, hi - lo, [&](int i) {
        if (distance_[size_t(i)] <= d_min) return;
        double s;
        if (!rayPolygonEdges2d(origin_, rayDirection(i), points, count, offset, s)) return;
        if (s > far_ || !(s < distance_[size_t(i)])) return;
        distance_[size_t(i)] = s;
        index_[size_t(i)] = index;
    });
}

glm::dvec3 OracleAngularSweep::rayDirection(int i) const {
    const double c = bin_cos_[size_t(i)], s = bin_sin_[size_t(i)];
    return {c * start_cos_ - s * start_sin_, s * start_cos_ + c * start_sin_, 0.0};
}

void OracleAngularSweep::markVisible(std::vector<char>& seen) const {
    for (const int32_t index : index_) {
        if (index < 0) continue;
        assert(size_t(index) < seen.size());
        seen[size_t(index)] = 1;
    }
}

}  // namespace gridcull
