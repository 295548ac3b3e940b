// Checks on 2D polygons (`"shape": "polygon"`, scene-format.md): the format asks
// for a simple polygon in counter-clockwise order, which the 2D cullers rely on
// (an inside test by winding, outward edge normals on the right of each edge).
#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "grid/polygon_area.h"  // signedDoubleArea

namespace gridcull {

// Empty when `points` (x-y plane, z ignored) form a simple polygon with at
// least 3 corners in counter-clockwise order; otherwise what is wrong, phrased
// to follow "must be a simple counter-clockwise polygon: ". Cost: O(n^2) in
// the corner count, so callers limit n.
std::string checkSimpleCounterClockwise(const std::vector<glm::dvec3>& points);

}  // namespace gridcull
