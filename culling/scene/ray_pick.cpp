#include "culling/scene/ray_pick.h"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "culling/scene/ray_intersect.h"

namespace gridcull {

namespace {

// The nearest s >= 0 where the ray meets one object at time t.
bool hitObject(const Scene& scene, const SceneObject& object, double t, const glm::dvec3& origin,
               const glm::dvec3& dir, double& s) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const glm::dvec3 shift = scene.displacementAt(object, t);
    double s0, s1;
    switch (object.shape) {
        case ShapeKind::Sphere:
            return lineSphere(origin, dir, object.center + shift, object.radius, s0, s1) &&
                   solidEntry(s0, s1, 0.0, kInfinity, s);
        case ShapeKind::Box:
            return lineBox(origin, dir, object.box.translated(shift), s0, s1) &&
                   solidEntry(s0, s1, 0.0, kInfinity, s);
        case ShapeKind::Polygon:
            if (object.points.size() < 3) return false;
            if (pointInPolygon2d(origin, object.points.data(), object.points.size(), shift)) {
                s = 0.0;
                return true;
            }
            return rayPolygonEdges2d(origin, dir, object.points.data(), object.points.size(), shift,
                                     s);
        case ShapeKind::Mesh: {
            if (!object.mesh) return false;
            const TriangleMesh& mesh = *object.mesh;
            const glm::dvec3 offset = object.center + shift;
            if (!lineBox(origin, dir, mesh.bounds.translated(offset), s0, s1) || s1 < 0.0)
                return false;
            bool hit = false;
            s = kInfinity;
            for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
                double tri_s;
                if (lineTriangle(origin, dir, mesh.vertices[mesh.indices[i]] + offset,
                                 mesh.vertices[mesh.indices[i + 1]] + offset,
                                 mesh.vertices[mesh.indices[i + 2]] + offset, tri_s) &&
                    tri_s >= 0.0 && tri_s < s) {
                    s = tri_s;
                    hit = true;
                }
            }
            return hit;
        }
    }
    return false;
}

}  // namespace

int pickObject(const Scene& scene, double t, glm::dvec3 origin, glm::dvec3 dir, double* distance) {
    const double length = glm::length(dir);
    if (!(length > 0.0) || !std::isfinite(length)) return -1;
    dir /= length;
    int best_id = -1;
    double best = std::numeric_limits<double>::infinity();
    for (const SceneObject& object : scene.objects) {
        double s;
        if (hitObject(scene, object, t, origin, dir, s) && s < best) {
            best = s;
            best_id = object.id;
        }
    }
    if (distance && best_id >= 0) *distance = best;
    return best_id;
}

}  // namespace gridcull
