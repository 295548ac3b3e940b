// The camera the scene view is drawn from, separate from the culling camera:
// 3D orbit around the world (default), a free-flying observer, or the culling
// camera itself; 2D a top-down orthographic map of the world box with pan and
// zoom. Double precision world units; matrices follow OpenGL conventions.
#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "culling/scene/camera.h"
#include "culling/scene/scene.h"
#include "ui/frame_snapshot.h"

namespace gridcull {

struct ViewMatrices {
    glm::dmat4 view{1.0};
    glm::dmat4 projection{1.0};
    glm::dmat4 view_projection{1.0};
    glm::dvec3 eye{0.0};  // perspective: the eye; orthographic: unused
    glm::dvec3 forward{0.0, 0.0, -1.0};
    bool orthographic = false;
};

class ViewCamera {
public:
    // Back to the default framing of `scene` (orbit 3D view / whole-world 2D map).
    void frameScene(const Scene& scene);

    // The matrices for a view of aspect width / height.
    ViewMatrices matrices(ViewMode mode, const Camera& culling, double aspect) const;

    // Input, in pixels of mouse motion or wheel steps. Orbit and 2D map.
    void orbit(double dx_pixels, double dy_pixels);
    void zoom(double wheel_steps);
    void pan2d(double dx_pixels, double dy_pixels, int view_height_pixels);
    // Fly: look around by mouse motion; move along the view axes by `move`
    // (x right, y up, z forward) scaled to the world's size per second.
    void look(double dx_pixels, double dy_pixels);
    void fly(const glm::dvec3& move, double seconds, bool fast);
    // Starts the fly camera where the orbit camera is, so switching does not jump.
    void startFlyingFromOrbit();

private:
    glm::dvec3 orbitEye() const;

    int dimensions_ = 3;
    double world_size_ = 1.0;  // diagonal of the world box
    // Orbit.
    glm::dvec3 orbit_target_{0.0};
    double orbit_distance_ = 1.0;
    double orbit_yaw_ = 0.0;    // radians around +y
    double orbit_pitch_ = 0.5;  // radians above the horizon
    // Fly.
    glm::dvec3 fly_position_{0.0};
    double fly_yaw_ = 0.0;
    double fly_pitch_ = 0.0;
    // 2D map.
    glm::dvec3 map_center_{0.0};
    double map_half_height_ = 1.0;
    double map_half_width_ = 1.0;  // of the world box, to fit it at any aspect
};

// The world-space ray under a pixel of a view of size width x height (pixel
// origin top left). Perspective: from the eye through the pixel, `dir` unit
// length. Orthographic: the point on the z = 0 plane under the pixel in `origin`.
void viewRay(const ViewMatrices& view, double px, double py, int width, int height,
             glm::dvec3& origin, glm::dvec3& dir);

}  // namespace gridcull
