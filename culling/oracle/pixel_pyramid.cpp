#include "culling/oracle/pixel_pyramid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "culling/scene/ray_intersect.h"

namespace gridcull {

namespace {

constexpr double kMisses = std::numeric_limits<double>::infinity();

// Rounding may lift a bound a little above the true least depth.
double lowered(double bound) {
    return bound - 1e-9 * std::abs(bound);
}

}  // namespace

glm::dvec3 PixelView::ray(double x, double y) const {
    const double u = (2.0 * x / width - 1.0) * tan_x;
    const double v = (1.0 - 2.0 * y / height) * tan_y;
    return forward + u * right + v * up;
}

glm::dvec3 PixelView::toView(const glm::dvec3& world) const {
    const glm::dvec3 rel = world - eye;
    return {glm::dot(rel, right), glm::dot(rel, up), glm::dot(rel, forward)};
}

double PixelView::columnOf(const glm::dvec3& p) const {
    return (p.x / p.z / tan_x + 1.0) * 0.5 * width;
}

double PixelView::rowOf(const glm::dvec3& p) const {
    return (1.0 - p.y / p.z / tan_y) * 0.5 * height;
}

PixelPyramid pixelPyramid(const PixelView& view, int px, int py) {
    return pixelPyramid((2.0 * px / view.width - 1.0) * view.tan_x,
                        (2.0 * (px + 1) / view.width - 1.0) * view.tan_x,
                        (1.0 - 2.0 * py / view.height) * view.tan_y,
                        (1.0 - 2.0 * (py + 1) / view.height) * view.tan_y);
}

PixelPyramid pixelPyramid(double u0, double u1, double v0, double v1) {
    PixelPyramid pyramid{{{0, -1, v0}, {-1, 0, u1}, {0, 1, -v1}, {1, 0, -u0}},
                         {{u0, v0, 1}, {u1, v0, 1}, {u1, v1, 1}, {u0, v1, 1}},
                         {}};
    for (int i = 0; i < 4; ++i) pyramid.normal_length[i] = glm::length(pyramid.normals[i]);
    return pyramid;
}

bool sphereMeetsPyramid(const PixelPyramid& pyramid, const glm::dvec3& center, double radius) {
    // The sphere meets the pyramid when its centre lies within radius of it.
    // Outside the pyramid the nearest point is on a face or on a corner ray.
    const double reach = radius * (1.0 + 1e-9) + 1e-12 * glm::length(center);
    bool inside = true;
    double nearest = kMisses;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 n = glm::normalize(pyramid.normals[i]);
        const double off = glm::dot(n, center);
        if (off < 0.0) inside = false;
        // The centre projected on face i's plane lies on the face when the other
        // three planes keep it.
        const glm::dvec3 q = center - off * n;
        bool on_face = true;
        for (int j = 0; j < 4 && on_face; ++j)
            if (j != i) on_face = glm::dot(pyramid.normals[j], q) >= 0.0;
        if (on_face) nearest = std::min(nearest, std::abs(off));
        const glm::dvec3 e = glm::normalize(pyramid.edges[i]);
        const double t = std::max(0.0, glm::dot(center, e));
        nearest = std::min(nearest, glm::length(center - t * e));
    }
    return inside || nearest <= reach;
}

namespace {

// Inside the pyramid, up to a relative 1e-9: a point that rounding puts just
// outside still counts, which can only lower a least depth.
bool inPyramid(const PixelPyramid& pyramid, const glm::dvec3& p) {
    const double scale = -1e-9 * (std::abs(p.x) + std::abs(p.y) + std::abs(p.z));
    for (int i = 0; i < 4; ++i)
        if (glm::dot(pyramid.normals[i], p) < scale * pyramid.normal_length[i]) return false;
    return true;
}

// The least depth of the sphere's part inside each plane alone, the greatest
// over the four: a weaker bound, the fallback when rounding leaves the exact
// search below with no point.
double sphereRelaxedBound(const PixelPyramid& pyramid, const glm::dvec3& center, double radius) {
    double bound = center.z - radius;
    for (const glm::dvec3& normal : pyramid.normals) {
        const glm::dvec3 n = glm::normalize(normal);
        const double off = glm::dot(n, center);
        if (off - radius * n.z >= 0.0) continue;  // the sphere's nearest point is inside
        const double disc_radius = std::sqrt(std::max(0.0, radius * radius - off * off));
        bound = std::max(bound, (center.z - off * n.z) -
                                    disc_radius * std::sqrt(std::max(0.0, 1.0 - n.z * n.z)));
    }
    return bound;
}

}  // namespace

