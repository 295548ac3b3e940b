// The seeded random walk behind `"motion": {"type": "random"}`
// (scene-format.md, "Motion"). The walk is precomputed as one constant velocity
// per segment of `segment_seconds`, each with |v| <= max_speed, plus prefix sums
// so that Scene::displacementAt evaluates it in O(1) without allocating. Scene
// then reflects it at the world bounds like linear motion; reflection flips
// velocity components, so the speed bound still holds.
#pragma once
#include <cstdint>

#include "culling/scene/scene.h"

namespace gridcull {

// Fills motion.segment_velocities / segment_offsets / segment_seconds for
// `segments` segments. The walk depends only on (seed, object_id, dimensions,
// max_speed, segments, segment_seconds), so two loads of one file agree.
// In 2D the z component is 0. Preconditions: motion.max_speed >= 0,
// segments >= 1, segment_seconds > 0. Cost: O(segments), allocates.
void buildRandomWalk(Motion& motion, int dimensions, uint64_t seed, int object_id, int segments,
                     double segment_seconds);

}  // namespace gridcull
