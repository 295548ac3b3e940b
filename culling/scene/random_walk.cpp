#include "culling/scene/random_walk.h"

#include <cassert>
#include <cmath>

#include "culling/scene/seeded_random.h"

namespace gridcull {

void buildRandomWalk(Motion& motion, int dimensions, uint64_t seed, int object_id, int segments,
                     double segment_seconds) {
    assert(segments >= 1 && segment_seconds > 0.0 && motion.max_speed >= 0.0);
    SeededRandom rng(seed, uint64_t(uint32_t(object_id)) | (uint64_t(0x52414e44) << 32));
    motion.segment_seconds = segment_seconds;
    motion.segment_velocities.resize(size_t(segments));
    motion.segment_offsets.resize(size_t(segments) + 1);
    motion.segment_offsets[0] = glm::dvec3(0.0);
    for (int i = 0; i < segments; ++i) {
        // Speeds between a quarter of and the full maximum: the walk keeps moving
        // and still reaches the bound that its temporal bounding volumes assume.
        const double speed = motion.max_speed * rng.uniform(0.25, 1.0);
        glm::dvec3 v = randomDirection(rng, dimensions) * speed;
        motion.segment_velocities[size_t(i)] = v;
        motion.segment_offsets[size_t(i) + 1] =
            motion.segment_offsets[size_t(i)] + v * segment_seconds;
    }
}

}  // namespace gridcull