double leastSphereDepthInPyramid(const PixelPyramid& pyramid, const glm::dvec3& center,
                                 double radius) {
    if (!sphereMeetsPyramid(pyramid, center, radius)) return kMisses;
    // Depth is linear and both sets convex, so the least depth is at the
    // sphere's nearest point when the pyramid holds it; else on a face, at the
    // least point of the disc the face's plane cuts from the sphere; else on a
    // corner ray, where it enters the sphere (or at the eye, inside it).
    const glm::dvec3 nearest = center - glm::dvec3(0.0, 0.0, radius);
    if (inPyramid(pyramid, nearest)) return lowered(nearest.z);
    double least = kMisses;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 n = glm::normalize(pyramid.normals[i]);
        const double off = glm::dot(n, center);
        if (std::abs(off) <= radius) {
            const glm::dvec3 disc_center = center - off * n;
            const double disc_radius = std::sqrt(std::max(0.0, radius * radius - off * off));
            // Straight down the depth axis, within the plane.
            const glm::dvec3 down = glm::dvec3(0.0, 0.0, 1.0) - n.z * n;
            const glm::dvec3 p = disc_center - disc_radius * glm::normalize(down);
            if (inPyramid(pyramid, p)) least = std::min(least, p.z);
        }
        double s0, s1;  // the corner ray's direction has depth component 1
        if (lineSphere(glm::dvec3(0.0), pyramid.edges[i], center, radius, s0, s1) && s1 >= 0.0)
            least = std::min(least, std::max(s0, 0.0));
    }
    if (least == kMisses) least = sphereRelaxedBound(pyramid, center, radius);
    return lowered(least);
}

double leastBoxDepthInPyramid(const PixelPyramid& pyramid, const glm::dvec3 corners[8]) {
    // Depth is linear: its least over the box cut by the pyramid is at a corner
    // of that polytope: a box corner inside the pyramid, a box edge crossing a
    // face's plane inside the other three, or a corner ray entering the box (or
    // the eye, inside it). `corners` may be any parallelepiped's, so the corner
    // rays meet its faces as planes, not as a slab test.
    double least = kMisses;
    double relaxed = kMisses;  // the per-plane bound, as a fallback
    for (int c = 0; c < 8; ++c) {
        relaxed = std::min(relaxed, corners[c].z);
        if (inPyramid(pyramid, corners[c])) least = std::min(least, corners[c].z);
    }
    for (const glm::dvec3& normal : pyramid.normals) {
        double side[8];
        double plane_least = kMisses;
        for (int c = 0; c < 8; ++c) {
            side[c] = glm::dot(normal, corners[c]);
            if (side[c] >= 0.0) plane_least = std::min(plane_least, corners[c].z);
        }
        if (plane_least == kMisses) return kMisses;  // wholly outside this plane
        for (int c = 0; c < 8; ++c)
            for (int bit = 1; bit < 8; bit <<= 1) {
                if (c & bit) continue;
                const int d = c | bit;
                if ((side[c] >= 0.0) == (side[d] >= 0.0)) continue;
                const glm::dvec3 p = corners[c] + (corners[d] - corners[c]) * (side[c] / (side[c] - side[d]));
                plane_least = std::min(plane_least, p.z);
                if (inPyramid(pyramid, p)) least = std::min(least, p.z);
            }
        relaxed = std::max(relaxed, plane_least);
    }
    // The corner rays: the box is the set where each of its three slabs (the
    // corner pairs along bit 1, 2, 4) holds, each slab two parallel planes. A
    // flat box has no normal to one slab: the weaker bound serves.
    for (int bit = 1; bit < 8; bit <<= 1)
        if (corners[bit] == corners[0]) return lowered(relaxed);
    for (const glm::dvec3& dir : pyramid.edges) {
        double lo = 0.0, hi = kMisses;  // ray parameters; depth = parameter
        for (int bit = 1; bit < 8 && lo <= hi; bit <<= 1) {
            // The slab's normal: across it, from corner 0 to corner `bit`.
            const glm::dvec3 across = corners[bit] - corners[0];
            const double a = glm::dot(across, corners[0]), b = glm::dot(across, corners[bit]);
            const double rate = glm::dot(across, dir);
            if (rate == 0.0) {
                if (0.0 < std::min(a, b) || 0.0 > std::max(a, b)) lo = kMisses;
                continue;
            }
            const double t0 = a / rate, t1 = b / rate;
            lo = std::max(lo, std::min(t0, t1));
            hi = std::min(hi, std::max(t0, t1));
        }
        if (lo <= hi) least = std::min(least, lo);
    }
    // No corner of the cut polytope: the box misses the pyramid (the points
    // above are taken within a margin far wider than their rounding).
    return least == kMisses ? kMisses : lowered(least);
}

}  // namespace gridcull
