// TBV shapes (culling/tbv/tbv_shapes.h, Sudarsky & Gotsman sections 3.2 and
// 3.3): a sphere or box made from a maximum speed holds the object at every
// position it can reach within the validity period (random directions, speeds
// and times, the edge of the reach included); a swept box holds the object's
// box at every time of the period along random piecewise-linear keyframed
// paths; the containment tests say no when they must.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "culling/scene/seeded_random.h"
#include "culling/tbv/tbv_shapes.h"
#include "tests/common/test_seeds.h"

namespace gridcull {
namespace {

glm::dvec3 randomPoint(SeededRandom& rng, int dims, double extent) {
    glm::dvec3 p(rng.uniform(-extent, extent), rng.uniform(-extent, extent), 0.0);
    if (dims == 3) p.z = rng.uniform(-extent, extent);
    return p;
}

TbvBox randomBox(SeededRandom& rng, int dims, double extent) {
    const glm::dvec3 c = randomPoint(rng, dims, extent);
    glm::dvec3 h(rng.uniform(0.01, 3.0), rng.uniform(0.01, 3.0), 0.0);
    if (dims == 3) h.z = rng.uniform(0.01, 3.0);
    return {c - h, c + h};
}

// The box of half-size r around p on the axes used (flat in z in 2D).
TbvBox toyBoxAround(const glm::dvec3& p, int dims, double r) {
    glm::dvec3 h(r, r, dims == 3 ? r : 0.0);
    return {p - h, p + h};
}

// A fraction of the reach: 1 (the edge) a quarter of the time, else uniform.
double reachFraction(SeededRandom& rng) {
    return rng.uniform() < 0.25 ? 1.0 : rng.uniform();
}

TEST(TbvShapes, SphereAndBoxHoldEveryPositionReachableAtMaxSpeed) {
    for (const uint64_t seed : test::seedsToRun(100, 6)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            for (int trial = 0; trial < 400; ++trial) {
                const int dims = trial % 2 == 0 ? 2 : 3;
                // Positions far from the origin too, where rounding is coarse.
                const double extent = trial % 5 == 0 ? 1e6 : 50.0;
                const glm::dvec3 p0 = randomPoint(rng, dims, extent);
                const double radius = rng.uniform(0.0, 2.0);
                const double speed = rng.uniform() < 0.1 ? 0.0 : rng.uniform(0.0, 20.0);
                const double validity = rng.uniform(0.001, 10.0);
                const TbvBox box0 = toyBoxAround(p0, dims, radius);
                const TbvShape sphere = sphereTbv(dims, p0, radius, speed, validity);
                const TbvShape box = boxTbv(dims, box0, speed, validity);
                for (int k = 0; k < 100; ++k) {
                    const glm::dvec3 d = randomDirection(rng, dims);
                    const double tau = validity * reachFraction(rng);
                    const double s = speed * reachFraction(rng);
                    const glm::dvec3 p = p0 + d * (s * tau);
                    ASSERT_TRUE(tbvContainsBall(sphere, p, radius))
                        << "trial " << trial << " dims " << dims << " speed " << speed
                        << " validity " << validity;
                    ASSERT_TRUE(tbvContainsBox(box, translated(box0, p - p0)))
                        << "trial " << trial << " dims " << dims;
                    // The bounding box a structure inserts holds the shape's reach too.
                    ASSERT_TRUE(tbvContainsBox(
                        TbvShape{TbvShapeKind::Box, dims, {}, 0.0, tbvBounds(sphere)},
                        toyBoxAround(p, dims, radius)));
                }
                // And is not much bigger: a ball 0.1% past the reach is outside.
                const glm::dvec3 d = randomDirection(rng, dims);
                const double beyond = speed * validity * 1.001 + 1e-2;  // > the pad at 1e6
                EXPECT_FALSE(tbvContainsBall(sphere, p0 + d * beyond, radius));
            }
        });
    }
}

TEST(TbvShapes, PerAxisBoxHoldsEveryVelocityWithinTheAxisBounds) {
    for (const uint64_t seed : test::seedsToRun(200, 6)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            for (int trial = 0; trial < 400; ++trial) {
                const int dims = trial % 2 == 0 ? 2 : 3;
                const TbvBox box0 = randomBox(rng, dims, trial % 5 == 0 ? 1e6 : 50.0);
                const glm::dvec3 bound(rng.uniform(0.0, 5.0), rng.uniform(0.0, 5.0),
                                       rng.uniform(0.0, 5.0));
                const double validity = rng.uniform(0.001, 10.0);
                const TbvShape box = boxTbv(dims, box0, bound, validity);
                for (int k = 0; k < 100; ++k) {
                    glm::dvec3 v(0.0);
                    for (int a = 0; a < dims; ++a)
                        v[a] = bound[a] * reachFraction(rng) * (rng.uniform() < 0.5 ? -1 : 1);
                    const double tau = validity * reachFraction(rng);
                    ASSERT_TRUE(tbvContainsBox(box, translated(box0, v * tau)))
                        << "trial " << trial << " dims " << dims;
                }
            }
        });
    }
}

