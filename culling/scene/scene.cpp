#include "culling/scene/scene.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

namespace gridcull {

const char* shapeName(ShapeKind kind, int dimensions) {
    switch (kind) {
        case ShapeKind::Sphere:
            return dimensions == 2 ? "circle" : "sphere";
        case ShapeKind::Box:
            return "box";
        case ShapeKind::Polygon:
            return "polygon";
        case ShapeKind::Mesh:
            return "mesh";
    }
    return "?";
}

const char* motionName(MotionKind kind) {
    switch (kind) {
        case MotionKind::Static:
            return "static";
        case MotionKind::Linear:
            return "linear";
        case MotionKind::Keyframes:
            return "keyframes";
        case MotionKind::Random:
            return "random";
    }
    return "?";
}

int Scene::indexOf(int id) const {
    const auto it = index_of_id_.find(id);
    return it == index_of_id_.end() ? -1 : it->second;
}

void Scene::finalize() {
    index_of_id_.clear();
    index_of_id_.reserve(objects.size());
    for (size_t i = 0; i < objects.size(); ++i) {
        const bool inserted = index_of_id_.emplace(objects[i].id, int(i)).second;
        assert(inserted && "object ids must be unique (the loader rejects duplicates)");
        (void)inserted;
    }
}

namespace {

// Folds an unbounded displacement `u` along one axis into [lo, hi] as a triangle
// wave: the object bounces off the walls with unchanged speed. lo <= 0 <= hi is
// how far the object's t = 0 bounding box may move before it touches a wall.
// When the box cannot move inside the world on this axis (it is larger than the
// world, or already sticks out of it at t = 0) the axis stays still: bouncing
// would either be undefined or teleport the object, and a still axis keeps the
// maximum speed an upper bound.
double reflectAxis(double u, double lo, double hi) {
    if (lo > 0.0 || hi < 0.0) return 0.0;
    const double span = hi - lo;
    if (!(span > 0.0)) return 0.0;
    double m = std::fmod(u - lo, 2.0 * span);
    if (m < 0.0) m += 2.0 * span;
    if (m > span) m = 2.0 * span - m;
    return lo + m;
}

glm::dvec3 reflectInWorld(const glm::dvec3& u, const Aabb& bounds, const Aabb& world,
                          int dimensions) {
    glm::dvec3 d{0.0};
    const int axes = dimensions == 2 ? 2 : 3;
    for (int axis = 0; axis < axes; ++axis)
        d[axis] = reflectAxis(u[axis], world.min[axis] - bounds.min[axis],
                              world.max[axis] - bounds.max[axis]);
    return d;
}

// The anchor's position on a keyframe path at t: linear between keys, held
// outside them. O(log keys).
glm::dvec3 keyframePosition(const std::vector<PositionKey>& keys, double t) {
    if (t <= keys.front().t) return keys.front().position;
    if (t >= keys.back().t) return keys.back().position;
    const auto after = std::upper_bound(keys.begin(), keys.end(), t,
                                        [](double v, const PositionKey& k) { return v < k.t; });
    const PositionKey& b = *after;
    const PositionKey& a = *(after - 1);
    const double span = b.t - a.t;
    const double f = span > 0.0 ? (t - a.t) / span : 1.0;
    return a.position + (b.position - a.position) * f;
}

// The unreflected displacement of a random walk at t: O(1) with the prefix sums,
// held before t = 0 and after the precomputed span.
glm::dvec3 randomWalkOffset(const Motion& m, double t) {
    const size_t n = m.segment_velocities.size();
    if (n == 0 || !(t > 0.0) || !(m.segment_seconds > 0.0)) return glm::dvec3(0.0);
    const double s = t / m.segment_seconds;
    const bool prefixed = m.segment_offsets.size() == n + 1;
    // Clamp in double first: a huge t must not overflow the integer cast.
    const size_t i = s >= double(n) ? n : size_t(s);
    glm::dvec3 start{0.0};
    if (prefixed) {
        start = m.segment_offsets[i];
    } else {
        // Hand-built motions without prefix sums still work, in O(segments).
        for (size_t k = 0; k < i; ++k) start += m.segment_velocities[k] * m.segment_seconds;
    }
    if (i == n) return start;
    return start + m.segment_velocities[i] * (t - double(i) * m.segment_seconds);
}

}  // namespace

glm::dvec3 Scene::displacementAt(const SceneObject& object, double t) const {
    const Motion& m = object.motion;
    switch (m.kind) {
        case MotionKind::Static:
            return glm::dvec3(0.0);
        case MotionKind::Linear:
            return reflectInWorld(m.velocity * t, object.bounds, grid.world, dimensions);
        case MotionKind::Keyframes:
            if (m.keys.empty()) return glm::dvec3(0.0);
            return keyframePosition(m.keys, t) - object.anchor;
        case MotionKind::Random:
            return reflectInWorld(randomWalkOffset(m, t), object.bounds, grid.world, dimensions);
    }
    return glm::dvec3(0.0);
}

glm::dvec3 Scene::positionAt(int id, double t) const {
    const int index = indexOf(id);
    assert(index >= 0 && "positionAt: unknown object id (call finalize() after filling objects)");
    const SceneObject& object = objects[size_t(index)];
    return object.anchor + displacementAt(object, t);
}

Aabb Scene::boundsAt(const SceneObject& object, double t) const {
    return object.bounds.translated(displacementAt(object, t));
}

void computeAnchorAndBounds(SceneObject& o, int dimensions) {
    switch (o.shape) {
        case ShapeKind::Sphere: {
            glm::dvec3 r{o.radius, o.radius, dimensions == 2 ? 0.0 : o.radius};
            o.bounds = {o.center - r, o.center + r};
            o.anchor = o.center;
            break;
        }
        case ShapeKind::Box:
            o.bounds = o.box;
            o.anchor = o.box.center();
            break;
        case ShapeKind::Polygon:
            o.bounds = {o.points.front(), o.points.front()};
            for (const glm::dvec3& p : o.points) o.bounds.merge({p, p});
            o.anchor = o.bounds.center();
            break;
        case ShapeKind::Mesh:
            o.bounds = o.mesh->bounds.translated(o.center);
            o.anchor = o.center;
            break;
    }
}

double keyframeSpeed(const std::vector<PositionKey>& keys) {
    double speed = 0.0;
    for (size_t i = 1; i < keys.size(); ++i) {
        const PositionKey& a = keys[i - 1];
        const PositionKey& b = keys[i];
        speed = std::max(speed, glm::length(b.position - a.position) / (b.t - a.t));
    }
    return speed;
}

}  // namespace gridcull
