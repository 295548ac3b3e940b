// Whether two convex objects together cover a pixel's square, and how deep:
// the second way the sub-sample gate proves a pixel covered (subsample_refiner.h,
// coverDepth), for the seams between two objects that touch or overlap, which
// no single object spans (a wall meeting a wall, a trunk entering its crown).
//
// Box A's silhouette is a convex polygon P (its corners, cut to depth >= near,
// projected; their hull). The square S lies in P u B exactly when each piece of
// S outside one edge of P (S cut by that edge's outer half-plane, a convex
// polygon) lies in B, and B is convex: when every corner of every piece does.
// Depth: over a convex region of the image the depth of a convex solid's front
// surface is greatest at one of the region's corners (1 / depth is concave
// there, subsample_gate.h), so A's greatest depth over S n P is at the corners
// of S n P, and B's over the pieces at theirs. The pair covers S no deeper than
// the greater of the two.
//
// Rounding: a corner of a piece lying on B's own silhouette (two boxes that
// touch: their silhouettes share an edge) counts as inside B within kSeam of a
// pixel, so a gap between two objects narrower than kSeam is taken as closed.
// A corner a ray does not meet (on an edge, by rounding) counts at the solid's
// greatest depth anywhere, which only makes the answer deeper.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "culling/oracle/pixel_pyramid.h"
#include "grid/aabb.h"

namespace gridcull {

// A sphere or a box, placed in the world.
struct CoverSolid {
    bool sphere = false;
    Aabb box;  // a box's extent; a sphere's bounding box
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

// A box's silhouette in continuous pixel coordinates, counter-clockwise as x
// right and y down show it (clockwise on screen); at most kMaxCorners corners.
struct Silhouette {
    static constexpr int kMaxCorners = 20;
    glm::dvec2 corner[kMaxCorners];
    int count = 0;  // < 3: nothing in front of the near plane, or flat
};

constexpr double kSeam = 1e-9;  // pixels

Silhouette boxSilhouette(const PixelView& view, const Aabb& box);

// Whether the outline (count >= 3) meets pixel (px, py)'s square, edges
// included: exact, up to kSeam, the separating-axis test of two convex shapes.
bool outlineMeetsPixel(const Silhouette& outline, int px, int py);

// The depth below which the pair covers pixel (px, py): a is a box with
// silhouette `a_outline`, b a sphere or box (`b_outline` its silhouette when a
// box, unused for a sphere). +infinity when the pair cannot be shown to cover it.
double pairCoverDepth(const PixelView& view, int px, int py, const CoverSolid& a,
                      const Silhouette& a_outline, const CoverSolid& b,
                      const Silhouette& b_outline);

}  // namespace gridcull
