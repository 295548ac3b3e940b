#include "culling/oracle/pixel_pyramid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

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
    return {{{0, -1, v0}, {-1, 0, u1}, {0, 1, -v1}, {1, 0, -u0}},
            {{u0, v0, 1}, {u1, v0, 1}, {u1, v1, 1}, {u0, v1, 1}}};
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

double leastSphereDepthInPyramid(const PixelPyramid& pyramid, const glm::dvec3& center,
                                 double radius) {
    if (!sphereMeetsPyramid(pyramid, center, radius)) return kMisses;
    double bound = center.z - radius;
    for (const glm::dvec3& normal : pyramid.normals) {
        const glm::dvec3 n = glm::normalize(normal);
        const double off = glm::dot(n, center);
        if (off - radius * n.z >= 0.0) continue;  // the sphere's nearest point is inside
        // Else the least depth is on the disc the plane cuts from the sphere.
        const double disc_radius = std::sqrt(std::max(0.0, radius * radius - off * off));
        const double least =
            (center.z - off * n.z) - disc_radius * std::sqrt(std::max(0.0, 1.0 - n.z * n.z));
        bound = std::max(bound, least);
    }
    return lowered(bound);
}

double leastBoxDepthInPyramid(const PixelPyramid& pyramid, const glm::dvec3 corners[8]) {
    double bound = kMisses;
    for (int c = 0; c < 8; ++c) bound = std::min(bound, corners[c].z);
    for (const glm::dvec3& normal : pyramid.normals) {
        // The box cut by the plane: its least depth is at a corner inside or
        // where an edge crosses the plane.
        double side[8];
        double least = kMisses;
        for (int c = 0; c < 8; ++c) {
            side[c] = glm::dot(normal, corners[c]);
            if (side[c] >= 0.0) least = std::min(least, corners[c].z);
        }
        if (least == kMisses) return kMisses;  // wholly outside this plane
        for (int c = 0; c < 8; ++c)
            for (int bit = 1; bit < 8; bit <<= 1) {
                if (c & bit) continue;
                const int d = c | bit;
                if ((side[c] >= 0.0) == (side[d] >= 0.0)) continue;
                const double f = side[c] / (side[c] - side[d]);
                least = std::min(least, corners[c].z + f * (corners[d].z - corners[c].z));
            }
        bound = std::max(bound, least);
    }
    return lowered(bound);
}

}  // namespace gridcull
