// The voxel under the pointer, outlined over the rgvc overlay so that the
// voxel the panel describes ("voxel under the mouse") is the one the eye finds:
// 2D its square, 3D its box's twelve edges. White at kBoldLine, as the window
// outlines the object under the pointer; white means "under the pointer" in
// this family's view and nothing else (ui/palette.h).
#pragma once
#include <glm/vec3.hpp>

#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/debug_draw.h"

namespace gridcull {

constexpr Paint kRgvcHoverPaint{Swatch::White, 1.0f};
constexpr float kRgvcHoverWidth = kBoldLine;

// Emits the outline of `voxel` of the snapshot's grid (z ignored in 2D); nothing
// for a voxel outside the grid.
void drawRgvcHoveredVoxel(const RgvcSnapshot& snapshot, const glm::ivec3& voxel, DebugDraw& draw);

}  // namespace gridcull
