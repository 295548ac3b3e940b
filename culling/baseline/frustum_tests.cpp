// The frustum math of culling/baseline/frustum_tests.h.
#include "culling/baseline/frustum_tests.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace gridcull {

namespace {

constexpr double kPi = 3.141592653589793238462643383279;
constexpr double kTwoPi = 2.0 * kPi;
// Slack that keeps the tests conservative under rounding: an object touching a
// plane or the wedge's edge within this much is kept.
constexpr double kAngleSlack = 1e-9;  // radians

double wrapAngle(double a) {
    a = std::fmod(a, kTwoPi);
    if (a > kPi) a -= kTwoPi;
    if (a <= -kPi) a += kTwoPi;
    return a;
}

// Does the arc [center - half_width, center + half_width] meet the camera's wedge?
bool arcMeetsWedge(double center, double half_width, const Camera& camera) {
    const glm::dvec3 fwd = camera.forward();
    const double heading = std::atan2(fwd.y, fwd.x);
    const double wedge_half = 0.5 * glm::radians(camera.fov_deg);
    // Two arcs on a circle meet iff their centres are at most the sum of their
    // half widths apart.
    return std::abs(wrapAngle(center - heading)) <= wedge_half + half_width + kAngleSlack;
}

}  // namespace

bool boxMayIntersectFrustum(const Aabb& box, const Camera& camera) {
    return boxMayIntersectFrustum(box, camera, camera.frustumPlanes());
}

bool boxMayIntersectFrustum(const Aabb& box, const Camera& camera,
                            const std::array<glm::dvec4, 6>& planes) {
    if (box.contains(camera.position)) return true;
    const double slack = 1e-9 * std::max(1.0, camera.far);
    for (const glm::dvec4& plane : planes) {
        // The corner furthest along the inward normal.
        const glm::dvec3 corner{plane.x >= 0.0 ? box.max.x : box.min.x,
                                plane.y >= 0.0 ? box.max.y : box.min.y,
                                plane.z >= 0.0 ? box.max.z : box.min.z};
        if (plane.x * corner.x + plane.y * corner.y + plane.z * corner.z + plane.w < -slack)
            return false;
    }
    return true;
}

bool circleMayIntersectWedge(const glm::dvec3& center, double radius, const Camera& camera) {
    const double dx = center.x - camera.position.x, dy = center.y - camera.position.y;
    const double dist = std::hypot(dx, dy);
    if (dist <= radius) return true;
    if (dist - radius > camera.far * (1.0 + 1e-12)) return false;
    if (camera.fov_deg >= 360.0) return true;
    return arcMeetsWedge(std::atan2(dy, dx), std::asin(radius / dist), camera);
}

bool boxMayIntersectWedge(const Aabb& box, const Camera& camera) {
    const glm::dvec3& o = camera.position;
    if (o.x >= box.min.x && o.x <= box.max.x && o.y >= box.min.y && o.y <= box.max.y) return true;
    const double gap_x = std::max({box.min.x - o.x, 0.0, o.x - box.max.x});
    const double gap_y = std::max({box.min.y - o.y, 0.0, o.y - box.max.y});
    if (std::hypot(gap_x, gap_y) > camera.far * (1.0 + 1e-12)) return false;
    if (camera.fov_deg >= 360.0) return true;
    // Seen from outside, a box spans less than pi, so its corners' angles measured
    // from the direction to its centre give its interval without wrapping.
    const glm::dvec3 c = box.center();
    const double mid = std::atan2(c.y - o.y, c.x - o.x);
    double lo = 0.0, hi = 0.0;
    for (int i = 0; i < 4; ++i) {
        const double x = (i & 1) ? box.max.x : box.min.x;
        const double y = (i & 2) ? box.max.y : box.min.y;
        const double rel = wrapAngle(std::atan2(y - o.y, x - o.x) - mid);
        lo = std::min(lo, rel);
        hi = std::max(hi, rel);
    }
    return arcMeetsWedge(mid + 0.5 * (lo + hi), 0.5 * (hi - lo), camera);
}

}  // namespace gridcull
