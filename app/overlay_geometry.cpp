#include "app/overlay_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace gridcull {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kCircleSegments = 48;
constexpr int kArcSegmentsPerTurn = 96;

}  // namespace

void appendSegment(std::vector<ColorVertex>& lines, const glm::dvec3& a, const glm::dvec3& b,
                   const glm::vec4& color) {
    lines.push_back({glm::vec3(a), color});
    lines.push_back({glm::vec3(b), color});
}

void appendBoxEdges(std::vector<ColorVertex>& lines, const Aabb& box, const glm::vec4& color) {
    const glm::dvec3 lo = box.min, hi = box.max;
    auto corner = [&](int i) {
        return glm::dvec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    };
    const bool flat = lo.z == hi.z;
    for (int i = 0; i < 8; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            const int j = i | (1 << axis);
            if (j == i || (flat && (axis == 2 || (i & 4)))) continue;
            appendSegment(lines, corner(i), corner(j), color);
        }
    }
}

void appendOutline2d(std::vector<ColorVertex>& lines, const Scene& scene,
                     const SceneObject& object, double t, const glm::vec4& color) {
    const glm::dvec3 d = scene.displacementAt(object, t);
    switch (object.shape) {
    case ShapeKind::Sphere: {
        const glm::dvec3 c = object.center + d;
        for (int i = 0; i < kCircleSegments; ++i) {
            const double a0 = 2.0 * kPi * i / kCircleSegments;
            const double a1 = 2.0 * kPi * (i + 1) / kCircleSegments;
            appendSegment(lines, c + object.radius * glm::dvec3(std::cos(a0), std::sin(a0), 0.0),
                          c + object.radius * glm::dvec3(std::cos(a1), std::sin(a1), 0.0), color);
        }
        break;
    }
    case ShapeKind::Polygon:
        for (size_t i = 0; i < object.points.size(); ++i) {
            appendSegment(lines, object.points[i] + d,
                          object.points[(i + 1) % object.points.size()] + d, color);
        }
        break;
    case ShapeKind::Box:
    case ShapeKind::Mesh: appendBoxEdges(lines, object.bounds.translated(d), color); break;
    }
}

void appendGridLines2d(std::vector<ColorVertex>& lines, const RegularGrid& grid,
                       const glm::vec4& color) {
    const glm::dvec3 lo = grid.world.min, hi = grid.world.max;
    const glm::dvec3 step = grid.voxelSize();
    for (int i = 0; i <= grid.resolution.x; ++i) {
        const double x = i == grid.resolution.x ? hi.x : lo.x + i * step.x;
        appendSegment(lines, {x, lo.y, 0.0}, {x, hi.y, 0.0}, color);
    }
    for (int j = 0; j <= grid.resolution.y; ++j) {
        const double y = j == grid.resolution.y ? hi.y : lo.y + j * step.y;
        appendSegment(lines, {lo.x, y, 0.0}, {hi.x, y, 0.0}, color);
    }
}

double viewDrawDistance(const Camera& camera, const Aabb& world) {
    double farthest = 0.0;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner(i & 1 ? world.max.x : world.min.x, i & 2 ? world.max.y : world.min.y,
                                i & 4 ? world.max.z : world.min.z);
        farthest = std::max(farthest, glm::length(corner - camera.position));
    }
    return std::max(std::min(camera.far, farthest), camera.near);
}

namespace {

// Where the ray p + s * d (s >= 0) leaves `box`, in units of |d|. False when the
// ray misses the box.
bool rayExitsBox(const glm::dvec3& p, const glm::dvec3& d, const Aabb& box, double& exit) {
    double lo = 0.0, hi = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0) {
            if (p[axis] < box.min[axis] || p[axis] > box.max[axis]) return false;
            continue;
        }
        const double a = (box.min[axis] - p[axis]) / d[axis];
        const double b = (box.max[axis] - p[axis]) / d[axis];
        lo = std::max(lo, std::min(a, b));
        hi = std::min(hi, std::max(a, b));
    }
    if (hi < lo) return false;
    exit = hi;
    return true;
}

}  // namespace

void appendFrustum(std::vector<ColorVertex>& lines, const Camera& camera, const Aabb& world,
                   const glm::vec4& color) {
    glm::dvec3 right, up, fwd;
    camera.basis(right, up, fwd);
    const double tan_y = std::tan(camera.fov_deg * kPi / 360.0);
    const double tan_x = tan_y * camera.aspect;
    // Edge directions with a forward component of 1: s along them is view depth.
    const glm::dvec3 edges[4] = {fwd - right * tan_x - up * tan_y, fwd + right * tan_x - up * tan_y,
                                 fwd + right * tan_x + up * tan_y, fwd - right * tan_x + up * tan_y};
    const double fallback = std::max(glm::dot(world.center() - camera.position, fwd), camera.near);
    double depth[4];
    double inside_depth = camera.far;
    for (int i = 0; i < 4; ++i) {
        double exit = 0.0;
        depth[i] = rayExitsBox(camera.position, edges[i], world, exit) ? exit : fallback;
        depth[i] = std::clamp(depth[i], camera.near, camera.far);
        inside_depth = std::min(inside_depth, depth[i]);
    }
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4;
        appendSegment(lines, camera.position, camera.position + edges[i] * depth[i], color);
        appendSegment(lines, camera.position + edges[i] * camera.near,
                      camera.position + edges[j] * camera.near, color);
        appendSegment(lines, camera.position + edges[i] * inside_depth,
                      camera.position + edges[j] * inside_depth, color);
    }
    // The view axis, dimmer, out to where it leaves the world: in a flat world the
    // edges leave through floor and ceiling early, and the axis still shows how
    // far the camera looks.
    double axis_depth = inside_depth;
    if (rayExitsBox(camera.position, fwd, world, axis_depth))
        axis_depth = std::clamp(axis_depth, camera.near, camera.far);
    appendSegment(lines, camera.position, camera.position + fwd * axis_depth,
                  glm::vec4(glm::vec3(color), color.a * 0.6f));
}

void appendWedge(std::vector<ColorVertex>& lines, std::vector<ColorVertex>& fill,
                 const Camera& camera, double distance, const glm::vec4& color,
                 const glm::vec4& fill_color) {
    const glm::dvec3 fwd = camera.forward();
    const double heading = std::atan2(fwd.y, fwd.x);
    const double half = std::min(camera.fov_deg, 360.0) * kPi / 360.0;
    const int segments = std::max(4, int(std::ceil(kArcSegmentsPerTurn * half / kPi)));
    const glm::dvec3 apex(camera.position.x, camera.position.y, 0.0);
    auto at = [&](int i) {
        const double a = heading - half + 2.0 * half * i / segments;
        return apex + distance * glm::dvec3(std::cos(a), std::sin(a), 0.0);
    };
    const bool full_turn = camera.fov_deg >= 360.0;
    if (!full_turn) {
        appendSegment(lines, apex, at(0), color);
        appendSegment(lines, apex, at(segments), color);
    }
    for (int i = 0; i < segments; ++i) {
        appendSegment(lines, at(i), at(i + 1), color);
        fill.push_back({glm::vec3(apex), fill_color});
        fill.push_back({glm::vec3(at(i)), fill_color});
        fill.push_back({glm::vec3(at(i + 1)), fill_color});
    }
    appendSegment(lines, apex, apex + fwd * (distance * 0.25),
                  glm::vec4(glm::vec3(color), color.a * 0.6f));
}

}  // namespace gridcull
