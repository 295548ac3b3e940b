// The pixel pyramid's geometry (culling/oracle/pixel_pyramid.h) against brute
// force: random spheres and boxes near random pixel pyramids, and a dense fan of
// rays through the pixel square. Whatever a ray meets, the pyramid test must
// keep; no ray may meet the object nearer than the bound, and the bound, exact,
// lies within the fan's coarseness of the least depth the fan meets.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "culling/oracle/pixel_pyramid.h"
#include "culling/scene/ray_intersect.h"
#include "culling/scene/seeded_random.h"
#include "grid/aabb.h"

namespace gridcull {
namespace {

constexpr int kFan = 48;  // rays per side of the pixel square, its edges included
constexpr int kCases = 3000;
// The brute force's own rounding: its entry depths are computed in another
// order than the bound's, so they agree to some ulps of the depth, not exactly.
constexpr double kBruteRounding = 1e-9;
// The bounds are exact, the fan is not: its least depth exceeds the true one by
// what the depth changes across one fan spacing, well under this fraction.
constexpr double kLoose = 0.01;

struct Pixel {
    double u0, u1, v0, v1;
};

Pixel randomPixel(SeededRandom& rng) {
    const double du = rng.uniform(1e-3, 0.05), dv = rng.uniform(1e-3, 0.05);
    const double u0 = rng.uniform(-1.0, 1.0), v1 = rng.uniform(-1.0, 1.0);
    return {u0, u0 + du, v1 + dv, v1};
}

// The least depth (view z >= 0) at which any ray of the fan meets the solid
// whose line interval `line` gives; +infinity when none does.
template <typename Line>
double fanLeastDepth(const Pixel& pixel, Line&& line) {
    double least = std::numeric_limits<double>::infinity();
    for (int j = 0; j < kFan; ++j)
        for (int i = 0; i < kFan; ++i) {
            const double u = pixel.u0 + (pixel.u1 - pixel.u0) * i / (kFan - 1);
            const double v = pixel.v1 + (pixel.v0 - pixel.v1) * j / (kFan - 1);
            double s0, s1;
            // Directions of z component 1, so the line parameter is the depth.
            if (!line(glm::dvec3(u, v, 1.0), s0, s1) || s1 < 0.0) continue;
            least = std::min(least, std::max(s0, 0.0));
        }
    return least;
}

TEST(PixelPyramid, SphereBoundIsTheLeastDepthARayMeets) {
    SeededRandom rng(20261203);
    int met = 0, rejected_in_rectangle = 0, tighter = 0, loose = 0;
    for (int n = 0; n < kCases; ++n) {
        const Pixel pixel = randomPixel(rng);
        const double radius = rng.uniform(0.01, 3.0);
        const double z = rng.uniform(-2.0, 40.0);
        // Near the pyramid: the pixel's middle slope at depth z, moved by up to
        // two radii, so that many spheres graze it.
        const glm::dvec3 center{0.5 * (pixel.u0 + pixel.u1) * z + rng.uniform(-2.0, 2.0) * radius,
                                0.5 * (pixel.v0 + pixel.v1) * z + rng.uniform(-2.0, 2.0) * radius, z};
        const PixelPyramid pyramid = pixelPyramid(pixel.u0, pixel.u1, pixel.v0, pixel.v1);
        const double bound = leastSphereDepthInPyramid(pyramid, center, radius);
        const double fan = fanLeastDepth(pixel, [&](const glm::dvec3& dir, double& s0, double& s1) {
            return lineSphere(glm::dvec3(0.0), dir, center, radius, s0, s1);
        });
        EXPECT_EQ(sphereMeetsPyramid(pyramid, center, radius), bound != INFINITY);
        if (fan != INFINITY) {
            ++met;
            ASSERT_LE(bound, fan + kBruteRounding * std::abs(fan))
                << "case " << n << ": a ray meets the sphere nearer than the bound";
            if (bound > center.z - radius + 1e-6) ++tighter;
            if (fan - bound > kLoose * fan) ++loose;
        }
        // Rejected although the four planes, one by one, keep it: the corners
        // of the silhouette's bounding rectangle.
        bool planes_keep = true;
        for (const glm::dvec3& normal : pyramid.normals)
            planes_keep = planes_keep && glm::dot(normal, center) >= -radius * glm::length(normal);
        if (planes_keep && bound == INFINITY) ++rejected_in_rectangle;
    }
    std::printf("[ pyramid ] spheres: %d of %d met by a ray; %d bounds above the sphere's "
                "nearest depth; %d rejected that the four planes alone keep; %d bounds more "
                "than %g below the fan's least depth\n",
                met, kCases, tighter, rejected_in_rectangle, loose, kLoose);
    EXPECT_GT(met, kCases / 10);
    EXPECT_GT(tighter, met / 10);
    EXPECT_LT(loose, met / 100);
    EXPECT_GT(rejected_in_rectangle, 0);
}

// A sphere kept by the test but met by no ray of the fan lies within the fan's
// spacing of the pyramid: the test is exact, not merely safe.
TEST(PixelPyramid, SphereTestIsExactUpToTheFansSpacing) {
    SeededRandom rng(7);
    for (int n = 0; n < kCases; ++n) {
        const Pixel pixel = randomPixel(rng);
        const double radius = rng.uniform(0.01, 3.0);
        const double z = rng.uniform(0.5, 40.0);
        const glm::dvec3 center{0.5 * (pixel.u0 + pixel.u1) * z + rng.uniform(-2.0, 2.0) * radius,
                                0.5 * (pixel.v0 + pixel.v1) * z + rng.uniform(-2.0, 2.0) * radius, z};
        const PixelPyramid pyramid = pixelPyramid(pixel.u0, pixel.u1, pixel.v0, pixel.v1);
        if (!sphereMeetsPyramid(pyramid, center, radius)) continue;
        // Grown by the fan's spacing at the far side of the sphere, a kept sphere
        // must meet some ray of the fan.
        const double spacing = std::max(pixel.u1 - pixel.u0, pixel.v0 - pixel.v1) / (kFan - 1);
        const double grown = radius + spacing * (z + radius);
        const double fan = fanLeastDepth(pixel, [&](const glm::dvec3& dir, double& s0, double& s1) {
            return lineSphere(glm::dvec3(0.0), dir, center, grown, s0, s1);
        });
        ASSERT_NE(fan, INFINITY) << "case " << n << ": kept a sphere well outside the pyramid";
    }
}

TEST(PixelPyramid, BoxBoundIsTheLeastDepthARayMeets) {
    SeededRandom rng(11);
    int met = 0, tighter = 0, loose = 0;
    for (int n = 0; n < kCases; ++n) {
        const Pixel pixel = randomPixel(rng);
        // A world box seen by a camera of random orientation at the origin: its
        // corners in view space, and rays turned back into world space.
        const glm::dvec3 forward = glm::normalize(
            glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) +
            glm::dvec3(0, 0, 1e-3));
        const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
        const glm::dvec3 up = glm::cross(right, forward);
        const double z = rng.uniform(-2.0, 40.0);
        const glm::dvec3 middle = forward * z +
                                  right * (0.5 * (pixel.u0 + pixel.u1) * z) +
                                  up * (0.5 * (pixel.v0 + pixel.v1) * z);
        const glm::dvec3 half{rng.uniform(0.01, 3.0), rng.uniform(0.01, 3.0), rng.uniform(0.01, 3.0)};
        const glm::dvec3 offset{rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)};
        const Aabb box{middle + offset * half - half, middle + offset * half + half};
        glm::dvec3 corners[8];
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 p = box.corner(c);
            corners[c] = {glm::dot(p, right), glm::dot(p, up), glm::dot(p, forward)};
        }
        const PixelPyramid pyramid = pixelPyramid(pixel.u0, pixel.u1, pixel.v0, pixel.v1);
        const double bound = leastBoxDepthInPyramid(pyramid, corners);
        const double fan = fanLeastDepth(pixel, [&](const glm::dvec3& dir, double& s0, double& s1) {
            const glm::dvec3 world = dir.x * right + dir.y * up + dir.z * forward;
            return lineBox(glm::dvec3(0.0), world, box, s0, s1);
        });
        if (fan == INFINITY) continue;
        ++met;
        ASSERT_LE(bound, fan + kBruteRounding * std::abs(fan))
            << "case " << n << ": a ray meets the box nearer than the bound";
        double nearest_corner = INFINITY;
        for (const glm::dvec3& c : corners) nearest_corner = std::min(nearest_corner, c.z);
        if (bound > nearest_corner + 1e-6) ++tighter;
        if (fan - bound > kLoose * fan) ++loose;
    }
    std::printf("[ pyramid ] boxes: %d of %d met by a ray; %d bounds above the box's nearest "
                "corner; %d more than %g below the fan's least depth\n",
                met, kCases, tighter, loose, kLoose);
    EXPECT_GT(met, kCases / 10);
    EXPECT_GT(tighter, met / 10);
    EXPECT_LT(loose, met / 100);
}

}  // namespace
}  // namespace gridcull
