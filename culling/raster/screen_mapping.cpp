#include "culling/raster/screen_mapping.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace gridcull {

void ScreenMapping::set(const Camera& camera, int width, int height) {
    camera.basis(right_, up_, forward_);
    eye_ = camera.position;
    tan_y_ = std::tan(glm::radians(camera.fov_deg) * 0.5);
    tan_x_ = tan_y_ * camera.aspect;
    near_ = camera.near;
    width_ = std::max(1, width);
    height_ = std::max(1, height);
}

glm::dvec3 ScreenMapping::toView(const glm::dvec3& world) const {
    const glm::dvec3 d = world - eye_;
    return {glm::dot(d, right_), glm::dot(d, up_), glm::dot(d, forward_)};
}

BoxOnScreen ScreenMapping::project(const Aabb& box) const {
    glm::dvec3 corner[8];
    double zmin = std::numeric_limits<double>::infinity();
    double zmax = -zmin;
    for (int i = 0; i < 8; ++i) {
        corner[i] = toView(box.corner(i));
        zmin = std::min(zmin, corner[i].z);
        zmax = std::max(zmax, corner[i].z);
    }
    BoxOnScreen out;
    const double slack = kDepthSlack * (1.0 + std::abs(zmin) + std::abs(zmax));
    out.znear = zmin - slack;
    out.zfar = zmax + slack;
    // The oracle counts a camera inside (or on) a sphere or box as seeing only it,
    // at depth near over the whole image; a box around the eye must cover it all.
    if (box.contains(eye_)) {
        out.rect = image();
        return out;
    }
    if (!(zmax >= near_)) return out;  // wholly in front of the near plane (or NaN): no pixel

    double u_lo = std::numeric_limits<double>::infinity(), u_hi = -u_lo;
    double v_lo = u_lo, v_hi = -u_lo;
    auto take = [&](const glm::dvec3& p) {
        u_lo = std::min(u_lo, p.x / p.z);
        u_hi = std::max(u_hi, p.x / p.z);
        v_lo = std::min(v_lo, p.y / p.z);
        v_hi = std::max(v_hi, p.y / p.z);
    };
    for (int i = 0; i < 8; ++i)
        if (corner[i].z >= near_) take(corner[i]);
    if (zmin < near_) {
        // The 12 edges join corners differing in one bit; keep their near-plane crossings.
        for (int i = 0; i < 8; ++i)
            for (int bit = 1; bit < 8; bit <<= 1) {
                const int j = i | bit;
                if (j == i) continue;
                const glm::dvec3& a = corner[i];
                const glm::dvec3& b = corner[j];
                if ((a.z < near_) == (b.z < near_)) continue;
                const double s = (near_ - a.z) / (b.z - a.z);
                take({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), near_});
            }
    }
    // u grows to the right, v grows up while rows grow down.
    const double x_lo = columnOf(u_lo) - kRectSlack, x_hi = columnOf(u_hi) + kRectSlack;
    const double y_lo = rowOf(v_hi) - kRectSlack, y_hi = rowOf(v_lo) + kRectSlack;
    if (!(x_lo <= x_hi) || !(y_lo <= y_hi)) {  // NaN from a degenerate camera: all pixels
        out.rect = image();
        return out;
    }
    // Clamp in double before the int cast so a huge coordinate cannot overflow it.
    auto floorTo = [](double x, int count) {
        return int(std::clamp(std::floor(x), -1.0, double(count)));
    };
    out.rect = PixelRect{floorTo(x_lo, width_), floorTo(y_lo, height_), floorTo(x_hi, width_),
                         floorTo(y_hi, height_)}
                   .intersect(image());
    return out;
}

}  // namespace gridcull
