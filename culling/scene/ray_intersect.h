// Exact ray-shape intersections, shared by the exact oracle (culling/oracle/exact_oracle.h)
// and ray picking (culling/scene/ray_pick.h) so that what the GUI hovers is what the
// oracle sees.
//
// A ray is origin + s * dir. `dir` need not be unit length: every parameter s is
// in units of |dir|. The 3D oracle passes directions whose forward component is 1,
// so s is the view depth directly; the 2D sweep and picking pass unit directions,
// so s is a distance. World units; 2D callers pass z = 0 in every point and vector.
//
// Solids: spheres, boxes and (2D) polygons are solid, so a ray that starts inside
// one meets it at once (solidEntry). Triangles are two-sided surfaces.
//
// All functions are inline, allocation-free and O(1) except the polygon ones,
// which are O(points).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "grid/aabb.h"

namespace gridcull {

// The roots s0 <= s1 of a*s^2 - 2*b*s + k = 0: where the line origin + s*dir
// meets a sphere, with a = |dir|^2, b = dir . (center - origin) and
// k = |center - origin|^2 - radius^2 (k <= 0 when the origin is inside).
// False when the line misses the sphere or a <= 0.
inline bool solveSphereQuadratic(double a, double b, double k, double& s0, double& s1) {
    if (!(a > 0.0)) return false;
    const double disc = b * b - a * k;
    if (disc < 0.0) return false;
    const double root = std::sqrt(disc);
    s0 = (b - root) / a;
    s1 = (b + root) / a;
    return true;
}

// The interval [s0, s1] of the whole line origin + s*dir inside a solid sphere.
inline bool lineSphere(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& center,
                       double radius, double& s0, double& s1) {
    const glm::dvec3 oc = center - origin;
    return solveSphereQuadratic(glm::dot(dir, dir), glm::dot(dir, oc),
                                glm::dot(oc, oc) - radius * radius, s0, s1);
}

// The interval [s0, s1] of the whole line inside a solid axis-aligned box (slab
// test). A zero direction component keeps the line in its slab or misses it, so a
// 2D box (z min == max == 0) is hit by a 2D line (origin.z == 0, dir.z == 0).
inline bool lineBox(const glm::dvec3& origin, const glm::dvec3& dir, const Aabb& box, double& s0,
                    double& s1) {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (dir[axis] == 0.0) {
            if (origin[axis] < box.min[axis] || origin[axis] > box.max[axis]) return false;
            continue;
        }
        const double inv = 1.0 / dir[axis];
        double t0 = (box.min[axis] - origin[axis]) * inv;
        double t1 = (box.max[axis] - origin[axis]) * inv;
        if (t0 > t1) std::swap(t0, t1);
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
        if (lo > hi) return false;
    }
    s0 = lo;
    s1 = hi;
    return true;
}

// Where a ray first meets a solid whose line interval is [s0, s1], counting only
// parameters in [s_min, s_max] (the oracle's [near, far]; picking's [0, inf)).
// A ray that starts inside the solid (s0 <= 0 <= s1) meets it at s_min: a camera
// inside a solid sees nothing else. So does a ray whose first counted point
// s_min already lies inside. Returns false when the solid is not met in range.
inline bool solidEntry(double s0, double s1, double s_min, double s_max, double& s) {
    if (s0 <= 0.0 && s1 >= 0.0) {
        s = s_min;
        return true;
    }
    if (s1 < s_min) return false;
    s = std::max(s0, s_min);
    return s <= s_max;
}

// Two-sided ray-triangle intersection (Moller-Trumbore): the line parameter s of
// the hit, any sign. False when the line misses or is parallel to the triangle.
// Edges and vertices count as hits.
inline bool lineTriangle(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a,
                         const glm::dvec3& b, const glm::dvec3& c, double& s) {
    const glm::dvec3 e1 = b - a;
    const glm::dvec3 e2 = c - a;
    const glm::dvec3 p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0) return false;
    const double inv_det = 1.0 / det;
    const glm::dvec3 to_origin = origin - a;
    const double u = glm::dot(to_origin, p) * inv_det;
    if (u < 0.0 || u > 1.0) return false;
    const glm::dvec3 q = glm::cross(to_origin, e1);
    const double v = glm::dot(dir, q) * inv_det;
    if (v < 0.0 || u + v > 1.0) return false;
    s = glm::dot(e2, q) * inv_det;
    return true;
}

// 2D (x-y): the parameter s >= 0 where the ray meets the segment [a, b], ends
// included. A ray parallel to the segment misses it; where it runs along a
// polygon's edge it still meets the neighbouring edges at the shared vertices.
inline bool raySegment2d(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a,
                         const glm::dvec3& b, double& s) {
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double denom = dir.x * ey - dir.y * ex;
    if (denom == 0.0) return false;
    const double wx = a.x - origin.x, wy = a.y - origin.y;
    const double ray_s = (wx * ey - wy * ex) / denom;
    const double seg_u = (wx * dir.y - wy * dir.x) / denom;
    if (ray_s < 0.0 || seg_u < 0.0 || seg_u > 1.0) return false;
    s = ray_s;
    return true;
}

// 2D: is p inside the simple polygon points[i] + offset (even-odd crossing rule)?
// Points on the boundary may go either way.
inline bool pointInPolygon2d(const glm::dvec3& p, const glm::dvec3* points, size_t count,
                             const glm::dvec3& offset) {
    bool inside = false;
    for (size_t i = 0, j = count - 1; i < count; j = i++) {
        const double xi = points[i].x + offset.x, yi = points[i].y + offset.y;
        const double xj = points[j].x + offset.x, yj = points[j].y + offset.y;
        if ((yi > p.y) != (yj > p.y)) {
            const double x_cross = xi + (p.y - yi) * (xj - xi) / (yj - yi);
            if (p.x < x_cross) inside = !inside;
        }
    }
    return inside;
}

// 2D: the nearest s >= 0 where the ray meets the boundary of the polygon
// points[i] + offset, ignoring whether the origin is inside (callers decide that
// once per polygon with pointInPolygon2d). False when no edge is met.
inline bool rayPolygonEdges2d(const glm::dvec3& origin, const glm::dvec3& dir,
                              const glm::dvec3* points, size_t count, const glm::dvec3& offset,
                              double& s) {
    bool hit = false;
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0, j = count - 1; i < count; j = i++) {
        double edge_s;
        if (raySegment2d(origin, dir, points[j] + offset, points[i] + offset, edge_s) &&
            edge_s < best) {
            best = edge_s;
            hit = true;
        }
    }
    if (hit) s = best;
    return hit;
}

}  // namespace gridcull
