// The 2D half of the exact oracle (culling/oracle/exact_oracle.h): an angular sweep, a
// "1D z-buffer" over rays from the camera.
//
// The wedge [heading - fov/2, heading + fov/2] (radians, x-y plane, angles
// counter-clockwise from +x) is cut into `rays` equal angular bins; ray i leaves
// the camera position at the centre of bin i, angle
//   heading - fov/2 + (i + 0.5) * fov / rays.
// Each ray keeps the nearest hit distance in [0, far] (world units, unit-length
// directions) and the index of the object hit. 2D has no near plane.
//
// Circles are intersected exactly, boxes and polygons by exact ray-segment tests
// (culling/scene/ray_intersect.h). Each object first gets its angular interval as seen
// from the camera and touches only the rays inside it, so a frame costs
// O(sum over objects of rays in its interval * edges), not O(rays * objects).
// A camera inside (or on the boundary of) a solid object covers every ray at
// distance 0. Wedges that cross the -pi/pi seam and fov 360 need no special case:
// intervals are measured relative to the wedge's first edge.
//
// Draw calls compare with a strict "<" (the first drawn wins a tie); drawing
// front to back lets each call skip rays already nearer than the object.
// No call allocates except resize().
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/scene/camera.h"

namespace gridcull {

class OracleAngularSweep {
public:
    // Sizes the buffers for `rays` (>= 1) rays over a wedge of fov_deg; no-op when
    // neither changed.
    void resize(int rays, double fov_deg);
    int rays() const { return int(distance_.size()); }

    // Takes the camera position and heading and clears every ray.
    void begin(const Camera& camera);

    // A lower bound of the distance from the camera to any point of the shape.
    double minDistanceOfCircle(const glm::dvec3& center, double radius) const;
    double minDistanceOfBox(const Aabb& box) const;

    // Each draw writes `index` into the rays it wins; false when the object lies
    // wholly beyond `far` or outside the wedge. Polygons are points[i] + offset,
    // counter-clockwise or not; boxes use their x-y rectangle.
    bool drawCircle(int index, const glm::dvec3& center, double radius);
    bool drawBox(int index, const Aabb& box);
    bool drawPolygon(int index, const glm::dvec3* points, size_t count, const glm::dvec3& offset);

    // Sets seen[index] = 1 for every index left on a ray. O(rays).
    void markVisible(std::vector<char>& seen) const;

private:
    // Every ray at distance 0: the camera is inside the object.
    void fillAll(int index);
    // The angle of p seen from the camera, measured counter-clockwise from the
    // wedge's first edge, in [0, 2 pi).
    double relativeAngle(const glm::dvec3& p) const;
    // Unit direction of ray i in world x-y.
    glm::dvec3 rayDirection(int i) const;
    // Calls hit(i) for every ray whose bin centre lies in the relative angular
    // interval [from, from + width] (with a one-ray margin); returns false when none.
    template <typename Hit>
    bool forRaysIn(double from, double width, Hit&& hit);

    std::vector<double> distance_;
    std::vector<int32_t> index_;
    std::vector<double> bin_cos_, bin_sin_;  // ray directions relative to the first edge
    double fov_rad_ = 0.0;
    double step_ = 0.0;  // angular width of one bin
    glm::dvec3 origin_{0.0};
    double start_cos_ = 1.0, start_sin_ = 0.0;  // direction of the wedge's first edge
    double far_ = 1000.0;
};

}  // namespace gridcull
