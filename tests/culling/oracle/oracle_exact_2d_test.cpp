// The exact 2D oracle (culling/oracle/exact_oracle_2d.h, the default --oracle-rays 0)
// on hand-made slivers: objects seen only through angular spans far narrower than
// one ray of the default sampled sweep (16384 rays per turn, 0.022 degrees), which
// the sweep misses and the exact oracle must find; and spans closed exactly, which
// must show nothing. Each sliver is checked to be one by a single exact ray
// (referenceHits2d) through it, and by the sweep missing it.
// Unless a test says otherwise: world [0, 100]^2, camera at (5, 50) looking down +x,
// a 90 degree wedge (its middle, world angle 0, falls on a border between two rays
// of the default sweep), far 1000.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "culling/oracle/exact_oracle.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/oracle/oracle_brute_force.h"

namespace gridcull {
namespace {

using test::addBox;
using test::addPolygon;
using test::addSphere;
using V = std::vector<int>;

constexpr double kPi = 3.141592653589793;
// One ten-thousandth of a degree, about 1/220 of a default sweep ray's span.
constexpr double kGap = 1e-4 * kPi / 180.0;
const glm::dvec3 kEye{5, 50, 0};

V exactIds(const Scene& scene, double t = 0.0) {
    ExactOracle oracle;
    return test::cullIds(oracle, scene, t);
}

V sweepIds(const Scene& scene, int rays_per_turn = 16384) {
    OracleOptions options;
    options.rays_per_turn = rays_per_turn;
    ExactOracle oracle{options};
    return test::cullIds(oracle, scene, 0.0);
}

// The id of the object a single exact ray from `eye` at world angle `angle` meets
// first, -1 for none.
int nearestAt(const Scene& scene, const glm::dvec3& eye, double angle) {
    std::vector<std::pair<double, int>> hits;
    test::referenceHits2d(scene, 0.0, eye, {std::cos(angle), std::sin(angle), 0.0},
                          scene.camera.far, hits);
    if (hits.empty()) return -1;
    return std::min_element(hits.begin(), hits.end())->second;
}

Scene looking(const glm::dvec3& eye, const glm::dvec3& target, double fov = 90.0) {
    Scene scene = test::scene2d();
    test::setCamera(scene, eye, target, fov);
    return scene;
}

// Two boxes at x 40..42 leave a slit around the ray y = 50 that spans `gap`
// radians as seen from kEye (half below, half above), a circle behind it.
void slitScene(Scene& scene, double gap) {
    addBox(scene, 1, {40, 0, 0}, {42, 50 - 37 * std::tan(gap / 2), 0});
    addBox(scene, 2, {40, 50 + 35 * std::tan(gap / 2), 0}, {42, 100, 0});
    addSphere(scene, 3, {80, 50, 0}, 3);
}

TEST(OracleExact2d, SeesThroughASlitOfATenThousandthDegree) {
    Scene scene = looking(kEye, {100, 50, 0});
    slitScene(scene, kGap);
    scene.finalize();
    ASSERT_EQ(nearestAt(scene, kEye, 0.0), 3);  // a real sliver
    EXPECT_EQ(exactIds(scene), (V{1, 2, 3}));
    EXPECT_EQ(sweepIds(scene), (V{1, 2}));  // narrower than one ray
}

TEST(OracleExact2d, AClosedSlitShowsNothing) {
    Scene scene = looking(kEye, {100, 50, 0});
    slitScene(scene, 0.0);  // the boxes touch along y = 50
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{1, 2}));
    // Silhouettes that touch only as seen from the camera: a near box below the ray
    // y = 50 and a far one above it, both with corners on it.
    Scene apart = looking(kEye, {100, 50, 0});
    addBox(apart, 1, {40, 0, 0}, {42, 50, 0});
    addBox(apart, 2, {60, 50, 0}, {62, 100, 0});
    addSphere(apart, 3, {80, 50, 0}, 3);
    apart.finalize();
    EXPECT_EQ(exactIds(apart), (V{1, 2}));
}

