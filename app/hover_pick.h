// Which object is under the mouse: a ray pick in 3D (culling/scene/ray_pick.h, the same
// intersections the oracle uses) and a point-in-shape test in 2D.
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "culling/scene/scene.h"
#include "ui/frame_snapshot.h"
#include "ui/object_state.h"

namespace gridcull {

// Index into scene.objects of the 2D object containing `point` (x, y) at time t,
// or -1. Where shapes overlap, the one drawn on top wins (false-culled, then
// visible, hidden, culled), as the renderer layers them. O(objects).
int pickObject2d(const Scene& scene, double t, const glm::dvec3& point,
                 const std::vector<ObjectState>& states);

// The hover panel's description of object `index` at time t.
HoverInfo describeObject(const Scene& scene, int index, double t,
                         const std::vector<ObjectState>& states, double distance);

// True when (x, y) lies inside or on the outline of the polygon (even-odd rule).
bool pointInPolygon(const std::vector<glm::dvec3>& points, const glm::dvec3& offset, double x,
                    double y);

}  // namespace gridcull
