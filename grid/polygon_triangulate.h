// Triangulation of simple polygons by ear clipping, for drawing 2D scene polygons
// (scene-format.md: "a simple polygon, counter-clockwise"). Pure geometry in the
// x-y plane; z is ignored.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace gridcull {

// Fills `triangles` with indices into `points`, three per triangle, each triangle
// counter-clockwise. A simple polygon of n points gives n - 2 triangles, fewer when
// some points are collinear with their neighbours (those add no area) or repeated.
// Clockwise input is accepted and triangulated with the orientation corrected.
// Returns false when the polygon has fewer than three distinct points, no area, or
// is not simple (ears run out); `triangles` then holds whatever was clipped before
// that, which still lies inside the polygon's outline for every simple prefix.
// Cost: O(n^2) time; `triangles` is cleared and its capacity reused, plus one
// scratch list of n indices.
bool triangulatePolygon(const std::vector<glm::dvec3>& points, std::vector<uint32_t>& triangles);

}  // namespace gridcull
