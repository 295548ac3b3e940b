// A small deterministic random source for scene generation and random motion.
// The scene format promises that a file always means the same scene, so the
// numbers must not depend on the standard library's distributions (their
// algorithms differ between implementations); SplitMix64 with hand-written
// mappings gives the same sequence everywhere. Not for cryptography.
#pragma once
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

namespace gridcull {

class SeededRandom {
public:
    explicit SeededRandom(uint64_t seed) : state_(seed) {}
    // Two seeds combined into one stream, e.g. (scene seed, object id).
    SeededRandom(uint64_t seed, uint64_t stream)
        : state_(seed ^ mix(stream + 0x632be59bd9b4e019ull)) {}

    uint64_t next() {
        state_ += 0x9e3779b97f4a7c15ull;
        return mix(state_);
    }
    // Uniform in [0, 1), 53 random bits.
    double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }
    // Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform integer in [0, n), n > 0; the modulo bias is below 2^-40 for n < 2^24.
    uint64_t below(uint64_t n) { return next() % n; }

private:
    static uint64_t mix(uint64_t z) {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    uint64_t state_;
};

// A uniformly distributed unit direction: in the x-y plane for 2D, on the
// sphere for 3D (Archimedes: z uniform in [-1, 1], angle uniform).
inline glm::dvec3 randomDirection(SeededRandom& rng, int dimensions) {
    const double angle = rng.uniform(0.0, 6.283185307179586);
    if (dimensions == 2) return {std::cos(angle), std::sin(angle), 0.0};
    const double z = rng.uniform(-1.0, 1.0);
    const double r = std::sqrt(1.0 - z * z);
    return {r * std::cos(angle), r * std::sin(angle), z};
}

}  // namespace gridcull
