// How every generator adds its objects to the scene: the next id, the anchor
// and bounds computed as the loader computes them for listed objects, and two
// shortcuts for the shapes most generators make. One place, so that generated
// and listed objects cannot differ in how they are finished.
#pragma once
#include <utility>

#include <glm/vec3.hpp>

#include "culling/scene/scene.h"
#include "grid/aabb.h"

namespace gridcull {

struct SceneEmitter {
    Scene& scene;
    int& next_id;
    void add(SceneObject o) {
        o.id = next_id++;
        computeAnchorAndBounds(o, scene.dimensions);
        scene.objects.push_back(std::move(o));
    }
    void addBox(const Aabb& box) {
        SceneObject o;
        o.shape = ShapeKind::Box;
        o.box = box;
        add(std::move(o));
    }
    void addSphere(const glm::dvec3& center, double radius) {
        SceneObject o;
        o.shape = ShapeKind::Sphere;
        o.center = center;
        o.radius = radius;
        add(std::move(o));
    }
};

}  // namespace gridcull
