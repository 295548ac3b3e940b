// The view-frustum tests of `vfc` (culling/baseline/vfc_culler.h), which every
// family reuses for its own frustum culling: conservative, so an object they
// reject is wholly outside the camera's frustum (3D) or wedge (2D).
// `t`-independent: pass bounds at t. O(1) each, no allocation.
#pragma once
#include <array>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "culling/scene/camera.h"
#include "grid/aabb.h"

namespace gridcull {

// 3D: may the box intersect the camera's frustum?
bool boxMayIntersectFrustum(const Aabb& box, const Camera& camera);
// The same with the camera's planes (camera.frustumPlanes()) computed once for
// many boxes: a culler testing every object computes them once per frame.
bool boxMayIntersectFrustum(const Aabb& box, const Camera& camera,
                            const std::array<glm::dvec4, 6>& planes);
// 2D: may the circle / the x-y box intersect the camera's wedge?
bool circleMayIntersectWedge(const glm::dvec3& center, double radius, const Camera& camera);
bool boxMayIntersectWedge(const Aabb& box, const Camera& camera);

}  // namespace gridcull
