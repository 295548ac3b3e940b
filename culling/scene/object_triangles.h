// How many triangles an object stands for when it is drawn: the papers' "triangles
// drawn" (Hey et al. Fig. 7; Kovalcik & Sochor Table 1). A mesh counts its own
// triangles, a box 12, a sphere kSphereTriangles (the window's finest sphere, 32
// slices x 16 stacks, two triangles per quad), a polygon (2D) 0.
#pragma once
#include <cstdint>

#include "culling/scene/scene.h"

namespace gridcull {

constexpr int64_t kSphereTriangles = 2 * 32 * 16;
constexpr int64_t kBoxTriangles = 12;

int64_t trianglesOf(const SceneObject& object);

}  // namespace gridcull
