#include "ui/image_plane_draw.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace gridcull {

ImageFrame imagePixelFrame(int image_width, int image_height) {
    ImageFrame frame;
    frame.image_width = std::max(image_width, 1);
    frame.image_height = std::max(image_height, 1);
    frame.area = {0.0, 0.0, double(frame.image_width), double(frame.image_height)};
    return frame;
}

double imagePlaneDistance(const Camera& camera, const glm::dvec3& world_size) {
    const double across = 0.1 * glm::length(world_size);
    return std::clamp(across, 2.0 * camera.near, std::max(camera.far, 2.0 * camera.near));
}

ImagePlaneDraw::ImagePlaneDraw(DebugDraw& target, const Camera& camera, double distance,
                               int image_width, int image_height)
    : target_(target) {
    glm::dvec3 right, up, forward;
    camera.basis(right, up, forward);
    const double half_h = distance * std::tan(0.5 * camera.fov_deg * M_PI / 180.0);
    const double half_w = half_h * camera.aspect;
    half_width_ = 0.5 * std::max(image_width, 1);
    half_height_ = 0.5 * std::max(image_height, 1);
    centre_ = camera.position + distance * forward;
    step_x_ = right * (half_w / half_width_);
    step_y_ = -up * (half_h / half_height_);
}

glm::dvec3 ImagePlaneDraw::toWorld(double px, double py) const {
    return centre_ + (px - half_width_) * step_x_ + (py - half_height_) * step_y_;
}

void ImagePlaneDraw::triangle(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b,
                              const glm::dvec3& c, Paint paint) {
    target_.triangle(DrawSpace::World, place(space, a), place(space, b), place(space, c), paint);
}

void ImagePlaneDraw::line(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, Paint paint,
                          float width) {
    target_.line(DrawSpace::World, place(space, a), place(space, b), paint, width);
}

void ImagePlaneDraw::text(DrawSpace space, const glm::dvec3& at, const char* text, Paint paint,
                          float scale) {
    target_.text(DrawSpace::World, place(space, at), text, paint, scale);
}

}  // namespace gridcull
