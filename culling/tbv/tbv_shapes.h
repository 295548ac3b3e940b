// Shapes of temporal bounding volumes (Sudarsky & Gotsman, "Dynamic scene
// occlusion culling", section 3.2: "for objects moving along preset
// trajectories, the TBVs can be sweep surfaces; if only maximum velocities or
// maximum accelerations are known, then spheres may be used"; section 3.3
// mentions axis-aligned boxes as the geometrically simple alternative). Apart
// from any spatial structure: a structure inserts tbvBounds(shape), the box
// around the volume, and may test the exact shape itself.
//
// Three kinds, in world units and seconds:
//  - Sphere (a circle in 2D): centre = the object's reference position when the
//    TBV is made, radius = its bounding radius (around that position) + max
//    speed * validity. Every position the object can reach in the validity
//    period at no more than the max speed keeps its bounding ball inside.
//  - Box: the object's box when the TBV is made, grown on each axis by max
//    speed * validity (a speed bound on |v|), or by speed[a] * validity (a bound
//    per axis, |v_a| <= speed[a]).
//  - Swept: the box bounding the object's boxes along a keyframed path over
//    [t, t + validity] (the paper's sweep surfaces, reduced to their bounding
//    box; see sweptTbv for why sampling at the key times is conservative).
//
// 2D shapes live in the x-y plane: z is neither grown nor tested (a box's z
// extent is kept as given, a circle's bounds have the centre's z).
//
// Departures from the paper: sweep surfaces are replaced by their axis-aligned
// bounding box (the paper itself found the exact sweeps slower to insert into
// the octree, section 6), and every shape is made a hair bigger than the exact
// bound (kTbvRelativePad, relative to the shape's size) so that rounding never
// leaves an object at the edge of its reach outside its own TBV.
#pragma once
#include <algorithm>
#include <cstddef>

#include <glm/vec3.hpp>

namespace gridcull {

// The relative pad every TBV gets (see the header comment): 1e-9 of the shape's
// largest extent or of its distance from the origin, whichever is larger.
constexpr double kTbvRelativePad = 1e-9;

// An axis-aligned box, min <= max on every axis used.
struct TbvBox {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
};

enum class TbvShapeKind { Sphere, Box, Swept };
const char* tbvShapeName(TbvShapeKind kind);

struct TbvShape {
    TbvShapeKind kind = TbvShapeKind::Box;
    int dimensions = 3;      // 2: x-y only
    glm::dvec3 centre{0.0};  // Sphere: its centre; Box, Swept: the box's centre
    double radius = 0.0;     // Sphere
    TbvBox box;              // Box and Swept
};

// A sphere (circle in 2D) around `position`: radius = bounding_radius +
// max_speed * validity. max_speed >= 0, validity >= 0, finite unless max_speed
// is 0 (a still object's TBV may last forever); the same for boxTbv.
TbvShape sphereTbv(int dimensions, const glm::dvec3& position, double bounding_radius,
                   double max_speed, double validity);

// The object's box grown by max_speed * validity on every axis used.
TbvShape boxTbv(int dimensions, const TbvBox& object_box, double max_speed, double validity);
// The object's box grown by axis_speed[a] * validity on each axis a used
// (per-axis speed bounds, each >= 0).
TbvShape boxTbv(int dimensions, const TbvBox& object_box, const glm::dvec3& axis_speed,
                double validity);

// The swept volume of a keyframed object over [t, t + validity]: the box
// bounding box_at(s) for s = t, every key time strictly inside the interval,
// and t + validity. `key_times` are the path's key times in increasing order
// (`count` of them); box_at(double) -> TbvBox is the object's box at a time.
//
// Why that is conservative for piecewise-linear keyframes: between two
// consecutive key times the object translates linearly, so each coordinate of
// its box's min and max corners is an affine function of time there, and an
// affine function on an interval takes its extremes at the interval's ends.
// The sample times cut [t, t + validity] into sub-intervals that each lie
// inside one key segment (before the first key and after the last the object
// is held still, also affine), so every box along the way lies inside the box
// around the sampled ones. This does not hold for curved (spline) paths or
// rotating objects: their boxes bulge between samples; give those a Sphere or
// Box TBV from a speed bound instead. Cost O(log keys + keys inside).
template <typename BoxAt>
TbvShape sweptTbv(int dimensions, BoxAt&& box_at, const double* key_times, size_t count, double t,
                  double validity);

// The axis-aligned box around the TBV, for a spatial structure to insert.
TbvBox tbvBounds(const TbvShape& shape);

// Whether the TBV holds `box` entirely (on the axes its dimensions use). For a
// sphere: every corner of the box inside it (a box is the convex hull of its
// corners), so a box whose corners stick out counts as outside even when the
// object inside that box does not; use tbvContainsBall for such objects.
bool tbvContainsBox(const TbvShape& shape, const TbvBox& box);
// Whether the TBV holds the ball (disc in 2D) of `radius` around `centre`.
bool tbvContainsBall(const TbvShape& shape, const glm::dvec3& centre, double radius);

// The box `box` moved by `shift`.
inline TbvBox translated(const TbvBox& box, const glm::dvec3& shift) {
    return {box.min + shift, box.max + shift};
}

// ---------------------------------------------------------------------------
// Implementation of the template.

namespace tbv_detail {
// Grows `box` by the relative pad of kTbvRelativePad.
TbvBox padded(int dimensions, const TbvBox& box);
inline void include(int dimensions, TbvBox& into, const TbvBox& b) {
    for (int a = 0; a < dimensions; ++a) {
        into.min[a] = std::min(into.min[a], b.min[a]);
        into.max[a] = std::max(into.max[a], b.max[a]);
    }
}
}  // namespace tbv_detail

template <typename BoxAt>
TbvShape sweptTbv(int dimensions, BoxAt&& box_at, const double* key_times, size_t count, double t,
                  double validity) {
    const double end = t + validity;
    TbvBox box = box_at(t);
    tbv_detail::include(dimensions, box, box_at(end));
    const double* first = std::upper_bound(key_times, key_times + count, t);
    for (const double* k = first; k != key_times + count && *k < end; ++k)
        tbv_detail::include(dimensions, box, box_at(*k));
    TbvShape shape;
    shape.kind = TbvShapeKind::Swept;
    shape.dimensions = dimensions;
    shape.box = tbv_detail::padded(dimensions, box);
    shape.centre = (shape.box.min + shape.box.max) * 0.5;
    return shape;
}

}  // namespace gridcull
