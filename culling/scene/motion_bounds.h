// What an object's motion allows, for the algorithms that bound where a hidden
// object can be without following it (temporal bounding volumes): its speed
// bound, where it can ever be, and the ball around its anchor that holds it.
#pragma once
#include "culling/scene/scene.h"

namespace gridcull {

// An upper bound of the object's speed (world units per second): the declared or
// computed max_speed, and whatever its motion data imply (hand-built scenes may
// leave max_speed at 0). 0 for a static object.
double maxSpeedOf(const SceneObject& object);

// Where the object can ever be: linear and random motion fold back at the
// world's walls (Scene::displacementAt), so on each axis where its t = 0 bounds
// fit inside the world it stays in the world, and on the others it stays
// still; a keyframed object stays in the box of its bounds at the keys.
Aabb reachOf(const SceneObject& object, const Aabb& world, int dimensions);

// The radius around the object's anchor that holds the whole shape, in the x-y
// plane (dimensions 2) or in space (3).
double boundingRadiusOf(const SceneObject& object, int dimensions);

}  // namespace gridcull
