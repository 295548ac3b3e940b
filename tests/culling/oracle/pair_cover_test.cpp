// Two objects covering a pixel together (culling/oracle/pair_cover.h): hand-made
// seams, and random pairs against a dense fan of rays through the pixel square.
// Whenever the pair is said to cover the pixel below some depth, every ray of
// the fan must meet one of the two no deeper than that.
#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "culling/oracle/pair_cover.h"
#include "culling/scene/ray_intersect.h"
#include "culling/scene/seeded_random.h"
#include "tests/culling/oracle/square_pixel_view.h"

namespace gridcull {
namespace {

constexpr int kSide = 64;  // pixels of the test image, each way
constexpr int kFan = 24;   // rays per side of the pixel square, its edges included

// The eye at the origin looking down +z, fov 90 each way (square_pixel_view.h).
PixelView testView() {
    return test::squarePixelView(kSide);
}

CoverSolid box(const glm::dvec3& lo, const glm::dvec3& hi) {
    CoverSolid solid;
    solid.box = {lo, hi};
    return solid;
}

CoverSolid sphere(const glm::dvec3& center, double radius) {
    CoverSolid solid;
    solid.sphere = true;
    solid.center = center;
    solid.radius = radius;
    solid.box = {center - radius, center + radius};
    return solid;
}

double cover(const PixelView& view, int px, int py, const CoverSolid& a, const CoverSolid& b) {
    return pairCoverDepth(view, px, py, a, boxSilhouette(view, a.box), b,
                          b.sphere ? Silhouette{} : boxSilhouette(view, b.box));
}

// The greatest depth, over the fan, of the nearer of the two where a ray meets
// either; +infinity when a ray meets neither.
double fanDeepestCover(const PixelView& view, int px, int py, const CoverSolid& a,
                       const CoverSolid& b) {
    double deepest = 0.0;
    for (int j = 0; j < kFan; ++j)
        for (int i = 0; i < kFan; ++i) {
            const glm::dvec3 dir = view.ray(px + double(i) / (kFan - 1), py + double(j) / (kFan - 1));
            double nearest = std::numeric_limits<double>::infinity();
            for (const CoverSolid* solid : {&a, &b}) {
                double s0, s1, s;
                const bool line = solid->sphere
                                      ? lineSphere(view.eye, dir, solid->center, solid->radius, s0, s1)
                                      : lineBox(view.eye, dir, solid->box, s0, s1);
                if (line && solidEntry(s0, s1, view.near, view.far, s)) nearest = std::min(nearest, s);
            }
            deepest = std::max(deepest, nearest);
        }
    return deepest;
}

// Two walls at depth 10 that meet inside pixel column 32 (slopes [0, 1 / 32]),
// at u = 0.3 / 32.
TEST(PairCover, TwoWallsThatTouchCoverThePixelOfTheirSeam) {
    const PixelView view = testView();
    const double seam = 10.0 * 0.3 / 32;
    const CoverSolid left = box({-20, -20, 10}, {seam, 20, 11});
    const CoverSolid right = box({seam, -20, 10}, {20, 20, 11});
    // With the right wall as the polygon, its side face (seen from the eye,
    // reaching back to depth 11) counts in full although the left wall hides
    // it: a bound, not the least one. The refiner takes the least of both orders.
    const double depth = std::min(cover(view, 32, 32, left, right), cover(view, 32, 32, right, left));
    EXPECT_NEAR(depth, 10.0, 1e-6);
    EXPECT_GE(depth * (1 + 1e-9), fanDeepestCover(view, 32, 32, left, right));
}

// Thin walls a hundredth of a pixel apart: the gap is open. (Thick walls would
// close it: seen obliquely, the right wall's side face fills it.)
TEST(PairCover, TwoWallsWithAGapInThePixelLeaveItOpen) {
    const PixelView view = testView();
    const double seam = 10.0 * 0.3 / 32, gap = 10.0 * 0.01 / 32;
    const CoverSolid left = box({-20, -20, 10}, {seam, 20, 10.001});
    const CoverSolid right = box({seam + gap, -20, 10}, {20, 20, 10.001});
    EXPECT_EQ(cover(view, 32, 32, left, right), std::numeric_limits<double>::infinity());
    EXPECT_EQ(cover(view, 32, 32, right, left), std::numeric_limits<double>::infinity());
    EXPECT_EQ(fanDeepestCover(view, 32, 32, left, right), std::numeric_limits<double>::infinity());
}

// A trunk entering its crown: a box whose top is inside a sphere.
TEST(PairCover, ABoxEnteringASphereCoversThePixelWhereItEnters) {
    const PixelView view = testView();
    // The trunk spans pixel columns 31 and 32; its top (v = 0.09, row 29) is
    // inside the crown, whose bottom shows at v = 0.05 (row 30).
    const CoverSolid trunk = box({-0.5, -5, 9.7}, {0.5, 0.9, 10.3});
    const CoverSolid crown = sphere({0, 2, 10}, 1.5);
    int covered = 0;
    for (int py = 20; py < 32; ++py) {
        const double depth = cover(view, 32, py, trunk, crown);
        if (depth == std::numeric_limits<double>::infinity()) continue;
        ++covered;
        EXPECT_GE(depth * (1 + 1e-9), fanDeepestCover(view, 32, py, trunk, crown));
    }
    EXPECT_GT(covered, 0);
}

TEST(PairCover, NeverClaimsMoreThanARayFanSees) {
    const PixelView view = testView();
    SeededRandom rng(20261203);
    int claimed = 0;
    for (int n = 0; n < 4000; ++n) {
        const int px = int(rng.uniform(1, kSide - 1)), py = int(rng.uniform(1, kSide - 1));
        const double z = rng.uniform(0.5, 30.0);
        // Near the pixel's middle at depth z, sized about one to three pixels
        // there, so that outlines cross the pixel often.
        const glm::dvec3 at = glm::dvec3((px + 0.5) / 32 - 1, 1 - (py + 0.5) / 32, 1.0) * z;
        const double pixel = z / 32;
        auto jitter = [&] {
            return glm::dvec3(rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), rng.uniform(0, 3)) * pixel;
        };
        auto size = [&] {
            return glm::dvec3(rng.uniform(0.3, 2), rng.uniform(0.3, 2), rng.uniform(0.3, 2)) * pixel;
        };
        const glm::dvec3 a_at = at + jitter();
        const CoverSolid a = box(a_at - size(), a_at + size());
        const glm::dvec3 b_at = at + jitter();
        const CoverSolid b = rng.uniform() < 0.5 ? box(b_at - size(), b_at + size())
                                                : sphere(b_at, rng.uniform(0.3, 2) * pixel);
        const double depth = cover(view, px, py, a, b);
        if (depth == std::numeric_limits<double>::infinity()) continue;
        ++claimed;
        const double fan = fanDeepestCover(view, px, py, a, b);
        ASSERT_NE(fan, std::numeric_limits<double>::infinity())
            << "case " << n << ": a ray of the fan meets neither";
        ASSERT_GE(depth * (1 + 1e-9), fan) << "case " << n << ": a ray meets the pair deeper";
    }
    std::printf("[ pair ] %d of 4000 random pairs cover their pixel\n", claimed);
    EXPECT_GT(claimed, 100);
}

// A box's outline meets exactly the pixels some ray through the square meets
// the box in: never fewer, and more only where the box grazes the square
// between the fan's rays.
TEST(PairCover, ABoxOutlineMeetsThePixelsItsRaysMeet) {
    const PixelView view = testView();
    SeededRandom rng(5);
    int met = 0, grazed = 0;
    for (int n = 0; n < 4000; ++n) {
        const int px = int(rng.uniform(1, kSide - 1)), py = int(rng.uniform(1, kSide - 1));
        const double z = rng.uniform(-1.0, 30.0);
        const double pixel = std::max(std::abs(z), 1.0) / 32;
        const glm::dvec3 at = glm::dvec3((px + 0.5) / 32 - 1, 1 - (py + 0.5) / 32, 1.0) * z +
                              glm::dvec3(rng.uniform(-3, 3), rng.uniform(-3, 3), 0) * pixel;
        const glm::dvec3 half =
            glm::dvec3(rng.uniform(0.1, 2), rng.uniform(0.1, 2), rng.uniform(0.1, 2)) * pixel;
        const CoverSolid solid = box(at - half, at + half);
        if (solid.box.contains(view.eye)) continue;
        const Silhouette outline = boxSilhouette(view, solid.box);
        const bool meets = outline.count >= 3 && outlineMeetsPixel(outline, px, py);
        bool fan = false;
        for (int j = 0; j < kFan && !fan; ++j)
            for (int i = 0; i < kFan && !fan; ++i) {
                double s0, s1, s;
                const glm::dvec3 dir = view.ray(px + double(i) / (kFan - 1), py + double(j) / (kFan - 1));
                fan = lineBox(view.eye, dir, solid.box, s0, s1) &&
                      solidEntry(s0, s1, view.near, view.far, s);
            }
        if (fan) {
            ++met;
            ASSERT_TRUE(meets) << "case " << n << ": a ray meets the box, the outline misses the pixel";
        } else if (meets) {
            ++grazed;
        }
    }
    std::printf("[ outline ] %d pixels met by a ray, %d more by the outline alone\n", met, grazed);
    EXPECT_GT(met, 500);
    EXPECT_LT(grazed, met / 10);
}

}  // namespace
}  // namespace gridcull