// A circle tangent to the ray y = 50 from below, behind a box whose silhouette
// ends on that ray, meets the view in one angle only: hidden. Raised by 0.001 it
// pokes through a span of about 1.3e-5 radians: seen.
TEST(OracleExact2d, TangentCircleBehindASilhouette) {
    for (const double lift : {0.0, 1e-3}) {
        SCOPED_TRACE(lift);
        Scene scene = looking(kEye, {100, 50, 0});
        addBox(scene, 1, {40, 0, 0}, {42, 50, 0});
        addBox(scene, 2, {20, 60, 0}, {22, 100, 0});  // keeps the upper half busy
        addSphere(scene, 3, {80, 47 + lift, 0}, 3);
        scene.finalize();
        if (lift == 0.0) {
            EXPECT_EQ(exactIds(scene), (V{1, 2}));
        } else {
            ASSERT_EQ(nearestAt(scene, kEye, 0.5e-5), 3);
            EXPECT_EQ(exactIds(scene), (V{1, 2, 3}));
            EXPECT_EQ(sweepIds(scene), (V{1, 2}));
        }
    }
}

// A thin triangle crosses the box's front face: its tip pokes 1e-5 in front of
// it, a span of about 1e-8 radians; found only where the two boundaries cross.
TEST(OracleExact2d, PolygonCrossingAnothersBoundary) {
    Scene scene = looking(kEye, {100, 50, 0});
    addBox(scene, 1, {40, 40, 0}, {60, 60, 0});
    addPolygon(scene, 2, {{40 - 1e-5, 50, 0}, {70, 49, 0}, {70, 51, 0}});
    addSphere(scene, 3, {80, 50, 0}, 3);  // behind both
    scene.finalize();
    ASSERT_EQ(nearestAt(scene, kEye, 0.0), 2);
    EXPECT_EQ(exactIds(scene), (V{1, 2}));
    EXPECT_EQ(sweepIds(scene), (V{1}));
}

// A circle whose nearest point lies 1e-9 inside far, half hidden by a box whose
// silhouette is the ray y = 50: the lens inside far spans about 1.5e-6 radians
// each side of that ray, so the half left open is seen only between far's
// crossings of the circle.
TEST(OracleExact2d, ObjectCutByFar) {
    Scene scene = looking(kEye, {100, 50, 0});
    scene.camera.far = 50.0;
    addBox(scene, 1, {30, 50, 0}, {32, 100, 0});
    addSphere(scene, 2, kEye + glm::dvec3(50 + 3 - 1e-9, 0, 0), 3);
    addSphere(scene, 3, kEye + glm::dvec3(50 + 3 + 1e-6, -10, 0), 3);  // wholly beyond far
    scene.finalize();
    ASSERT_EQ(nearestAt(scene, kEye, -0.5e-6), 2);
    EXPECT_EQ(exactIds(scene), (V{1, 2}));
    EXPECT_EQ(sweepIds(scene), (V{1}));
}

TEST(OracleExact2d, CameraInsideAnObjectSeesOnlyIt) {
    Scene scene = looking(kEye, {100, 50, 0});
    slitScene(scene, kGap);
    addBox(scene, 4, kEye - glm::dvec3(1, 1, 0), kEye + glm::dvec3(1, 1, 0));
    addPolygon(scene, 5, {{4, 49, 0}, {6, 50, 0}, {4, 51, 0}});  // also holds the camera
    scene.finalize();
    const V ids = exactIds(scene);
    ASSERT_EQ(ids.size(), 1u);
    EXPECT_TRUE(ids[0] == 4 || ids[0] == 5);
    // On the boundary counts as inside.
    Scene touching = looking(kEye, {100, 50, 0});
    slitScene(touching, kGap);
    addBox(touching, 4, kEye, kEye + glm::dvec3(1, 1, 0));
    touching.finalize();
    EXPECT_EQ(exactIds(touching), (V{4}));
}

