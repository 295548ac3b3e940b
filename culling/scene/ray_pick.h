// Picking: which object a ray from the eye meets first, for the GUI's hover.
// Uses the exact oracle's intersection functions (culling/scene/ray_intersect.h), so a
// hovered object is what `exact` would see along that ray.
#pragma once
#include <glm/vec3.hpp>

#include "culling/scene/scene.h"

namespace gridcull {

// The id of the object met first by the ray origin + s * dir, s >= 0, with every
// object at its position at time t; -1 when none is met or dir is zero.
// `distance` (may be null) receives the world distance from origin to the hit.
// Spheres, boxes and polygons are solid (an origin inside one hits it at 0);
// meshes are two-sided triangles. World units; 2D scenes pass z = 0.
// Cost: O(objects + mesh triangles); allocates nothing.
int pickObject(const Scene& scene, double t, glm::dvec3 origin, glm::dvec3 dir, double* distance);

}  // namespace gridcull
