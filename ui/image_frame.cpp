#include "ui/image_frame.h"

#include <algorithm>

namespace gridcull {

glm::dvec2 ImageFrame::toView(double px, double py) const {
    return {area.x0 + px * (area.x1 - area.x0) / image_width,
            area.y0 + py * (area.y1 - area.y0) / image_height};
}

glm::dvec2 ImageFrame::toImage(const glm::dvec2& v) const {
    const double w = area.x1 - area.x0, h = area.y1 - area.y0;
    return {w > 0.0 ? (v.x - area.x0) * image_width / w : 0.0,
            h > 0.0 ? (v.y - area.y0) * image_height / h : 0.0};
}

ViewRect ImageFrame::pixelsToView(int x0, int y0, int x1, int y1) const {
    const glm::dvec2 a = toView(x0, y0), b = toView(x1 + 1, y1 + 1);
    return {a.x, a.y, b.x, b.y};
}

ImageFrame cullingImageFrame(double camera_aspect, double view_width, double view_height,
                             int image_width, int image_height) {
    ImageFrame frame;
    frame.image_width = std::max(image_width, 1);
    frame.image_height = std::max(image_height, 1);
    view_height = std::max(view_height, 1.0);
    const double view_aspect = std::max(view_width / view_height, 1e-3);
    camera_aspect = std::max(camera_aspect, 1e-3);
    // The same test as ViewCamera::matrices: a wider view keeps the vertical angle.
    if (view_aspect >= camera_aspect) {
        const double w = view_height * camera_aspect;
        const double x = 0.5 * (view_width - w);
        frame.area = {x, 0.0, x + w, view_height};
    } else {
        const double h = view_width / camera_aspect;
        const double y = 0.5 * (view_height - h);
        frame.area = {0.0, y, view_width, y + h};
    }
    return frame;
}

}  // namespace gridcull
