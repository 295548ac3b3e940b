// One pixel's pyramid from the eye, and what a sphere or a box does inside it:
// the geometry behind the sub-sample gate's per-pixel test (subsample_refiner.h).
//
// In view space (x right, y up, z forward, the eye at the origin) the rays
// through pixel square [u0, u1] x [v1, v0] of slopes fill the pyramid
// u0 z <= x <= u1 z, v1 z <= y <= v0 z: four planes through the eye. A sphere's
// or box's least depth (view z) inside it tells whether a cover nearer than that
// hides the object in this pixel; the object's own nearest depth, over the whole
// screen, is a far weaker bound near its silhouette.
#pragma once
#include <glm/vec3.hpp>

namespace gridcull {

// The buffer's camera and pixel mapping (id_depth_buffer.h), for rays and
// pyramids through continuous pixel points: pixel (px, py) is the square
// [px, px + 1] x [py, py + 1], its centre at (px + 0.5, py + 0.5), rows from the
// top.
struct PixelView {
    glm::dvec3 eye, right, up, forward;
    double tan_x, tan_y, near, far;
    int width, height;

    glm::dvec3 ray(double x, double y) const;  // through continuous pixel point (x, y)
    glm::dvec3 toView(const glm::dvec3& world) const;
    double columnOf(const glm::dvec3& view_point) const;  // continuous x of its projection
    double rowOf(const glm::dvec3& view_point) const;     // continuous y of its projection
};

struct PixelPyramid {
    // Inward normals of the top, right, bottom and left planes: face i lies
    // between the corner rays edges[i] and edges[(i + 1) % 4].
    glm::dvec3 normals[4];
    glm::dvec3 edges[4];
    double normal_length[4];
};

// The pyramid of slopes u0 < u1 (left to right) and v0 > v1 (top to bottom).
PixelPyramid pixelPyramid(double u0, double u1, double v0, double v1);
// Pixel (px, py)'s pyramid.
PixelPyramid pixelPyramid(const PixelView& view, int px, int py);

// Whether the sphere meets the pyramid: exactly, up to a relative margin of
// 1e-9 of the radius that keeps a sphere touching it. The four planes taken one
// by one pass every pixel of the silhouette's bounding rectangle, a fifth of
// which lies outside the silhouette.
bool sphereMeetsPyramid(const PixelPyramid& pyramid, const glm::dvec3& center, double radius);

// The least depth of the sphere's part inside the pyramid, or +infinity when
// the sphere misses it: exact (the sphere's nearest point, a face's or a corner
// ray's least point, whichever lies in the pyramid), lowered by 1e-9 of itself
// for rounding. Should rounding leave no such point, the greatest over the four
// planes of the least depth inside that plane alone stands in: lower still.
double leastSphereDepthInPyramid(const PixelPyramid& pyramid, const glm::dvec3& center,
                                 double radius);

// The same for a box given by its 8 view-space corners (grid/aabb.h's corner
// order: bit 0 x, bit 1 y, bit 2 z; a rectangular box in any orientation): the
// least over the corners of the box cut by the pyramid, +infinity when it has
// none (the box misses the pyramid). A flat box (two corners that coincide)
// gets the greatest over the four planes of its least depth inside that plane
// alone, lower than the exact value and +infinity only when all its corners lie
// outside one plane.
double leastBoxDepthInPyramid(const PixelPyramid& pyramid, const glm::dvec3 corners[8]);

}  // namespace gridcull
