// One 2D object as the exact angular oracle (culling/oracle/exact_oracle_2d.h) sees
// it from the camera: a solid circle or a solid polygon (a box is its x-y rectangle,
// a polygon its points + offset, either winding), with the camera frame that
// measures its angles and casts its rays.
//
// Angles are relative: radians counter-clockwise from the wedge's first edge, in
// [0, 2 pi), measured in the frame rotated by minus the start angle so that the
// wedge is [0, fov] with no seam inside it (the -pi/pi seam of world angles and
// fov 360 need no special case). Distances are world units along unit rays.
#pragma once
#include <cstddef>

#include <glm/vec3.hpp>

#include "culling/scene/camera.h"
#include "grid/aabb.h"

namespace gridcull {

// The camera's position, the wedge's first edge and far.
struct AngularFrame {
    glm::dvec3 origin{0.0};                   // z = 0
    double start_cos = 1.0, start_sin = 0.0;  // direction of the wedge's first edge
    double fov = 0.0;                         // radians, in (0, 2 pi]
    double far = 1000.0;

    void set(const Camera& camera, double fov_rad);
    // The relative angle of p, in [0, 2 pi).
    double angleOf(const glm::dvec3& p) const;
    // The unit world direction of relative angle a.
    glm::dvec3 direction(double a) const;
};

struct AngularShape {
    bool circle = false;
    glm::dvec3 center{0.0};  // circle, z = 0
    double radius = 0.0;
    // Polygon: points[i] + offset, or the box's four corners when points is null.
    const glm::dvec3* points = nullptr;
    size_t count = 0;
    glm::dvec3 offset{0.0};
    glm::dvec3 corners[4];

    static AngularShape makeCircle(const glm::dvec3& center, double radius);
    static AngularShape makeBox(const Aabb& box);
    static AngularShape makePolygon(const glm::dvec3* points, size_t count,
                                    const glm::dvec3& offset);

    size_t vertexCount() const { return points ? count : (circle ? 0 : 4); }
    glm::dvec3 vertex(size_t i) const;
};

// What the camera sees of a shape before any occlusion: whether the camera is
// inside it or on its boundary (then it sees nothing else), its angular interval
// [lo, hi] (relative angles, unwrapped: lo may be negative or hi beyond 2 pi; a
// width >= 2 pi covers every direction), and bounds of its distance.
struct AngularExtent {
    bool contains_camera = false;
    double lo = 0.0, hi = 0.0;
    double min_distance = 0.0, max_distance = 0.0;
};
AngularExtent angularExtent(const AngularShape& shape, const AngularFrame& frame);

// The distance along unit ray `dir` from the camera to the first point of the
// shape, counting only [0, far]; +infinity when the ray misses it there. The
// camera must be outside the shape (AngularExtent::contains_camera false).
double rayDistance(const AngularShape& shape, const AngularFrame& frame, const glm::dvec3& dir);

}  // namespace gridcull
