// An image-space overlay seen from outside the culling camera. A family draws
// its state over the culling camera's image in View space through an
// ImageFrame (ui/image_frame.h); looking from the observer's camera there is
// no such image on the screen, so this DebugDraw takes the same View-space
// primitives, in the image's own pixels (imagePixelFrame), and puts them on a
// plane across the culling camera's frustum at a chosen distance, as World
// space: the camera's "film", held up in the scene where the observer sees
// which objects lie behind which cells. Line widths and text stay in screen
// pixels; World-space primitives pass through unchanged.
#pragma once
#include <glm/vec3.hpp>

#include "culling/scene/camera.h"
#include "ui/debug_draw.h"
#include "ui/image_frame.h"

namespace gridcull {

// The frame that maps image pixels onto themselves: what to hand an overlay
// drawing through an ImagePlaneDraw.
ImageFrame imagePixelFrame(int image_width, int image_height);

// Where the film is held: a tenth of the way across the world from the
// camera, and at least twice its near distance, so it reads at the observer's
// usual distance without hiding the objects nearest the camera.
double imagePlaneDistance(const Camera& camera, const glm::dvec3& world_size);

class ImagePlaneDraw final : public DebugDraw {
public:
    // `target` receives the World-space primitives; the image is image_width x
    // image_height pixels over the whole of `camera`'s frustum.
    ImagePlaneDraw(DebugDraw& target, const Camera& camera, double distance, int image_width,
                   int image_height);

    // The World point of image point (px, py) (pixels, origin top left).
    glm::dvec3 toWorld(double px, double py) const;

    void triangle(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                  Paint paint) override;
    void line(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, Paint paint,
              float width) override;
    void text(DrawSpace space, const glm::dvec3& at, const char* text, Paint paint,
              float scale = 2.0f) override;

private:
    glm::dvec3 place(DrawSpace space, const glm::dvec3& p) const {
        return space == DrawSpace::View ? toWorld(p.x, p.y) : p;
    }
    DebugDraw& target_;
    glm::dvec3 centre_{0.0};  // the image's centre on the plane
    glm::dvec3 step_x_{0.0};  // World offset of one pixel to the right
    glm::dvec3 step_y_{0.0};  // World offset of one pixel down
    double half_width_ = 0.0, half_height_ = 0.0;  // pixels
};

}  // namespace gridcull
