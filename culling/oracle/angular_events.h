// The event angles of the exact 2D oracle (culling/oracle/exact_oracle_2d.h): the
// relative angles (culling/oracle/angular_shape_2d.h) where the front-to-back order
// of two shapes' boundaries, or whether a shape is met within far, can change.
// Between two consecutive events the nearest of two shapes along a ray is the same
// for every ray, so one ray decides the whole interval.
//
// All intersections are closed form (segment-segment, segment-circle,
// circle-circle); each appends the angles of its points that lie strictly inside
// (from, to) to `out`, which must have room (callers reserve; nothing here
// allocates beyond the vector's capacity).
#pragma once
#include <vector>

#include "culling/oracle/angular_shape_2d.h"

namespace gridcull {

// Where a shape's own depth along the ray jumps: its vertices' angles (a
// polygon's nearest edge changes there, or the polygon starts or ends) and a
// circle's two tangent angles (`extent` from angularExtent).
void silhouetteEvents(const AngularShape& shape, const AngularExtent& extent,
                      const AngularFrame& frame, double from, double to, std::vector<double>& out);

// Where a shape's boundary crosses the far circle (radius far around the camera).
void farEvents(const AngularShape& shape, const AngularFrame& frame, double from, double to,
               std::vector<double>& out);

// Where the boundaries of two shapes cross each other.
void crossingEvents(const AngularShape& a, const AngularShape& b, const AngularFrame& frame,
                    double from, double to, std::vector<double>& out);

}  // namespace gridcull
