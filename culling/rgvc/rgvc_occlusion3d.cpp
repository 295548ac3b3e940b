// The direction map of 3D regular-grid occlusion; see rgvc_occlusion3d.h.
#include "culling/rgvc/rgvc_occlusion3d.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>

namespace gridcull {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The cell holding direction coordinate u in [-1, 1] on a face of R cells. A
// value on a boundary gives the cell above it: as a range's low end that cell is
// the first one the range meets, and as its high end that cell touches the range
// at its edge and is included, which only makes the test stricter.
int cellOf(double u, int r) {
    return std::clamp(int(std::floor((u + 1.0) * 0.5 * r)), 0, r - 1);
}

// Distance from e to the interval [lo, hi] (0 inside).
double gap(double e, double lo, double hi) {
    return e < lo ? lo - e : (e > hi ? e - hi : 0.0);
}

}  // namespace

int RgvcDirectionMap::resolutionFor(int longest) {
    // A voxel at the far side of the grid spans about 2 / longest of a face's
    // [-1, 1] from a viewer at the other side.
    return std::clamp(longest * kDirectionMapCellsPerVoxel, kMinDirectionMapResolution,
                      kMaxDirectionMapResolution);
}

void RgvcDirectionMap::resize(int resolution) {
    resolution_ = resolution;
    cells_.resize(resolution, resolution, 6);
    tried_.assign(size_t(resolution) * size_t(resolution) * 6, 0);
}

void RgvcDirectionMap::begin(const glm::dvec3& eye) {
    eye_ = eye;
    cells_.clearAll();
    for (int face = 0; face < 6; ++face) {
        DirectionRect& b = covered_bounds_[size_t(face)];
        b.face = face;
        b.i0 = b.j0 = resolution_;
        b.i1 = b.j1 = -1;
    }
}

uint32_t RgvcDirectionMap::restartPasses() {
    std::fill(tried_.begin(), tried_.end(), 0u);
    return 1;
}

int RgvcDirectionMap::footprint(const glm::dvec3& lo, const glm::dvec3& hi,
                                std::array<DirectionRect, 6>& out) const {
    // A box wholly inside one face's pyramid (depth along the face's axis above
    // the offset on both other axes at every corner) has its footprint on that
    // face alone: the common case, one face instead of six.
    const glm::dvec3 c = (lo + hi) * 0.5 - eye_;
    const glm::dvec3 ac = glm::abs(c);
    const int dominant = ac.x >= ac.y ? (ac.x >= ac.z ? 0 : 2) : (ac.y >= ac.z ? 1 : 2);
    const int only = 2 * dominant + (c[dominant] >= 0.0 ? 0 : 1);
    {
        const int a = dominant, b = (a + 1) % 3, cc = (a + 2) % 3;
        const double near_depth = c[a] >= 0.0 ? lo[a] - eye_[a] : eye_[a] - hi[a];
        const double reach_b = std::max(std::abs(lo[b] - eye_[b]), std::abs(hi[b] - eye_[b]));
        const double reach_c = std::max(std::abs(lo[cc] - eye_[cc]), std::abs(hi[cc] - eye_[cc]));
        if (near_depth > reach_b && near_depth > reach_c)
            return faceFootprint(only, lo, hi, out[0]);
    }
    int n = 0;
    for (int face = 0; face < 6; ++face) {
        const int r = faceFootprint(face, lo, hi, out[size_t(n)]);
        if (r < 0) return -1;
        n += r;
    }
    return n;
}

int RgvcDirectionMap::faceFootprint(int face, const glm::dvec3& lo, const glm::dvec3& hi,
                                    DirectionRect& r) const {
    const int a = face / 2, b = (a + 1) % 3, c = (a + 2) % 3;
    const double s = (face % 2 == 0) ? 1.0 : -1.0;
    // Depth along the face's axis over the box.
    const double d0 = s > 0 ? lo[a] - eye_[a] : eye_[a] - hi[a];
    const double d1 = s > 0 ? hi[a] - eye_[a] : eye_[a] - lo[a];
    if (d1 <= 0.0) return 0;  // wholly behind this face's half-space
    // Points whose direction lies on this face have depth >= |offset| on both
    // in-face axes, hence at least the box's gap to the eye on them.
    const double m = std::max({d0, gap(eye_[b], lo[b], hi[b]), gap(eye_[c], lo[c], hi[c])});
    if (m > d1) return 0;  // no point of the box has its direction here
    if (!(m > 0.0)) return -1;
    // u = offset_b / depth over offset in [lo_b, hi_b] - eye_b, depth in [m, d1]:
    // its extremes are at the corners.
    const double im = 1.0 / m, id1 = 1.0 / d1;
    auto range = [&](int axis, double& r0, double& r1) {
        const double o0 = lo[axis] - eye_[axis], o1 = hi[axis] - eye_[axis];
        r0 = std::min(o0 * (o0 < 0.0 ? im : id1), o1 * (o1 < 0.0 ? im : id1));
        r1 = std::max(o0 * (o0 < 0.0 ? id1 : im), o1 * (o1 < 0.0 ? id1 : im));
    };
    double u0, u1, v0, v1;
    range(b, u0, u1);
    range(c, v0, v1);
    if (u1 < -1.0 || u0 > 1.0 || v1 < -1.0 || v0 > 1.0) return 0;
    r.face = face;
    r.i0 = cellOf(std::max(u0, -1.0), resolution_);
    r.i1 = cellOf(std::min(u1, 1.0), resolution_);
    r.j0 = cellOf(std::max(v0, -1.0), resolution_);
    r.j1 = cellOf(std::min(v1, 1.0), resolution_);
    return 1;
}