// The slit at world angle pi, on the -pi/pi seam, seen by a camera looking down -x.
TEST(OracleExact2d, SlitOnTheSeam) {
    const glm::dvec3 eye{95, 50, 0};
    Scene scene = looking(eye, {0, 50, 0});
    addBox(scene, 1, {58, 0, 0}, {60, 50 - 37 * std::tan(kGap / 2), 0});
    addBox(scene, 2, {58, 50 + 35 * std::tan(kGap / 2), 0}, {60, 100, 0});
    addSphere(scene, 3, {20, 50, 0}, 3);
    scene.finalize();
    ASSERT_EQ(nearestAt(scene, eye, kPi), 3);
    EXPECT_EQ(exactIds(scene), (V{1, 2, 3}));
    EXPECT_EQ(sweepIds(scene), (V{1, 2}));
}

// fov 360 looking down -x: the wedge's first and last edges are both world angle
// 0, where the slit is; the envelope must join its two ends there.
TEST(OracleExact2d, FullTurnWithTheSlitOnItsEdges) {
    Scene scene = looking(kEye, {0, 50, 0}, 360.0);
    slitScene(scene, kGap);
    addSphere(scene, 4, {2, 50, 0}, 1);  // behind the camera's heading: seen
    scene.finalize();
    ASSERT_EQ(nearestAt(scene, kEye, 0.0), 3);
    EXPECT_EQ(exactIds(scene), (V{1, 2, 3, 4}));
    EXPECT_EQ(sweepIds(scene), (V{1, 2, 4}));
    // Closed, nothing shows through at the edges either.
    Scene closed = looking(kEye, {0, 50, 0}, 360.0);
    slitScene(closed, 0.0);
    closed.finalize();
    EXPECT_EQ(exactIds(closed), (V{1, 2}));
}

// A C-shaped polygon around the camera: the camera sits in its channel, a slit of
// a ten-thousandth of a degree as seen from it, and sees the circle out of its
// mouth; a box across the mouth closes it.
TEST(OracleExact2d, CameraInTheChannelOfANonConvexPolygon) {
    const double lo = 50 - 37 * std::tan(kGap / 2), hi = 50 + 37 * std::tan(kGap / 2);
    for (const bool closed : {false, true}) {
        SCOPED_TRACE(closed ? "closed" : "open");
        Scene scene = looking(kEye, {100, 50, 0});
        addPolygon(scene, 1,
                   {{0, 0, 0},
                    {42, 0, 0},
                    {42, lo, 0},
                    {2, lo, 0},
                    {2, hi, 0},
                    {42, hi, 0},
                    {42, 100, 0},
                    {0, 100, 0}});
        addSphere(scene, 2, {80, 50, 0}, 3);
        if (closed) addBox(scene, 3, {42, 40, 0}, {44, 60, 0});
        scene.finalize();
        if (closed) {
            EXPECT_EQ(exactIds(scene), (V{1, 3}));
        } else {
            ASSERT_EQ(nearestAt(scene, kEye, 0.0), 2);
            EXPECT_EQ(exactIds(scene), (V{1, 2}));
            EXPECT_EQ(sweepIds(scene), (V{1}));
        }
    }
}

// Two overlapping boxes whose left faces lie on one line (walls-2d's walls 0 and
// 3): where the faces coincide both boxes are at the same distance, so both are
// seen, though rounding would hand each ray to one or the other.
TEST(OracleExact2d, CoincidentFacesShowBothObjects) {
    const glm::dvec3 eye{10, 25, 0};
    Scene scene = looking(eye, {10, 100, 0});
    addBox(scene, 0, {20, 0, 0}, {22, 60, 0});
    addBox(scene, 3, {20, 58, 0}, {80, 60, 0});
    scene.finalize();
    EXPECT_EQ(exactIds(scene), (V{0, 3}));
}

}  // namespace
}  // namespace gridcull
