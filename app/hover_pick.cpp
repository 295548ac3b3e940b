#include "app/hover_pick.h"

#include <glm/geometric.hpp>

namespace gridcull {

namespace {

// Higher draws on top in the 2D view.
int layerOf(ObjectState state) {
    switch (state) {
    case ObjectState::Culled: return 0;
    case ObjectState::Hidden: return 1;
    case ObjectState::Visible: return 2;
    case ObjectState::SubSample: return 3;
    case ObjectState::FalseCulled: return 4;
    }
    return 0;
}

bool contains2d(const Scene& scene, const SceneObject& object, double t, double x, double y) {
    const glm::dvec3 d = scene.displacementAt(object, t);
    switch (object.shape) {
    case ShapeKind::Sphere: {
        const glm::dvec3 c = object.center + d;
        const double dx = x - c.x, dy = y - c.y;
        return dx * dx + dy * dy <= object.radius * object.radius;
    }
    case ShapeKind::Polygon: return pointInPolygon(object.points, d, x, y);
    case ShapeKind::Box:
    case ShapeKind::Mesh: {
        const Aabb b = object.bounds.translated(d);
        return x >= b.min.x && x <= b.max.x && y >= b.min.y && y <= b.max.y;
    }
    }
    return false;
}

}  // namespace

bool pointInPolygon(const std::vector<glm::dvec3>& points, const glm::dvec3& offset, double x,
                    double y) {
    bool inside = false;
    const size_t n = points.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const glm::dvec3 a = points[i] + offset;
        const glm::dvec3 b = points[j] + offset;
        if ((a.y > y) != (b.y > y)) {
            const double cross_x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (x == cross_x) return true;
            if (x < cross_x) inside = !inside;
        }
    }
    return inside;
}

int pickObject2d(const Scene& scene, double t, const glm::dvec3& point,
                 const std::vector<ObjectState>& states) {
    int best = -1, best_layer = -1;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const int layer = i < states.size() ? layerOf(states[i]) : 0;
        if (layer <= best_layer) continue;
        if (contains2d(scene, scene.objects[i], t, point.x, point.y)) {
            best = int(i);
            best_layer = layer;
        }
    }
    return best;
}

HoverInfo describeObject(const Scene& scene, int index, double t,
                         const std::vector<ObjectState>& states, double distance) {
    HoverInfo info;
    if (index < 0 || index >= int(scene.objects.size())) return info;
    const SceneObject& object = scene.objects[size_t(index)];
    info.id = object.id;
    info.shape = object.shape;
    info.state = size_t(index) < states.size() ? states[size_t(index)] : ObjectState::Culled;
    info.bounds = scene.boundsAt(object, t);
    info.motion = object.motion.kind;
    info.max_speed = object.motion.max_speed;
    info.distance = distance;
    return info;
}

}  // namespace gridcull
