// The exact ray-shape intersections (culling/scene/ray_intersect.h) on cases
// computed by hand; the arithmetic is in the comments. Every expected value is a
// short binary fraction the functions compute exactly or to the last bit, so
// they are compared with EXPECT_DOUBLE_EQ (4 ulps), no looser tolerance.
#include <vector>

#include <gtest/gtest.h>
#include <glm/vec3.hpp>

#include "culling/scene/ray_intersect.h"

namespace gridcull {
namespace {

using glm::dvec3;

// ---- solveSphereQuadratic: a s^2 - 2 b s + k = 0 ----

TEST(RayIntersect, SphereQuadraticRootsInOrderOrMiss) {
    double s0 = 0, s1 = 0;
    // a = 1, b = 5, k = 21: disc = 25 - 21 = 4, roots (5 -+ 2) / 1.
    ASSERT_TRUE(solveSphereQuadratic(1.0, 5.0, 21.0, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 3.0);
    EXPECT_DOUBLE_EQ(s1, 7.0);
    // b = -5 (centre behind): roots (-5 -+ 2): both negative, still ordered.
    ASSERT_TRUE(solveSphereQuadratic(1.0, -5.0, 21.0, s0, s1));
    EXPECT_DOUBLE_EQ(s0, -7.0);
    EXPECT_DOUBLE_EQ(s1, -3.0);
    // disc = 25 - 30 < 0: miss. a = 0 and a < 0: no line.
    EXPECT_FALSE(solveSphereQuadratic(1.0, 5.0, 30.0, s0, s1));
    EXPECT_FALSE(solveSphereQuadratic(0.0, 5.0, 21.0, s0, s1));
    EXPECT_FALSE(solveSphereQuadratic(-1.0, 5.0, 21.0, s0, s1));
}

// ---- lineSphere ----

TEST(RayIntersect, LineSphereHitMissTangentInsideAndBehind) {
    double s0 = 0, s1 = 0;
    // Centre (5, 0, 0), r = 2 on the x axis: oc = (5, 0, 0), b = 5, k = 25 - 4 = 21,
    // disc = 4: s = 5 -+ 2.
    ASSERT_TRUE(lineSphere({0, 0, 0}, {1, 0, 0}, {5, 0, 0}, 2.0, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 3.0);
    EXPECT_DOUBLE_EQ(s1, 7.0);
    // Off axis: centre (3, 0, 5), r = 5, dir +z: b = 5, k = 9 + 25 - 25 = 9,
    // disc = 25 - 9 = 16: s = 5 -+ 4 (the point (0, 0, 1) is 5 from the centre).
    ASSERT_TRUE(lineSphere({0, 0, 0}, {0, 0, 1}, {3, 0, 5}, 5.0, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 1.0);
    EXPECT_DOUBLE_EQ(s1, 9.0);
    // Miss: centre (0, 3, 5), r = 2: k = 9 + 25 - 4 = 30 > b^2 = 25.
    EXPECT_FALSE(lineSphere({0, 0, 0}, {0, 0, 1}, {0, 3, 5}, 2.0, s0, s1));
    // Tangent: centre (0, 2, 5), r = 2: k = 4 + 25 - 4 = 25 = b^2, one point at s = 5.
    ASSERT_TRUE(lineSphere({0, 0, 0}, {0, 0, 1}, {0, 2, 5}, 2.0, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 5.0);
    EXPECT_DOUBLE_EQ(s1, 5.0);
    // Origin inside: centre (1, 0, 0), r = 3: b = 1, k = 1 - 9 = -8, disc = 9:
    // s = 1 -+ 3, the interval straddles 0.
    ASSERT_TRUE(lineSphere({0, 0, 0}, {1, 0, 0}, {1, 0, 0}, 3.0, s0, s1));
    EXPECT_DOUBLE_EQ(s0, -2.0);
    EXPECT_DOUBLE_EQ(s1, 4.0);
    // Sign: the same sphere on the other side, centre (-5, 0, 0): b = -5, s = -5 -+ 2.
    ASSERT_TRUE(lineSphere({0, 0, 0}, {1, 0, 0}, {-5, 0, 0}, 2.0, s0, s1));
    EXPECT_DOUBLE_EQ(s0, -7.0);
    EXPECT_DOUBLE_EQ(s1, -3.0);
    // Zero direction: no line.
    EXPECT_FALSE(lineSphere({0, 0, 0}, {0, 0, 0}, {5, 0, 0}, 2.0, s0, s1));
}

TEST(RayIntersect, LineSphereParameterIsInUnitsOfTheDirectionsLength) {
    double s0 = 0, s1 = 0;
    // dir (2, 0, 0): a = 4, b = 2 * 5 = 10, k = 21, disc = 100 - 84 = 16:
    // s = (10 -+ 4) / 4 = 1.5, 3.5, half of the unit-direction 3, 7.
    ASSERT_TRUE(lineSphere({0, 0, 0}, {2, 0, 0}, {5, 0, 0}, 2.0, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 1.5);
    EXPECT_DOUBLE_EQ(s1, 3.5);
    // Origin moved: from (1, 1, 1) towards (6, 1, 1) with dir (0.5, 0, 0): a = 0.25,
    // oc = (5, 0, 0), b = 2.5, k = 21, disc = 6.25 - 5.25 = 1: s = (2.5 -+ 1) / 0.25.
    ASSERT_TRUE(lineSphere({1, 1, 1}, {0.5, 0, 0}, {6, 1, 1}, 2.0, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 6.0);
    EXPECT_DOUBLE_EQ(s1, 14.0);
}

// ---- lineBox ----

const Aabb kBox{{1, -1, -1}, {3, 1, 1}};

TEST(RayIntersect, LineBoxEntersThroughEachFace) {
    struct Case {
        dvec3 origin, dir;
        const char* face;
    };
    // From 3 units outside each face straight at it: the near face at s = 2,
    // the opposite face at s = 4 (x: (1 - -1) / 1 = 2 and (3 - -1) / 1 = 4; for
    // -x: (3 - 5) / -1 = 2 and (1 - 5) / -1 = 4; y, z: the slab is [-1, 1], the
    // origin at -+3).
    const std::vector<Case> cases = {
        {{-1, 0, 0}, {1, 0, 0}, "min x"}, {{5, 0, 0}, {-1, 0, 0}, "max x"},
        {{2, -3, 0}, {0, 1, 0}, "min y"}, {{2, 3, 0}, {0, -1, 0}, "max y"},
        {{2, 0, -3}, {0, 0, 1}, "min z"}, {{2, 0, 3}, {0, 0, -1}, "max z"},
    };
    for (const Case& c : cases) {
        double s0 = 0, s1 = 0;
        ASSERT_TRUE(lineBox(c.origin, c.dir, kBox, s0, s1)) << c.face;
        EXPECT_DOUBLE_EQ(s0, 2.0) << c.face;
        EXPECT_DOUBLE_EQ(s1, 4.0) << c.face;
    }
}

TEST(RayIntersect, LineBoxObliqueMissInsideAndBehind) {
    double s0 = 0, s1 = 0;
    // dir (1, 0.5, 0) from the origin: x slab [1, 3], y slab [-1 / 0.5, 1 / 0.5] =
    // [-2, 2]: in at x = 1 (s = 1), out through the top y = 1 (s = 2).
    ASSERT_TRUE(lineBox({0, 0, 0}, {1, 0.5, 0}, kBox, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 1.0);
    EXPECT_DOUBLE_EQ(s1, 2.0);
    // dir (1, -0.5, 0): y slab [1 / -0.5, -1 / -0.5] swapped to [-2, 2]: the same.
    ASSERT_TRUE(lineBox({0, 0, 0}, {1, -0.5, 0}, kBox, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 1.0);
    EXPECT_DOUBLE_EQ(s1, 2.0);
    // dir (1, 2, 0): x [1, 3], y [-0.5, 0.5]: disjoint, miss.
    EXPECT_FALSE(lineBox({0, 0, 0}, {1, 2, 0}, kBox, s0, s1));
    // Origin inside at (2, 0, 0), dir +x: x slab [(1 - 2), (3 - 2)] = [-1, 1].
    ASSERT_TRUE(lineBox({2, 0, 0}, {1, 0, 0}, kBox, s0, s1));
    EXPECT_DOUBLE_EQ(s0, -1.0);
    EXPECT_DOUBLE_EQ(s1, 1.0);
    // Sign: the box behind the origin (5, 0, 0) looking +x: [(1 - 5), (3 - 5)] = [-4, -2].
    ASSERT_TRUE(lineBox({5, 0, 0}, {1, 0, 0}, kBox, s0, s1));
    EXPECT_DOUBLE_EQ(s0, -4.0);
    EXPECT_DOUBLE_EQ(s1, -2.0);
    // Non-unit direction: dir (4, 0, 0) from (-1, 0, 0): [2 / 4, 4 / 4].
    ASSERT_TRUE(lineBox({-1, 0, 0}, {4, 0, 0}, kBox, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 0.5);
    EXPECT_DOUBLE_EQ(s1, 1.0);
}

TEST(RayIntersect, LineBoxZeroDirectionComponentKeepsOrMissesTheSlab) {
    double s0 = 0, s1 = 0;
    // dir.y = dir.z = 0: y = 0.5 is inside [-1, 1], so only x decides: [2, 4].
    ASSERT_TRUE(lineBox({-1, 0.5, 0}, {1, 0, 0}, kBox, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 2.0);
    EXPECT_DOUBLE_EQ(s1, 4.0);
    // On the slab's boundary (y = 1 = max.y) still counts as inside.
    EXPECT_TRUE(lineBox({-1, 1, 0}, {1, 0, 0}, kBox, s0, s1));
    // y = 1.5 or -1.5 is outside the slab for every s: miss.
    EXPECT_FALSE(lineBox({-1, 1.5, 0}, {1, 0, 0}, kBox, s0, s1));
    EXPECT_FALSE(lineBox({-1, -1.5, 0}, {1, 0, 0}, kBox, s0, s1));
}

TEST(RayIntersect, LineBoxMeetsAFlatTwoDimensionalBox) {
    const Aabb flat{{0, 0, 0}, {2, 2, 0}};  // z min == max == 0
    double s0 = 0, s1 = 0;
    // A 2D line (z = 0, dir.z = 0) from (-1, 1): x slab [1, 3], y and z kept.
    ASSERT_TRUE(lineBox({-1, 1, 0}, {1, 0, 0}, flat, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 1.0);
    EXPECT_DOUBLE_EQ(s1, 3.0);
    // Diagonal in the plane from (-1, -1): x and y slabs both [1, 3].
    ASSERT_TRUE(lineBox({-1, -1, 0}, {1, 1, 0}, flat, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 1.0);
    EXPECT_DOUBLE_EQ(s1, 3.0);
    // Off the plane (z = 0.5, dir.z = 0): outside the z "slab" [0, 0], miss.
    EXPECT_FALSE(lineBox({-1, 1, 0.5}, {1, 0, 0}, flat, s0, s1));
    // Through the plane: z slab is the single s = (0 - -1) / 1 = 1, where x = 1, y = 1.
    ASSERT_TRUE(lineBox({1, 1, -1}, {0, 0, 1}, flat, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 1.0);
    EXPECT_DOUBLE_EQ(s1, 1.0);
}

// ---- solidEntry(s0, s1, s_min, s_max) ----

TEST(RayIntersect, SolidEntryNearAndFarRules) {
    double s = -1;
    // In front: entry at s0.
    ASSERT_TRUE(solidEntry(3.0, 7.0, 0.1, 100.0, s));
    EXPECT_DOUBLE_EQ(s, 3.0);
    // Entry before near (0 < s0 < near <= s1): the near-plane point is inside, s = near.
    ASSERT_TRUE(solidEntry(0.05, 2.0, 0.1, 100.0, s));
    EXPECT_DOUBLE_EQ(s, 0.1);
    // The solid ends before near without holding the origin: not met.
    EXPECT_FALSE(solidEntry(0.02, 0.05, 0.1, 100.0, s));
    // Origin inside (s0 <= 0 <= s1): met at near, even when it ends before near
    // (a camera inside a solid sees nothing else).
    ASSERT_TRUE(solidEntry(-1.0, 1.0, 0.1, 100.0, s));
    EXPECT_DOUBLE_EQ(s, 0.1);
    ASSERT_TRUE(solidEntry(-1.0, 0.05, 0.1, 100.0, s));
    EXPECT_DOUBLE_EQ(s, 0.1);
    ASSERT_TRUE(solidEntry(0.0, 5.0, 0.1, 100.0, s));  // origin on the surface
    EXPECT_DOUBLE_EQ(s, 0.1);
    // Behind the origin: not met.
    EXPECT_FALSE(solidEntry(-7.0, -3.0, 0.1, 100.0, s));
    // Beyond far: not met; exactly at far: met there; straddling far: met at s0.
    EXPECT_FALSE(solidEntry(150.0, 160.0, 0.1, 100.0, s));
    ASSERT_TRUE(solidEntry(100.0, 110.0, 0.1, 100.0, s));
    EXPECT_DOUBLE_EQ(s, 100.0);
    ASSERT_TRUE(solidEntry(90.0, 120.0, 0.1, 100.0, s));
    EXPECT_DOUBLE_EQ(s, 90.0);
}

// ---- lineTriangle ----

// The triangle (0, 0, 5), (2, 0, 5), (0, 2, 5) in the plane z = 5.
const dvec3 kA{0, 0, 5}, kB{2, 0, 5}, kC{0, 2, 5};

TEST(RayIntersect, LineTriangleHitsFromEitherSideAtAnySign) {
    double s = 0;
    // From (0.5, 0.5, 0) along +z: the plane at s = 5 / 1 (barycentrics 0.25, 0.25).
    ASSERT_TRUE(lineTriangle({0.5, 0.5, 0}, {0, 0, 1}, kA, kB, kC, s));
    EXPECT_DOUBLE_EQ(s, 5.0);
    // Twice the direction: s = 5 / 2.
    ASSERT_TRUE(lineTriangle({0.5, 0.5, 0}, {0, 0, 2}, kA, kB, kC, s));
    EXPECT_DOUBLE_EQ(s, 2.5);
    // Pointing away: the line still meets it, at s = 5 / -1.
    ASSERT_TRUE(lineTriangle({0.5, 0.5, 0}, {0, 0, -1}, kA, kB, kC, s));
    EXPECT_DOUBLE_EQ(s, -5.0);
    // From the other side (z = 10) along +z: behind, s = (5 - 10) / 1.
    ASSERT_TRUE(lineTriangle({0.5, 0.5, 10}, {0, 0, 1}, kA, kB, kC, s));
    EXPECT_DOUBLE_EQ(s, -5.0);
    // Two-sided: the reversed winding gives the same hit.
    ASSERT_TRUE(lineTriangle({0.5, 0.5, 0}, {0, 0, 1}, kA, kC, kB, s));
    EXPECT_DOUBLE_EQ(s, 5.0);
    // Oblique: from (0, 0, 0) with dir (0.1, 0.2, 1) the plane z = 5 is reached at
    // s = 5, the point (0.5, 1, 5), inside (x + y = 1.5 <= 2).
    ASSERT_TRUE(lineTriangle({0, 0, 0}, {0.1, 0.2, 1}, kA, kB, kC, s));
    EXPECT_DOUBLE_EQ(s, 5.0);
}

TEST(RayIntersect, LineTriangleEdgesCountMissesAndParallelDoNot) {
    double s = 0;
    // On the edge AB (y = 0) and at the vertex A: hits.
    EXPECT_TRUE(lineTriangle({1, 0, 0}, {0, 0, 1}, kA, kB, kC, s));
    EXPECT_TRUE(lineTriangle({0, 0, 0}, {0, 0, 1}, kA, kB, kC, s));
    // Outside the hypotenuse (x + y = 3 > 2), and at negative x: misses.
    EXPECT_FALSE(lineTriangle({1.5, 1.5, 0}, {0, 0, 1}, kA, kB, kC, s));
    EXPECT_FALSE(lineTriangle({-0.5, 0.5, 0}, {0, 0, 1}, kA, kB, kC, s));
    // Parallel to the plane: no hit, even through it (det = 0).
    EXPECT_FALSE(lineTriangle({-1, 0.5, 5}, {1, 0, 0}, kA, kB, kC, s));
}

// ---- 2D: raySegment2d ----

TEST(RayIntersect, RaySegmentHitEndsBehindAndParallel) {
    const dvec3 a{2, -1, 0}, b{2, 1, 0};  // the segment x = 2, y in [-1, 1]
    double s = 0;
    // denom = dir.x * (b - a).y - dir.y * (b - a).x = 1 * 2 = 2, w = a - o = (2, -1):
    // s = (2 * 2 - (-1) * 0) / 2 = 2, segment u = (2 * 0 - (-1) * 1) / 2 = 0.5.
    ASSERT_TRUE(raySegment2d({0, 0, 0}, {1, 0, 0}, a, b, s));
    EXPECT_DOUBLE_EQ(s, 2.0);
    // dir (2, 0, 0): s halves to 1.
    ASSERT_TRUE(raySegment2d({0, 0, 0}, {2, 0, 0}, a, b, s));
    EXPECT_DOUBLE_EQ(s, 1.0);
    // Through the end b (u = 1) and the end a (u = 0): hits.
    ASSERT_TRUE(raySegment2d({0, 1, 0}, {1, 0, 0}, a, b, s));
    EXPECT_DOUBLE_EQ(s, 2.0);
    EXPECT_TRUE(raySegment2d({0, -1, 0}, {1, 0, 0}, a, b, s));
    // Past the end (y = 1.5), behind the ray (dir -x: s = -2), parallel: misses.
    EXPECT_FALSE(raySegment2d({0, 1.5, 0}, {1, 0, 0}, a, b, s));
    EXPECT_FALSE(raySegment2d({0, 0, 0}, {-1, 0, 0}, a, b, s));
    EXPECT_FALSE(raySegment2d({0, 0, 0}, {0, 1, 0}, a, b, s));
    // From the other side, looking -x: s = (0 - 2) / -1 = 2.
    ASSERT_TRUE(raySegment2d({4, 0.5, 0}, {-1, 0, 0}, a, b, s));
    EXPECT_DOUBLE_EQ(s, 2.0);
}

// ---- 2D: pointInPolygon2d and rayPolygonEdges2d ----

// The square [0, 4]^2, counter-clockwise, placed with an offset of (10, 0).
const std::vector<dvec3> kSquare = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}};
const dvec3 kOffset{10, 0, 0};
// An L: the square [0, 4]^2 without [1, 4] x [1, 4] (concave, counter-clockwise).
const std::vector<dvec3> kEll = {{0, 0, 0}, {4, 0, 0}, {4, 1, 0}, {1, 1, 0}, {1, 4, 0}, {0, 4, 0}};

TEST(RayIntersect, PointInPolygonHonoursTheOffsetAndConcavity) {
    // (12, 2) is (2, 2) in the square's own frame: inside; (2, 2) would be inside
    // only without the offset; (15, 2) is past the right edge.
    EXPECT_TRUE(pointInPolygon2d({12, 2, 0}, kSquare.data(), kSquare.size(), kOffset));
    EXPECT_FALSE(pointInPolygon2d({2, 2, 0}, kSquare.data(), kSquare.size(), kOffset));
    EXPECT_FALSE(pointInPolygon2d({15, 2, 0}, kSquare.data(), kSquare.size(), kOffset));
    EXPECT_FALSE(pointInPolygon2d({12, -1, 0}, kSquare.data(), kSquare.size(), kOffset));
    // The L: both arms inside (one edge crosses their row to their right), the
    // notch and the point left of it outside (none, and two: x = 1 and x = 0).
    const dvec3 none{0, 0, 0};
    EXPECT_TRUE(pointInPolygon2d({0.5, 3, 0}, kEll.data(), kEll.size(), none));
    EXPECT_TRUE(pointInPolygon2d({3, 0.5, 0}, kEll.data(), kEll.size(), none));
    EXPECT_FALSE(pointInPolygon2d({2, 2, 0}, kEll.data(), kEll.size(), none));
    EXPECT_FALSE(pointInPolygon2d({-0.5, 2, 0}, kEll.data(), kEll.size(), none));
}

TEST(RayIntersect, RayPolygonEdgesFindsTheNearestEdgeAhead) {
    double s = 0;
    // From (0, 2) along +x: edges x = 10 (s = 10) and x = 14 (s = 14): the nearer.
    ASSERT_TRUE(
        rayPolygonEdges2d({0, 2, 0}, {1, 0, 0}, kSquare.data(), kSquare.size(), kOffset, s));
    EXPECT_DOUBLE_EQ(s, 10.0);
    // dir (2, 0, 0): s = 10 / 2.
    ASSERT_TRUE(
        rayPolygonEdges2d({0, 2, 0}, {2, 0, 0}, kSquare.data(), kSquare.size(), kOffset, s));
    EXPECT_DOUBLE_EQ(s, 5.0);
    // From inside (12, 2): the edge x = 10 is behind, x = 14 ahead at s = 2;
    // looking -x it is the other way round, also s = 2.
    ASSERT_TRUE(
        rayPolygonEdges2d({12, 2, 0}, {1, 0, 0}, kSquare.data(), kSquare.size(), kOffset, s));
    EXPECT_DOUBLE_EQ(s, 2.0);
    ASSERT_TRUE(
        rayPolygonEdges2d({12, 3, 0}, {-1, 0, 0}, kSquare.data(), kSquare.size(), kOffset, s));
    EXPECT_DOUBLE_EQ(s, 2.0);
    // Looking away (-x from (0, 2)) or passing above (y = 5): no edge.
    EXPECT_FALSE(
        rayPolygonEdges2d({0, 2, 0}, {-1, 0, 0}, kSquare.data(), kSquare.size(), kOffset, s));
    EXPECT_FALSE(
        rayPolygonEdges2d({0, 5, 0}, {1, 0, 0}, kSquare.data(), kSquare.size(), kOffset, s));
    // The L from (3, 3) (in the notch) looking -x: the inner edge x = 1 at s = 2.
    ASSERT_TRUE(rayPolygonEdges2d({3, 3, 0}, {-1, 0, 0}, kEll.data(), kEll.size(), dvec3(0.0), s));
    EXPECT_DOUBLE_EQ(s, 2.0);
}

}  // namespace
}  // namespace gridcull
