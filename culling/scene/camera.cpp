#include "culling/scene/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace gridcull {

glm::dvec3 Camera::forward() const {
    const glm::dvec3 d = target - position;
    const double len = glm::length(d);
    if (!(len > 0.0) || !std::isfinite(len)) return {1.0, 0.0, 0.0};
    return d / len;
}

void Camera::basis(glm::dvec3& right, glm::dvec3& true_up, glm::dvec3& fwd) const {
    fwd = forward();
    glm::dvec3 r = glm::cross(fwd, up);
    if (glm::length(r) < 1e-9) {
        // Looking along `up`: any perpendicular axis gives a valid basis.
        r = glm::cross(fwd, std::abs(fwd.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1));
    }
    right = glm::normalize(r);
    true_up = glm::cross(right, fwd);
}

glm::dmat4 Camera::viewMatrix() const {
    glm::dvec3 right, true_up, fwd;
    basis(right, true_up, fwd);
    return glm::lookAt(position, position + fwd, true_up);
}

glm::dmat4 Camera::projectionMatrix() const {
    return glm::perspective(glm::radians(fov_deg), aspect, near, far);
}

std::array<glm::dvec4, 6> Camera::frustumPlanes() const {
    glm::dvec3 right, true_up, fwd;
    basis(right, true_up, fwd);
    const double tan_y = std::tan(glm::radians(fov_deg) * 0.5);
    const double tan_x = tan_y * aspect;
    // Inward normals of the side planes through the eye.
    const glm::dvec3 left_n = glm::normalize(fwd * tan_x + right);
    const glm::dvec3 right_n = glm::normalize(fwd * tan_x - right);
    const glm::dvec3 bottom_n = glm::normalize(fwd * tan_y + true_up);
    const glm::dvec3 top_n = glm::normalize(fwd * tan_y - true_up);
    auto through = [&](const glm::dvec3& n, const glm::dvec3& p) {
        return glm::dvec4(n, -glm::dot(n, p));
    };
    return {through(left_n, position),           through(right_n, position),
            through(bottom_n, position),         through(top_n, position),
            through(fwd, position + fwd * near), through(-fwd, position + fwd * far)};
}

Camera cameraAt(const Scene& scene, double t) {
    const CameraSpec& spec = scene.camera;
    Camera cam;
    cam.dimensions = scene.dimensions;
    cam.fov_deg = spec.fov_deg;
    cam.aspect = spec.aspect;
    cam.near = spec.near;
    cam.far = spec.far;
    if (spec.path.empty()) return cam;
    const auto& path = spec.path;
    auto take = [&](const CameraKey& key) {
        cam.position = key.position;
        cam.target = key.target;
        cam.up = key.up;
    };
    if (t <= path.front().t) {
        take(path.front());
    } else if (t >= path.back().t) {
        take(path.back());
    } else {
        // First key with key.t > t; keys are strictly increasing in t.
        auto next = std::upper_bound(path.begin(), path.end(), t,
                                     [](double time, const CameraKey& k) { return time < k.t; });
        const CameraKey& b = *next;
        const CameraKey& a = *(next - 1);
        const double s = (t - a.t) / (b.t - a.t);
        cam.position = a.position + (b.position - a.position) * s;
        cam.target = a.target + (b.target - a.target) * s;
        // Up turns with the keys; when the two ups cancel, keep the first key's.
        const glm::dvec3 up = a.up + (b.up - a.up) * s;
        cam.up = glm::length(up) > 1e-12 ? glm::normalize(up) : a.up;
    }
    if (scene.dimensions == 2) {
        cam.position.z = 0.0;
        cam.target.z = 0.0;
        cam.up = {0.0, 0.0, 1.0};
    }
    return cam;
}

}  // namespace gridcull
