// The sweep's scenes at the edges (docs/LIMITS.md): the extremes suite's
// random objects (tests/culling/registry/extremes_scenes.h: spheres, boxes,
// thin walls, 2D polygons, a third moving) in a world from 0.1 to 10^5 units
// wide, now and then shifted up to 10^6 from the origin, with objects of a
// ten-thousandth of a voxel, slivers, boxes larger than the world, and a
// camera that looks from inside an object, grazes a box face (its eye on the
// face's plane, looking along it), or looks in from far outside; near planes
// from 10^-4 of a voxel, far planes cutting the world, fields of view from
// 1 degree up (3D below 170, where the oracle is sound; 2D up to 360).
#pragma once
#include <cstdint>

#include "culling/scene/scene.h"

namespace gridcull::sweep {

Scene extremesScene(uint64_t seed, int dimensions);

}  // namespace gridcull::sweep
