// The 3D frustum of regular-grid culling; see rgvc_frustum3d.h.
#include "culling/rgvc/rgvc_frustum3d.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace gridcull {

namespace {

constexpr double kIndexLimit = 1099511627776.0;  // 2^40 voxels: beyond any grid

int64_t clampIndex(double v) {
    return int64_t(std::clamp(v, -kIndexLimit, kIndexLimit));
}

}  // namespace

void RgvcFrustum3::set(const Camera& camera, const RegularGrid& grid) {
    const std::array<glm::dvec4, 6> all = camera.frustumPlanes();
    // Left, right, bottom, top and far: all but the near plane (index 4).
    planes_ = {all[0], all[1], all[2], all[3], all[5]};
    apex_ = camera.position;
    forward_ = camera.forward();
    origin_ = grid.world.min;
    voxel_ = grid.voxelSize();
    near_ = camera.near;
    far_ = camera.far;
    const double side = std::max({voxel_.x, voxel_.y, voxel_.z});
    slack_ = kFrustum3Slack * side;
    depth_half_ = 0.5 * (std::abs(forward_.x) * voxel_.x + std::abs(forward_.y) * voxel_.y +
                         std::abs(forward_.z) * voxel_.z);
    glm::dvec3 right, up, fwd;
    camera.basis(right, up, fwd);
    const double ty = std::tan(glm::radians(camera.fov_deg) * 0.5), tx = ty * camera.aspect;
    for (int i = 0; i < 4; ++i) {
        const double sx = (i & 1) ? 1.0 : -1.0, sy = (i & 2) ? 1.0 : -1.0;
        far_corners_[i] = apex_ + (fwd + right * (sx * tx) + up * (sy * ty)) * far_;
    }
}

bool RgvcFrustum3::touchesBox(const glm::dvec3& lo, const glm::dvec3& hi) const {
    for (const glm::dvec4& p : planes_) {
        const glm::dvec3 n(p);
        const glm::dvec3 best{n.x > 0.0 ? hi.x : lo.x, n.y > 0.0 ? hi.y : lo.y,
                              n.z > 0.0 ? hi.z : lo.z};
        if (glm::dot(n, best) + p.w < -slack_) return false;
    }
    return true;
}

bool RgvcFrustum3::touchesVoxel(const glm::i64vec3& v) const {
    const glm::dvec3 lo = origin_ + glm::dvec3(v) * voxel_;
    return touchesBox(lo, lo + voxel_);
}

bool RgvcFrustum3::rowRange(int axis, const glm::i64vec3& at, int64_t& i0, int64_t& i1) const {
    const glm::dvec3 lo = origin_ + glm::dvec3(at) * voxel_;
    double lo_f = double(i0), hi_f = double(i1);
    for (const glm::dvec4& p : planes_) {
        const glm::dvec3 n(p);
        // The best corner's dot product is a * i + b along the row.
        double b = p.w + slack_;
        for (int k = 0; k < 3; ++k) {
            if (k == axis) continue;
            b += n[k] * (n[k] > 0.0 ? lo[k] + voxel_[k] : lo[k]);
        }
        const double a = n[axis] * voxel_[axis];
        b += n[axis] * (origin_[axis] + (n[axis] > 0.0 ? voxel_[axis] : 0.0));
        if (a > 0.0) {
            lo_f = std::max(lo_f, std::ceil(-b / a));
        } else if (a < 0.0) {
            hi_f = std::min(hi_f, std::floor(b / -a));
        } else if (b < 0.0) {
            return false;
        }
        if (lo_f > hi_f) return false;
    }
    i0 = clampIndex(lo_f);
    i1 = clampIndex(hi_f);
    return i0 <= i1;
}

void RgvcFrustum3::voxelBounds(glm::i64vec3& lo, glm::i64vec3& hi) const {
    glm::dvec3 a = apex_, b = apex_;
    for (const glm::dvec3& c : far_corners_) {
        a = glm::min(a, c);
        b = glm::max(b, c);
    }
    for (int k = 0; k < 3; ++k) {
        lo[k] = clampIndex(std::floor((a[k] - origin_[k]) / voxel_[k]) - 1.0);
        hi[k] = clampIndex(std::floor((b[k] - origin_[k]) / voxel_[k]) + 1.0);
    }
}

std::array<glm::dvec3, 4> RgvcFrustum3::edgeDirections() const {
    return {far_corners_[0] - apex_, far_corners_[1] - apex_, far_corners_[2] - apex_,
            far_corners_[3] - apex_};
}

double RgvcFrustum3::minDepthOfVoxel(const glm::i64vec3& v) const {
    const glm::dvec3 centre = origin_ + (glm::dvec3(v) + 0.5) * voxel_;
    return glm::dot(centre - apex_, forward_) - depth_half_;
}

}  // namespace gridcull
