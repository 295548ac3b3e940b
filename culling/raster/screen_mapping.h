// Screen space of the image-space cullers: how a world box maps to the image
// they draw (after Hey, Tobler & Purgathofer, section 7: "The image area of a
// bounding box is approximated by its bounding rectangle in the image").
//
// The image is the one the shared rasterizer samples (culling/raster/
// id_depth_buffer.h): width x height pixels over exactly the camera's
// frustum, pixel (px, py) from the top-left, its centre at continuous coordinates
// (px + 0.5, py + 0.5). Depth is view-space distance along the camera's forward
// axis in world units, as in the oracle, so "znear <= zfar" compares like with
// like everywhere.
#pragma once
#include <glm/vec3.hpp>

#include "culling/api/pixel_rect.h"
#include "culling/scene/camera.h"
#include "grid/aabb.h"

namespace gridcull {

// A box as the grid sees it.
struct BoxOnScreen {
    PixelRect rect;      // every pixel the box's projection touches, clipped to the image
    double znear = 0.0;  // <= the depth of every point of the box (may be < near)
    double zfar = 0.0;   // >= the depth of every point of the box
};

class ScreenMapping {
public:
    // Takes the camera and the image size (each >= 1). Allocates nothing.
    void set(const Camera& camera, int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }
    PixelRect image() const { return {0, 0, width_ - 1, height_ - 1}; }

    // The box's depth range and the pixels its part at depth >= near projects onto.
    // The part in front of the near plane is cut off first (its corners at depth >=
    // near plus the crossings of its edges with the near plane), so a box around
    // the eye projects to a bounded rectangle; a box that contains the eye (its
    // boundary included) covers the whole image, as the oracle then fills every
    // pixel with what the eye is in. The rectangle holds every pixel whose
    // centre sees a point of the box at depth >= near: continuous bounds are widened
    // by kRectSlack pixels against rounding, then floored. Empty rect: no pixel of
    // the image can see the box. O(1), no allocation.
    BoxOnScreen project(const Aabb& box) const;

    // Continuous pixel coordinates of a view-space direction (u, v) = (x/z, y/z).
    double columnOf(double u) const { return (u / tan_x_ + 1.0) * 0.5 * width_; }
    double rowOf(double v) const { return (1.0 - v / tan_y_) * 0.5 * height_; }
    glm::dvec3 toView(const glm::dvec3& world) const;

    static constexpr double kRectSlack = 1e-6;  // pixels
    // Relative slack taken off znear (and added to zfar) so that rounding in the
    // per-pixel depth of a shape touching its box can never put it nearer.
    static constexpr double kDepthSlack = 1e-9;

private:
    glm::dvec3 eye_{0.0}, right_{1, 0, 0}, up_{0, 1, 0}, forward_{0, 0, 1};
    double tan_x_ = 1.0, tan_y_ = 1.0, near_ = 0.1;
    int width_ = 1, height_ = 1;
};

}  // namespace gridcull
