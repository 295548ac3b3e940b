// Where the culling camera's image lies in a view that looks through the culling
// camera (ViewMode::CullingCamera). That image is the one the exact oracle's ID
// buffer and the image-space cullers sample (culling/raster/screen_mapping.h):
// image_width x image_height pixels over exactly the camera's frustum, pixel
// (0, 0) at the top left, so a pixel of it maps linearly onto the view.
//
// ViewCamera::matrices keeps the camera's vertical angle when the view is wider
// than camera.aspect and widens it when the view is narrower, so the image is
// the largest rectangle of the camera's aspect centred in the view; the bars
// beside it (or above and below) show what lies outside the frustum. A view of
// the camera's own aspect (`shot --view camera` at 16:9) is covered exactly.
#pragma once
#include <glm/vec2.hpp>

#include "culling/api/pixel_rect.h"
#include "ui/debug_draw.h"

namespace gridcull {

struct ImageFrame {
    ViewRect area;                          // the view pixels the image spans
    int image_width = 1, image_height = 1;  // image pixels

    // The view point of continuous image coordinates (px, py); a pixel's centre
    // is at (px + 0.5, py + 0.5), its corners at whole numbers.
    glm::dvec2 toView(double px, double py) const;
    // The other way: the continuous image coordinates of view point `v`.
    glm::dvec2 toImage(const glm::dvec2& v) const;
    // The view rectangle that image pixels [x0, x1] x [y0, y1] (inclusive) cover.
    ViewRect pixelsToView(int x0, int y0, int x1, int y1) const;
    ViewRect pixelsToView(const PixelRect& r) const { return pixelsToView(r.x0, r.y0, r.x1, r.y1); }
};

// The frame of a camera of aspect `camera_aspect` (width / height) in a view of
// view_width x view_height pixels, for an image of image_width x image_height.
ImageFrame cullingImageFrame(double camera_aspect, double view_width, double view_height,
                             int image_width, int image_height);

}  // namespace gridcull