void RgvcDirectionMap::cellOfPoint(const glm::dvec3& p, int& face, int& i, int& j) const {
    const glm::dvec3 c = p - eye_;
    const glm::dvec3 ac = glm::abs(c);
    const int a = ac.x >= ac.y ? (ac.x >= ac.z ? 0 : 2) : (ac.y >= ac.z ? 1 : 2);
    face = 2 * a + (c[a] >= 0.0 ? 0 : 1);
    const double depth = ac[a] > 0.0 ? ac[a] : 1.0;
    i = cellOf(c[(a + 1) % 3] / depth, resolution_);
    j = cellOf(c[(a + 2) % 3] / depth, resolution_);
}

bool RgvcDirectionMap::coversBox(const glm::dvec3& lo, const glm::dvec3& hi) const {
    // Most boxes a traversal reaches are not covered: the cell of the box's
    // centre direction says so in O(1).
    const glm::dvec3 c = (lo + hi) * 0.5 - eye_;
    const glm::dvec3 ac = glm::abs(c);
    const int a = ac.x >= ac.y ? (ac.x >= ac.z ? 0 : 2) : (ac.y >= ac.z ? 1 : 2);
    if (ac[a] > 0.0) {
        const int face = 2 * a + (c[a] >= 0.0 ? 0 : 1);
        const DirectionRect& b = covered_bounds_[size_t(face)];
        if (b.empty()) return false;
        // The centre's face coordinates against the covered cells' bounds,
        // multiplied out: u = c_b / depth lies in [u(i0), u(i1 + 1)].
        const double step = 2.0 / resolution_, depth = ac[a];
        const double cb = c[(a + 1) % 3], cc = c[(a + 2) % 3];
        if (cb < (-1.0 + step * b.i0) * depth || cb > (-1.0 + step * (b.i1 + 1)) * depth ||
            cc < (-1.0 + step * b.j0) * depth || cc > (-1.0 + step * (b.j1 + 1)) * depth)
            return false;
        int f, i, j;
        cellOfPoint(lo + (hi - lo) * 0.5, f, i, j);
        if (!covered(f, i, j)) return false;
    }
    std::array<DirectionRect, 6> rects;
    const int n = footprint(lo, hi, rects);
    if (n <= 0) return false;
    for (int k = 0; k < n; ++k) {
        const DirectionRect& r = rects[size_t(k)];
        for (int j = r.j0; j <= r.j1; ++j)
            if (!cells_.allSet(cells_.row(j, r.face), r.i0, r.i1)) return false;
    }
    return true;
}

void RgvcDirectionMap::setFrustum(const std::array<glm::dvec3, 4>& edges) {
    for (int face = 0; face < 6; ++face) {
        const int a = face / 2, b = (a + 1) % 3, c = (a + 2) % 3;
        const double s = (face % 2 == 0) ? 1.0 : -1.0;
        DirectionRect& r = frustum_cells_[size_t(face)];
        r.face = face;
        int ahead = 0;
        double u0 = 1.0, u1 = -1.0, v0 = 1.0, v1 = -1.0;
        for (const glm::dvec3& e : edges) {
            if (!(s * e[a] > 0.0)) continue;
            ++ahead;
            const double u = e[b] / (s * e[a]), v = e[c] / (s * e[a]);
            u0 = std::min(u0, u), u1 = std::max(u1, u);
            v0 = std::min(v0, v), v1 = std::max(v1, v);
        }
        if (ahead == 0) {
            // The cone of four edges wider than a half-space cannot be; none
            // ahead means the frustum has no direction on this face.
            r.i0 = 0, r.i1 = -1, r.j0 = 0, r.j1 = -1;
        } else if (ahead < 4) {
            // Some edges point away from the face: the cone meets its plane in
            // an unbounded region, so take the whole face.
            r.i0 = 0, r.i1 = resolution_ - 1, r.j0 = 0, r.j1 = resolution_ - 1;
        } else if (u1 < -1.0 || u0 > 1.0 || v1 < -1.0 || v0 > 1.0) {
            r.i0 = 0, r.i1 = -1, r.j0 = 0, r.j1 = -1;
        } else {
            // A convex cone with every edge ahead projects to the hull of the
            // edges' projections.
            r.i0 = cellOf(std::max(u0, -1.0), resolution_);
            r.i1 = cellOf(std::min(u1, 1.0), resolution_);
            r.j0 = cellOf(std::max(v0, -1.0), resolution_);
            r.j1 = cellOf(std::min(v1, 1.0), resolution_);
        }
    }
}

