#include "culling/scene/motion_bounds.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace gridcull {

double maxSpeedOf(const SceneObject& object) {
    const Motion& m = object.motion;
    double speed = m.max_speed;
    switch (m.kind) {
        case MotionKind::Static:
            return 0.0;
        case MotionKind::Linear:
            speed = std::max(speed, glm::length(m.velocity));
            break;
        case MotionKind::Random:
            for (const glm::dvec3& v : m.segment_velocities)
                speed = std::max(speed, glm::length(v));
            break;
        case MotionKind::Keyframes:
            for (size_t i = 1; i < m.keys.size(); ++i) {
                const double span = m.keys[i].t - m.keys[i - 1].t;
                const double dist = glm::length(m.keys[i].position - m.keys[i - 1].position);
                if (span > 0.0) speed = std::max(speed, dist / span);
            }
            break;
    }
    return speed;
}

Aabb reachOf(const SceneObject& object, const Aabb& world, int dimensions) {
    const Aabb& b = object.bounds;
    switch (object.motion.kind) {
        case MotionKind::Static:
            return b;
        case MotionKind::Keyframes: {
            if (object.motion.keys.empty()) return b;
            Aabb reach = b.translated(object.motion.keys.front().position - object.anchor);
            for (const PositionKey& key : object.motion.keys)
                reach.merge(b.translated(key.position - object.anchor));
            return reach;
        }
        case MotionKind::Linear:
        case MotionKind::Random:
            break;
    }
    Aabb reach = b;
    for (int a = 0; a < dimensions; ++a) {
        const double lo = world.min[a] - b.min[a], hi = world.max[a] - b.max[a];
        if (lo > 0.0 || hi < 0.0 || !(hi > lo)) continue;
        reach.min[a] = world.min[a];
        reach.max[a] = world.max[a];
    }
    return reach;
}

double boundingRadiusOf(const SceneObject& object, int dimensions) {
    const glm::dvec3 a = object.anchor;
    switch (object.shape) {
        case ShapeKind::Sphere: {
            glm::dvec3 d = object.center - a;
            if (dimensions == 2) d.z = 0.0;
            return object.radius + glm::length(d);
        }
        case ShapeKind::Polygon: {
            double r = 0.0;
            for (const glm::dvec3& p : object.points) r = std::max(r, glm::length(p - a));
            return r;
        }
        case ShapeKind::Box:
        case ShapeKind::Mesh:
            break;
    }
    // A box, or a mesh (its bounds hold its vertices): the farthest corner.
    const Aabb& b = object.bounds;
    double r = 0.0;
    const int corners = dimensions == 2 ? 4 : 8;
    for (int i = 0; i < corners; ++i) {
        glm::dvec3 corner{(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                          (i & 4) ? b.max.z : b.min.z};
        glm::dvec3 from = a;
        if (dimensions == 2) corner.z = from.z = 0.0;
        r = std::max(r, glm::length(corner - from));
    }
    return r;
}

}  // namespace gridcull
