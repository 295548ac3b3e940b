#include "app/view_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace gridcull {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kViewFovDeg = 45.0;
constexpr double kRadiansPerPixel = 0.006;
constexpr double kMaxPitch = 1.5;        // just short of straight up or down
constexpr double kZoomPerStep = 0.88;
constexpr double kMapMargin = 1.04;      // a little space around the world box

glm::dvec3 directionOf(double yaw, double pitch) {
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

}  // namespace

void ViewCamera::frameScene(const Scene& scene) {
    dimensions_ = scene.dimensions;
    const Aabb& world = scene.grid.world;
    world_size_ = std::max(glm::length(world.extent()), 1e-6);
    orbit_target_ = world.center();
    // Far enough that the world's bounding sphere fits the vertical field of view.
    orbit_distance_ = 0.5 * world_size_ / std::sin(kViewFovDeg * kPi / 360.0);
    // From the (+x, -z) corner: square to the x = z diagonal along which the
    // shipped scenes' camera paths mostly run, so frusta show side-on.
    orbit_yaw_ = -0.25 * kPi;
    orbit_pitch_ = 0.6;
    startFlyingFromOrbit();
    map_center_ = world.center();
    map_center_.z = 0.0;
    map_half_height_ = 0.5 * world.extent().y * kMapMargin;
    map_half_width_ = 0.5 * world.extent().x * kMapMargin;
}

glm::dvec3 ViewCamera::orbitEye() const {
    return orbit_target_ - directionOf(orbit_yaw_, -orbit_pitch_) * orbit_distance_;
}

ViewMatrices ViewCamera::matrices(ViewMode mode, const Camera& culling, double aspect) const {
    ViewMatrices m;
    aspect = std::max(aspect, 1e-3);
    if (dimensions_ == 2) {
        // Fit the world box: whichever of its sides is the tighter fit decides.
        const double half_h = std::max(map_half_height_, map_half_width_ / aspect);
        const double half_w = half_h * aspect;
        m.orthographic = true;
        m.view = glm::lookAt(map_center_ + glm::dvec3(0, 0, 10), map_center_,
                             glm::dvec3(0.0, 1.0, 0.0));
        m.projection = glm::ortho(-half_w, half_w, -half_h, half_h, 1.0, 20.0);
        m.forward = {0.0, 0.0, -1.0};
        m.eye = map_center_ + glm::dvec3(0, 0, 10);
    } else if (mode == ViewMode::CullingCamera) {
        // The culling camera's own view; when the view is narrower than the
        // camera's aspect, widen the vertical angle so its whole width shows.
        double fov = culling.fov_deg * kPi / 180.0;
        if (aspect < culling.aspect)
            fov = 2.0 * std::atan(std::tan(fov * 0.5) * culling.aspect / aspect);
        m.view = culling.viewMatrix();
        m.projection = glm::perspective(fov, aspect, culling.near, culling.far);
        m.eye = culling.position;
        m.forward = culling.forward();
    } else {
        const glm::dvec3 eye = mode == ViewMode::Fly ? fly_position_ : orbitEye();
        const glm::dvec3 fwd = mode == ViewMode::Fly ? directionOf(fly_yaw_, fly_pitch_)
                                                     : glm::normalize(orbit_target_ - eye);
        m.view = glm::lookAt(eye, eye + fwd, glm::dvec3(0.0, 1.0, 0.0));
        const double reach = glm::length(eye - orbit_target_) + world_size_ * 2.0;
        m.projection = glm::perspective(kViewFovDeg * kPi / 180.0, aspect, reach * 1e-4, reach);
        m.eye = eye;
        m.forward = fwd;
    }
    m.view_projection = m.projection * m.view;
    return m;
}

void ViewCamera::orbit(double dx_pixels, double dy_pixels) {
    orbit_yaw_ -= dx_pixels * kRadiansPerPixel;
    orbit_pitch_ = std::clamp(orbit_pitch_ + dy_pixels * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
}

void ViewCamera::zoom(double wheel_steps) {
    const double factor = std::pow(kZoomPerStep, wheel_steps);
    if (dimensions_ == 2) {
        map_half_height_ *= factor;
        map_half_width_ *= factor;
    } else {
        orbit_distance_ = std::clamp(orbit_distance_ * factor, world_size_ * 1e-3, world_size_ * 20.0);
    }
}

void ViewCamera::pan2d(double dx_pixels, double dy_pixels, int view_height_pixels) {
    // The map's half height in world units covers half the view's pixels, or
    // more when the width is the tighter fit; the height-based scale is close
    // enough for dragging.
    const double units_per_pixel = 2.0 * map_half_height_ / std::max(view_height_pixels, 1);
    map_center_.x -= dx_pixels * units_per_pixel;
    map_center_.y += dy_pixels * units_per_pixel;
}

void ViewCamera::look(double dx_pixels, double dy_pixels) {
    fly_yaw_ -= dx_pixels * kRadiansPerPixel;
    fly_pitch_ = std::clamp(fly_pitch_ - dy_pixels * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
}

void ViewCamera::fly(const glm::dvec3& move, double seconds, bool fast) {
    const glm::dvec3 fwd = directionOf(fly_yaw_, fly_pitch_);
    const glm::dvec3 right = glm::normalize(glm::cross(fwd, glm::dvec3(0.0, 1.0, 0.0)));
    const double speed = world_size_ * (fast ? 0.5 : 0.12);
    fly_position_ += (right * move.x + glm::dvec3(0.0, 1.0, 0.0) * move.y + fwd * move.z) *
                     (speed * seconds);
}

void ViewCamera::startFlyingFromOrbit() {
    fly_position_ = orbitEye();
    const glm::dvec3 fwd = glm::normalize(orbit_target_ - fly_position_);
    fly_yaw_ = std::atan2(fwd.x, fwd.z);
    fly_pitch_ = std::asin(std::clamp(fwd.y, -1.0, 1.0));
}

void viewRay(const ViewMatrices& view, double px, double py, int width, int height,
             glm::dvec3& origin, glm::dvec3& dir) {
    const double nx = 2.0 * (px + 0.5) / std::max(width, 1) - 1.0;
    const double ny = 1.0 - 2.0 * (py + 0.5) / std::max(height, 1);
    const glm::dmat4 inverse = glm::inverse(view.view_projection);
    auto unproject = [&](double nz) {
        const glm::dvec4 p = inverse * glm::dvec4(nx, ny, nz, 1.0);
        return glm::dvec3(p) / p.w;
    };
    const glm::dvec3 a = unproject(-1.0);
    const glm::dvec3 b = unproject(1.0);
    if (view.orthographic) {
        origin = {a.x, a.y, 0.0};
        dir = {0.0, 0.0, -1.0};
        return;
    }
    origin = view.eye;
    dir = glm::normalize(b - a);
}

}  // namespace gridcull
