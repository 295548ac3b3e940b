// Occluder extension and occlusion polygons (Batagelo & Wu, sections 4.3 and
// 4.4); the header says where this departs from the paper.
#include "culling/rgvc/rgvc_occlusion.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace gridcull {

namespace {

double cross(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

HalfPlane2 unitPlane(double nx, double ny, glm::dvec2 through) {
    const double len = std::hypot(nx, ny);
    nx /= len;
    ny /= len;
    return {nx, ny, nx * through.x + ny * through.y};
}

struct Rect {
    double x0, y0, x1, y1;
};

Rect voxelRect(const RegularGrid& grid, glm::ivec2 a, glm::ivec2 b) {
    const glm::dvec3 d = grid.voxelSize();
    const glm::dvec3& o = grid.world.min;
    const glm::ivec2 lo = glm::min(a, b), hi = glm::max(a, b);
    return {o.x + lo.x * d.x, o.y + lo.y * d.y, o.x + (hi.x + 1) * d.x, o.y + (hi.y + 1) * d.y};
}

// The two wedge planes between the rays from `apex` through s1 and s2; false
// when the rays are (nearly) parallel, which leaves no usable wedge.
bool wedgePlanes(glm::dvec2 apex, glm::dvec2 s1, glm::dvec2 s2, RgvcOcclusionPolygon& poly) {
    glm::dvec2 u = s1 - apex, v = s2 - apex;
    const double c = cross(u, v);
    if (!(std::abs(c) > 1e-12 * glm::dot(u, u) + 1e-12 * glm::dot(v, v))) return false;
    if (c < 0.0) std::swap(u, v);
    // Left of apex->u: cross(u, p - apex) >= 0; right of apex->v: cross(p - apex, v) >= 0.
    poly.planes[size_t(poly.plane_count++)] = unitPlane(-u.y, u.x, apex);
    poly.planes[size_t(poly.plane_count++)] = unitPlane(v.y, -v.x, apex);
    return true;
}

// The region hidden by one rectangle; false when the apex lies in or on it.
bool rectShadow(const Rect& r, glm::dvec2 apex, double slack, RgvcOcclusionPolygon& poly) {
    if (apex.x >= r.x0 - slack && apex.x <= r.x1 + slack && apex.y >= r.y0 - slack &&
        apex.y <= r.y1 + slack)
        return false;
    const glm::dvec2 corners[4] = {{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}};
    // Silhouettes: the corner every other corner is counter-clockwise of, and the
    // one every other corner is clockwise of.
    int first = -1, last = -1;
    for (int i = 0; i < 4; ++i) {
        bool all_ccw = true, all_cw = true;
        for (int j = 0; j < 4; ++j) {
            const double c = cross(corners[i] - apex, corners[j] - apex);
            all_ccw = all_ccw && c >= 0.0;
            all_cw = all_cw && c <= 0.0;
        }
        if (all_ccw && first < 0) first = i;
        if (all_cw && last < 0) last = i;
    }
    if (first < 0 || last < 0) return false;
    poly = RgvcOcclusionPolygon{};
    poly.apex = apex;
    if (!wedgePlanes(apex, corners[first], corners[last], poly)) return false;
    // The faces turned to the apex.
    if (apex.x < r.x0) poly.planes[size_t(poly.plane_count++)] = {1.0, 0.0, r.x0};
    if (apex.x > r.x1) poly.planes[size_t(poly.plane_count++)] = {-1.0, 0.0, -r.x1};
    if (apex.y < r.y0) poly.planes[size_t(poly.plane_count++)] = {0.0, 1.0, r.y0};
    if (apex.y > r.y1) poly.planes[size_t(poly.plane_count++)] = {0.0, -1.0, -r.y1};
    poly.outline[size_t(poly.outline_count++)] = corners[first];
    if (poly.plane_count == 4) {
        // Two faces: they meet at the corner nearest the apex.
        const glm::dvec2 front{apex.x < r.x0 ? r.x0 : r.x1, apex.y < r.y0 ? r.y0 : r.y1};
        poly.outline[size_t(poly.outline_count++)] = front;
    }
    poly.outline[size_t(poly.outline_count++)] = corners[last];
    return true;
}

}  // namespace

bool RgvcExtendedOccluder::covers(glm::ivec2 v) const {
    for (int i = 0; i < part_count; ++i) {
        const RgvcOccluderL& l = parts[size_t(i)];
        if (v.y == l.corner.y) {
            const int along = (v.x - l.corner.x) * -toward.x;
            if (along >= 0 && along <= l.leg_x) return true;
        }
        if (v.x == l.corner.x) {
            const int along = (v.y - l.corner.y) * -toward.y;
            if (along >= 0 && along <= l.leg_y) return true;
        }
    }
    return false;
}

int RgvcExtendedOccluder::voxelCount() const {
    int n = 0;
    for (int i = 0; i < part_count; ++i) n += 1 + parts[size_t(i)].leg_x + parts[size_t(i)].leg_y;
    return n - (part_count - 1);  // the Ls of a staircase share the initial voxel
}

bool RgvcOcclusionPolygon::containsPoint(glm::dvec2 p, double margin) const {
    for (int i = 0; i < plane_count; ++i)
        if (!(planes[size_t(i)].eval(p.x, p.y) > margin)) return false;
    return plane_count > 0;
}

namespace {

// The occlusion polygons of one L (its corner facing `toward`), appended to
// out[n..): one when the apex lies in the quadrant the corner faces, else one
// per leg. Returns the new n.
int lShadows(const RgvcOccluderL& l, glm::ivec2 toward, const RegularGrid& grid, glm::dvec2 apex,
             RgvcOcclusionPolygons& out, int n) {
    const glm::dvec3 d = grid.voxelSize();
    const double slack = kOcclusionSlack * std::max(d.x, d.y);
    const glm::ivec2 x_end = l.corner + glm::ivec2(-toward.x * l.leg_x, 0);
    const glm::ivec2 y_end = l.corner + glm::ivec2(0, -toward.y * l.leg_y);
    const Rect leg_x = voxelRect(grid, l.corner, x_end);
    const Rect leg_y = voxelRect(grid, l.corner, y_end);
    if (l.leg_x == 0 || l.leg_y == 0) {
        // A straight occluder (or one voxel): a single rectangle.
        return rectShadow(l.leg_x > 0 ? leg_x : leg_y, apex, slack, out[size_t(n)]) ? n + 1 : n;
    }
    // The corner of the corner voxel facing the viewer; the legs leave it away
    // from the viewer along +-x and +-y.
    const Rect c = voxelRect(grid, l.corner, l.corner);
    const glm::dvec2 k{toward.x < 0 ? c.x0 : c.x1, toward.y < 0 ? c.y0 : c.y1};
    const bool in_quadrant = (apex.x - k.x) * toward.x >= 0.0 && (apex.y - k.y) * toward.y >= 0.0 &&
                             std::max(std::abs(apex.x - k.x), std::abs(apex.y - k.y)) > slack;
    if (in_quadrant) {
        // Both outer edges face the viewpoint: every ray between the silhouettes
        // a (end of the x leg's outer edge) and b (end of the y leg's) crosses
        // them, so the polygon is the quadrant beyond k cut by the wedge.
        const glm::dvec2 a{toward.x < 0 ? leg_x.x1 : leg_x.x0, k.y};
        const glm::dvec2 b{k.x, toward.y < 0 ? leg_y.y1 : leg_y.y0};
        RgvcOcclusionPolygon& poly = out[size_t(n)];
        poly = RgvcOcclusionPolygon{};
        poly.apex = apex;
        if (wedgePlanes(apex, a, b, poly)) {
            poly.planes[size_t(poly.plane_count++)] = unitPlane(-toward.x, 0.0, k);
            poly.planes[size_t(poly.plane_count++)] = unitPlane(0.0, -toward.y, k);
            poly.outline = {a, k, b};
            poly.outline_count = 3;
            return n + 1;
        }
    }
    if (rectShadow(leg_x, apex, slack, out[size_t(n)])) ++n;
    if (rectShadow(leg_y, apex, slack, out[size_t(n)])) ++n;
    return n;
}

}  // namespace

int occlusionPolygons(const RgvcExtendedOccluder& occ, const RegularGrid& grid, glm::dvec2 apex,
                      RgvcOcclusionPolygons& out) {
    // A staircase's hidden region is the union of its Ls' (the header says why
    // their overlapping polygons are kept rather than a partition).
    int n = 0;
    for (int i = 0; i < occ.part_count; ++i)
        n = lShadows(occ.parts[size_t(i)], occ.toward, grid, apex, out, n);
    return n;
}

}  // namespace gridcull