bool RgvcDirectionMap::clipToFrustum(DirectionRect& rect, int margin) const {
    const DirectionRect& f = frustum_cells_[size_t(rect.face)];
    if (f.empty()) return false;
    rect.i0 = std::max(rect.i0, f.i0 - margin);
    rect.i1 = std::min(rect.i1, f.i1 + margin);
    rect.j0 = std::max(rect.j0, f.j0 - margin);
    rect.j1 = std::min(rect.j1, f.j1 + margin);
    return !rect.empty();
}

bool RgvcDirectionMap::mayCoverPartOf(const glm::dvec3& lo, const glm::dvec3& hi) const {
    std::array<DirectionRect, 6> rects;
    const int n = footprint(lo, hi, rects);
    if (n < 0) return true;
    for (int k = 0; k < n; ++k) {
        const DirectionRect& r = rects[size_t(k)];
        const DirectionRect& b = covered_bounds_[size_t(r.face)];
        if (!b.empty() && r.i0 <= b.i1 && r.i1 >= b.i0 && r.j0 <= b.j1 && r.j1 >= b.j0) return true;
    }
    return false;
}

DirectionCell RgvcDirectionMap::cell(int face, int i, int j) const {
    const double step = 2.0 / resolution_;
    DirectionCell c;
    c.face = face;
    c.i = i;
    c.j = j;
    c.u0 = -1.0 + step * i;
    c.u1 = i + 1 == resolution_ ? 1.0 : -1.0 + step * (i + 1);
    c.v0 = -1.0 + step * j;
    c.v1 = j + 1 == resolution_ ? 1.0 : -1.0 + step * (j + 1);
    return c;
}

bool cellOnPlane(const DirectionCell& cell, const glm::dvec3& eye, int axis, double plane,
                 PlaneRect& out) {
    const int fa = cell.face / 2, fb = (fa + 1) % 3, fc = (fa + 2) % 3;
    const double s = (cell.face % 2 == 0) ? 1.0 : -1.0;
    // Each direction component as an interval: r_fa = s, r_fb = u, r_fc = v.
    double r_lo[3], r_hi[3];
    r_lo[fa] = r_hi[fa] = s;
    r_lo[fb] = cell.u0, r_hi[fb] = cell.u1;
    r_lo[fc] = cell.v0, r_hi[fc] = cell.v1;
    const double dist = plane - eye[axis];
    // The ray parameter t = dist / r_axis must be > 0 for some direction.
    double t0, t1;
    const double ra0 = r_lo[axis], ra1 = r_hi[axis];
    if (dist == 0.0) return false;
    if (dist > 0.0) {
        if (ra1 <= 0.0) return false;
        t0 = dist / ra1;
        t1 = ra0 > 0.0 ? dist / ra0 : kInf;
    } else {
        if (ra0 >= 0.0) return false;
        t0 = dist / ra0;
        t1 = ra1 < 0.0 ? dist / ra1 : kInf;
    }
    for (int k = 0; k < 2; ++k) {
        const int other = (axis + 1 + k) % 3;
        // eye + t * r over t in [t0, t1] and r in [r_lo, r_hi]: extremes at corners.
        double lo = kInf, hi = -kInf;
        for (const double t : {t0, t1})
            for (const double r : {r_lo[other], r_hi[other]}) {
                // t = inf times r = 0 stays at the eye's coordinate on that side.
                const double p = r == 0.0 ? 0.0 : t * r;
                lo = std::min(lo, p);
                hi = std::max(hi, p);
            }
        out.lo[k] = eye[other] + lo;
        out.hi[k] = eye[other] + hi;
    }
    return true;
}

}  // namespace gridcull