// A keyframed path: positions at increasing key times, linear between them,
// held before the first and after the last (culling/scene's Keyframes motion).
struct KeyPath {
    std::vector<double> times;
    std::vector<glm::dvec3> positions;
    glm::dvec3 at(double t) const {
        if (t <= times.front()) return positions.front();
        if (t >= times.back()) return positions.back();
        const size_t k = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin());
        const double u = (t - times[k - 1]) / (times[k] - times[k - 1]);
        return positions[k - 1] + (positions[k] - positions[k - 1]) * u;
    }
};

TEST(TbvShapes, SweptBoxHoldsTheObjectAlongRandomKeyframedPaths) {
    for (const uint64_t seed : test::seedsToRun(300, 8)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            for (int trial = 0; trial < 200; ++trial) {
                const int dims = trial % 2 == 0 ? 2 : 3;
                KeyPath path;
                const int keys = 1 + int(rng.below(9));
                double t = rng.uniform(-5.0, 5.0);
                for (int k = 0; k < keys; ++k) {
                    path.times.push_back(t);
                    path.positions.push_back(randomPoint(rng, dims, 30.0));
                    t += rng.uniform(0.05, 3.0);
                }
                const TbvBox local = randomBox(rng, dims, 0.0);  // around the anchor
                auto box_at = [&](double s) { return translated(local, path.at(s)); };
                const double span = path.times.back() - path.times.front();
                const double t0 = rng.uniform(path.times.front() - 2.0, path.times.back() + 1.0);
                const double validity = rng.uniform(0.01, span + 2.0);
                const TbvShape swept =
                    sweptTbv(dims, box_at, path.times.data(), path.times.size(), t0, validity);
                EXPECT_EQ(swept.kind, TbvShapeKind::Swept);
                std::vector<double> samples{t0, t0 + validity};
                for (const double k : path.times)
                    if (k >= t0 && k <= t0 + validity) samples.push_back(k);
                for (int k = 0; k < 300; ++k) samples.push_back(t0 + validity * rng.uniform());
                for (const double s : samples)
                    ASSERT_TRUE(tbvContainsBox(swept, box_at(s)))
                        << "trial " << trial << " dims " << dims << " at t = " << s << " of [" << t0
                        << ", " << t0 + validity << "]";
            }
        });
    }
}

TEST(TbvShapes, ContainmentSaysNoWhenTheObjectIsOutside) {
    // A unit sphere at the origin (radius 0 + speed 1 * validity 1).
    const TbvShape s = sphereTbv(3, glm::dvec3(0.0), 0.0, 1.0, 1.0);
    EXPECT_TRUE(tbvContainsBox(s, {glm::dvec3(-0.5), glm::dvec3(0.5)}));
    // A cube whose faces are inside but whose corners stick out (0.7 * sqrt(3) > 1).
    EXPECT_FALSE(tbvContainsBox(s, {glm::dvec3(-0.7), glm::dvec3(0.7)}));
    EXPECT_TRUE(tbvContainsBall(s, glm::dvec3(0.5, 0.0, 0.0), 0.5));
    EXPECT_FALSE(tbvContainsBall(s, glm::dvec3(0.5, 0.0, 0.0), 0.6));
    EXPECT_FALSE(tbvContainsBall(s, glm::dvec3(0.0), 1.5));
    // 2D ignores z, in a circle and in a box.
    const TbvShape c = sphereTbv(2, glm::dvec3(0.0), 0.0, 1.0, 1.0);
    EXPECT_TRUE(tbvContainsBall(c, glm::dvec3(0.0, 0.0, 100.0), 0.5));
    const TbvShape b = boxTbv(2, TbvBox{glm::dvec3(-1, -1, 0), glm::dvec3(1, 1, 0)}, 0.0, 1.0);
    EXPECT_TRUE(tbvContainsBox(b, {glm::dvec3(-1, -1, -5), glm::dvec3(1, 1, 5)}));
    EXPECT_FALSE(tbvContainsBox(b, {glm::dvec3(-1, -1, 0), glm::dvec3(1.001, 1, 0)}));
    // Bounds: a sphere's box is centre +- radius on the axes used.
    const TbvBox sb = tbvBounds(sphereTbv(2, glm::dvec3(1, 2, 3), 1.0, 1.0, 1.0));
    EXPECT_NEAR(sb.min.x, -1.0, 1e-8);
    EXPECT_NEAR(sb.max.y, 4.0, 1e-8);
    EXPECT_EQ(sb.min.z, 3.0);
    EXPECT_EQ(sb.max.z, 3.0);
}

}  // namespace
}  // namespace gridcull
