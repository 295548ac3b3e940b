// The culling camera at one instant, interpolated from the scene's camera path.
// 3D: a perspective frustum with vertical fov_deg, aspect = width / height, near
// and far distances along the view direction. 2D: a wedge of fov_deg (up to 360)
// around the direction to the target in the x-y plane, cut at `far`.
#pragma once
#include <array>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "culling/scene/scene.h"

namespace gridcull {

struct Camera {
    int dimensions = 3;
    glm::dvec3 position{0.0};
    glm::dvec3 target{0.0, 0.0, 1.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fov_deg = 60.0;
    double aspect = 16.0 / 9.0;
    double near = 0.1;
    double far = 1000.0;

    // Unit view direction; +x of the scene when position == target.
    glm::dvec3 forward() const;
    // Right-handed camera basis (3D): right = forward x up, true up = right x forward.
    // When `up` is parallel to forward another axis is chosen so the basis exists.
    void basis(glm::dvec3& right, glm::dvec3& true_up, glm::dvec3& fwd) const;
    glm::dmat4 viewMatrix() const;        // world -> eye (OpenGL convention, -z forward)
    glm::dmat4 projectionMatrix() const;  // eye -> clip, OpenGL depth range [-1, 1]
    // The six frustum planes (left, right, bottom, top, near, far), each as
    // (n, d) with n pointing inwards: a point p is inside when dot(n, p) + d >= 0.
    std::array<glm::dvec4, 6> frustumPlanes() const;
};

// Position and target linear in t between path keys, held before the first and
// after the last key (scene-format.md, "Camera").
Camera cameraAt(const Scene& scene, double t);

}  // namespace gridcull
