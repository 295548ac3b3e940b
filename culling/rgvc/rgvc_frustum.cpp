// The 2D frustum of regular-grid culling (Batagelo & Wu, section 4.2); see
// rgvc_frustum.h.
#include "culling/rgvc/rgvc_frustum.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/trigonometric.hpp>

#include "grid/chess_ring.h"

namespace gridcull {

namespace {

constexpr double kPi = 3.141592653589793238462643383279;

double cross(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

int64_t positiveMod(int64_t a, int64_t n) {
    const int64_t m = a % n;
    return m < 0 ? m + n : m;
}

// Voxels on either side of an edge's crossing that may still meet the edge's ray
// in the same ring (the ray crosses a ring one voxel thick, so at most two
// positions either way; one more against rounding).
constexpr int64_t kRunMargin = 3;

}  // namespace

void RgvcWedge::set(const Camera& camera, const glm::dvec3& voxel_size) {
    apex_ = {camera.position.x, camera.position.y};
    const glm::dvec3 f = camera.forward();
    forward_ = glm::dvec2(f.x, f.y);
    const double len = std::hypot(forward_.x, forward_.y);
    forward_ = len > 0.0 ? forward_ / len : glm::dvec2(1.0, 0.0);
    full_ = camera.fov_deg >= 360.0;
    fov_ = glm::radians(std::min(camera.fov_deg, 360.0));
    const double heading = std::atan2(forward_.y, forward_.x);
    edge_cw_ = {std::cos(heading - 0.5 * fov_), std::sin(heading - 0.5 * fov_)};
    edge_ccw_ = {std::cos(heading + 0.5 * fov_), std::sin(heading + 0.5 * fov_)};
    far_ = camera.far;
    slack_ = kWedgeSlack * std::max(voxel_size.x, voxel_size.y);
    const double reach = far_ * (1.0 + 1e-12) + slack_;
    far_sq_ = reach * reach;
    voxel_size_ = voxel_size;
}

bool RgvcWedge::inConvexWedge(double px, double py) const {
    const glm::dvec2 q{px - apex_.x, py - apex_.y};
    return cross(edge_cw_, q) >= -slack_ && cross(q, edge_ccw_) >= -slack_;
}

bool RgvcWedge::strictlyInComplement(double px, double py) const {
    // The complement of a wedge of at least 180 degrees is an open convex wedge
    // from the counter-clockwise edge round to the clockwise one.
    const glm::dvec2 q{px - apex_.x, py - apex_.y};
    return cross(edge_ccw_, q) > slack_ && cross(q, edge_cw_) > slack_;
}

bool RgvcWedge::rayMeetsBox(glm::dvec2 dir, double x0, double y0, double x1, double y1) const {
    double lo = 0.0, hi = std::numeric_limits<double>::infinity();
    const double bmin[2] = {x0 - slack_, y0 - slack_}, bmax[2] = {x1 + slack_, y1 + slack_};
    const double o[2] = {apex_.x, apex_.y}, d[2] = {dir.x, dir.y};
    for (int axis = 0; axis < 2; ++axis) {
        if (d[axis] == 0.0) {
            if (o[axis] < bmin[axis] || o[axis] > bmax[axis]) return false;
            continue;
        }
        double ta = (bmin[axis] - o[axis]) / d[axis], tb = (bmax[axis] - o[axis]) / d[axis];
        if (ta > tb) std::swap(ta, tb);
        lo = std::max(lo, ta);
        hi = std::min(hi, tb);
        if (lo > hi) return false;
    }
    return true;
}

bool RgvcWedge::touchesBox(double x0, double y0, double x1, double y1) const {
    const double gap_x = std::max({x0 - apex_.x, 0.0, apex_.x - x1});
    const double gap_y = std::max({y0 - apex_.y, 0.0, apex_.y - y1});
    if (gap_x * gap_x + gap_y * gap_y > far_sq_) return false;
    if (full_) return true;
    if (apex_.x >= x0 - slack_ && apex_.x <= x1 + slack_ && apex_.y >= y0 - slack_ &&
        apex_.y <= y1 + slack_)
        return true;
    const double xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
    if (fov_ < kPi) {
        // Convex wedge and convex box: they meet iff a corner of the box lies in
        // the wedge or an edge of the wedge crosses the box (the apex is outside).
        for (int i = 0; i < 4; ++i)
            if (inConvexWedge(xs[i], ys[i])) return true;
        return rayMeetsBox(edge_cw_, x0, y0, x1, y1) || rayMeetsBox(edge_ccw_, x0, y0, x1, y1);
    }
    // A box misses a wedge of 180 degrees or more iff it lies in the open convex
    // complement, i.e. all its corners do.
    for (int i = 0; i < 4; ++i)
        if (!strictlyInComplement(xs[i], ys[i])) return true;
    return false;
}

bool RgvcWedge::touchesVoxel(const RegularGrid& grid, glm::i64vec2 v) const {
    const glm::dvec3& o = grid.world.min;
    const double x0 = o.x + double(v.x) * voxel_size_.x, y0 = o.y + double(v.y) * voxel_size_.y;
    return touchesBox(x0, y0, x0 + voxel_size_.x, y0 + voxel_size_.y);
}

int64_t RgvcWedge::exitIndex(const RegularGrid& grid, glm::i64vec2 viewer, int64_t k,
                             glm::dvec2 dir) const {
    const glm::dvec3 d = grid.voxelSize();
    const glm::dvec3& o = grid.world.min;
    // The outer square of ring k: voxels viewer - k .. viewer + k on both axes.
    const double lo_x = o.x + double(viewer.x - k) * d.x,
                 hi_x = o.x + double(viewer.x + k + 1) * d.x;
    const double lo_y = o.y + double(viewer.y - k) * d.y,
                 hi_y = o.y + double(viewer.y + k + 1) * d.y;
    const double inf = std::numeric_limits<double>::infinity();
    const double tx = dir.x > 0.0   ? (hi_x - apex_.x) / dir.x
                      : dir.x < 0.0 ? (lo_x - apex_.x) / dir.x
                                    : inf;
    const double ty = dir.y > 0.0   ? (hi_y - apex_.y) / dir.y
                      : dir.y < 0.0 ? (lo_y - apex_.y) / dir.y
                                    : inf;
    const double t = std::max(0.0, std::min(tx, ty));
    auto relative = [&](double world, double origin, double size, int64_t centre) {
        const double cell = std::floor((world - origin) / size) - double(centre);
        return int64_t(std::clamp(cell, double(-k), double(k)));
    };
    glm::i64vec2 rel;
    if (tx <= ty) {
        rel.x = dir.x > 0.0 ? k : -k;
        rel.y = relative(apex_.y + t * dir.y, o.y, d.y, viewer.y);
    } else {
        rel.y = dir.y > 0.0 ? k : -k;
        rel.x = relative(apex_.x + t * dir.x, o.x, d.x, viewer.x);
    }
    return ringIndex(rel);
}

RingRun RgvcWedge::layerRun(const RegularGrid& grid, glm::i64vec2 viewer, int64_t k) const {
    const int64_t n = ringSize(k);
    if (k == 0) return {0, 1, 0, 0};
    if (full_) return {0, n, 0, n};
    // A viewpoint on a face or corner of its voxel touches neighbours in ring 1
    // whatever the wedge's direction; ring 1 is short, take all of it.
    if (k == 1) return {0, n, 0, 0};
    const int64_t p_cw = exitIndex(grid, viewer, k, edge_cw_);
    const int64_t p_ccw = exitIndex(grid, viewer, k, edge_ccw_);
    // The wedge runs counter-clockwise from its clockwise edge to the other one.
    int64_t start = p_cw, span = positiveMod(p_ccw - p_cw, n);
    bool trusted = true;
    if (fov_ < kPi && span > 6 * k) {
        // A narrow wedge whose edges rounding put in the wrong order.
        start = p_ccw;
        span = positiveMod(p_cw - p_ccw, n);
        trusted = false;
    } else if (fov_ >= kPi && span < 2 * k) {
        // Half a turn or more can never be this short: the edges wrapped round.
        return {0, n, 0, 0};
    }
    RingRun run;
    run.length = span + 2 * kRunMargin + 1;
    run.start = positiveMod(start - kRunMargin, n);
    if (run.length >= n) run.start = 0, run.length = n;
    if (trusted && span + 1 > 2 * kRunMargin) {
        run.inner_start = positiveMod(start + kRunMargin, n);
        run.inner_length = span + 1 - 2 * kRunMargin;
    }
    return run;
}

bool RgvcWedge::layerWithinFar(const RegularGrid& grid, glm::i64vec2 viewer, int64_t k) const {
    const glm::dvec3& o = grid.world.min;
    const double lo_x = o.x + double(viewer.x - k) * voxel_size_.x - apex_.x;
    const double hi_x = o.x + double(viewer.x + k + 1) * voxel_size_.x - apex_.x;
    const double lo_y = o.y + double(viewer.y - k) * voxel_size_.y - apex_.y;
    const double hi_y = o.y + double(viewer.y + k + 1) * voxel_size_.y - apex_.y;
    const double dx = std::max(-lo_x, hi_x), dy = std::max(-lo_y, hi_y);
    return dx * dx + dy * dy <= far_ * far_;
}

void RgvcWedge::bounds(double& x0, double& y0, double& x1, double& y1) const {
    x0 = x1 = apex_.x;
    y0 = y1 = apex_.y;
    auto add = [&](glm::dvec2 dir) {
        x0 = std::min(x0, apex_.x + far_ * dir.x), x1 = std::max(x1, apex_.x + far_ * dir.x);
        y0 = std::min(y0, apex_.y + far_ * dir.y), y1 = std::max(y1, apex_.y + far_ * dir.y);
    };
    add(edge_cw_);
    add(edge_ccw_);
    const glm::dvec2 axes[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    for (const glm::dvec2& axis : axes) {
        const glm::dvec2 p = apex_ + axis;
        const bool in =
            full_ || (fov_ < kPi ? inConvexWedge(p.x, p.y) : !strictlyInComplement(p.x, p.y));
        if (in) add(axis);
    }
    x0 -= slack_, y0 -= slack_, x1 += slack_, y1 += slack_;
}

}  // namespace gridcull
