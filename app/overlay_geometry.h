// Lines and translucent fills drawn over the objects: the world box, the grid
// (2D), the culling camera's frustum (3D) or view wedge (2D), outlines of
// false-culled and hovered objects. World coordinates; built on the CPU each
// frame into vectors whose capacity is kept.
#pragma once
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "culling/scene/camera.h"
#include "culling/scene/scene.h"
#include "grid/aabb.h"
#include "ui/debug_draw.h"
#include "ui/object_state.h"

namespace gridcull {

// The debug-draw batch's vertex (ui/debug_draw.h), so overlays and these lines
// share one renderer.
using ColorVertex = DebugDrawBatch::Vertex;

inline glm::vec4 toRgba(Rgb c, float alpha = 1.0f) {
    return {c.r, c.g, c.b, alpha};
}

// Two vertices per segment (GL_LINES).
void appendSegment(std::vector<ColorVertex>& lines, const glm::dvec3& a, const glm::dvec3& b,
                   const glm::vec4& color);
// The 12 edges of a box; in 2D (min.z == max.z) its 4 sides.
void appendBoxEdges(std::vector<ColorVertex>& lines, const Aabb& box, const glm::vec4& color);
// The outline of a 2D object at time t: circle, box or polygon.
void appendOutline2d(std::vector<ColorVertex>& lines, const Scene& scene, const SceneObject& object,
                     double t, const glm::vec4& color);
// The lines of a 2D grid's voxel boundaries.
void appendGridLines2d(std::vector<ColorVertex>& lines, const RegularGrid& grid,
                       const glm::vec4& color);

// How far to draw a camera's view: its far distance, cut to the farthest corner
// of `world` so that a far plane at 1000 units does not dwarf a 100-unit scene.
double viewDrawDistance(const Camera& camera, const Aabb& world);

// 3D: the frustum cut to `world`: its four edges from the eye to where they
// leave the world box (or the far plane, if nearer), the near rectangle, and the
// largest cross-section that lies wholly inside the box, and the view axis out
// to the box's wall. A far plane at 1000 units would otherwise dwarf a 100-unit
// scene. Edges that miss the box end at the distance of the box's centre.
void appendFrustum(std::vector<ColorVertex>& lines, const Camera& camera, const Aabb& world,
                   const glm::vec4& color);
// 2D: the wedge's two sides and its arc at `distance` as lines, and its area as
// triangles (GL_TRIANGLES) in `fill_color`.
void appendWedge(std::vector<ColorVertex>& lines, std::vector<ColorVertex>& fill,
                 const Camera& camera, double distance, const glm::vec4& color,
                 const glm::vec4& fill_color);

}  // namespace gridcull
