#include "grid/polygon_triangulate.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace gridcull {
namespace {

using Points = std::vector<glm::dvec3>;

constexpr double kAreaTolerance = 1e-9;  // relative, for sums of triangle areas

double triangleDoubleArea(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

double polygonDoubleArea(const Points& poly) {
    double sum = 0.0;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        sum += poly[j].x * poly[i].y - poly[i].x * poly[j].y;
    return sum;
}

// Even-odd rule; used on triangle centroids, which never lie on the outline.
bool insidePolygon(const Points& poly, const glm::dvec3& p) {
    bool inside = false;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const glm::dvec3& a = poly[i];
        const glm::dvec3& b = poly[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

// Checks the triangles tile the polygon: every one counter-clockwise with its
// centroid inside, and their areas summing to the polygon's.
void expectTiles(const Points& poly, const std::vector<uint32_t>& tris) {
    ASSERT_EQ(tris.size() % 3, 0u);
    double sum = 0.0;
    for (size_t t = 0; t < tris.size(); t += 3) {
        ASSERT_LT(tris[t], poly.size());
        ASSERT_LT(tris[t + 1], poly.size());
        ASSERT_LT(tris[t + 2], poly.size());
        const glm::dvec3& a = poly[tris[t]];
        const glm::dvec3& b = poly[tris[t + 1]];
        const glm::dvec3& c = poly[tris[t + 2]];
        const double area2 = triangleDoubleArea(a, b, c);
        EXPECT_GT(area2, 0.0) << "triangle " << t / 3 << " is not counter-clockwise";
        EXPECT_TRUE(insidePolygon(poly, (a + b + c) / 3.0)) << "triangle " << t / 3;
        sum += area2;
    }
    const double expected = std::abs(polygonDoubleArea(poly));
    EXPECT_NEAR(sum, expected, kAreaTolerance * expected);
}

TEST(PolygonTriangulate, SquareGivesTwoTriangles) {
    const Points square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    std::vector<uint32_t> tris;
    ASSERT_TRUE(triangulatePolygon(square, tris));
    EXPECT_EQ(tris.size(), 6u);
    expectTiles(square, tris);
}

TEST(PolygonTriangulate, ConcaveLShape) {
    const Points l{{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};
    std::vector<uint32_t> tris;
    ASSERT_TRUE(triangulatePolygon(l, tris));
    EXPECT_EQ(tris.size(), 3u * 4u);
    expectTiles(l, tris);
}

TEST(PolygonTriangulate, CombWithDeepNotches) {
    // Teeth pointing up; a fan from any vertex would cover the notches.
    Points comb{{0, 0, 0}, {9, 0, 0}};
    for (int k = 4; k >= 0; --k) {
        const double x = 2.0 * k;
        comb.push_back({x + 1, 5, 0});
        comb.push_back({x, 5, 0});
        if (k > 0) comb.push_back({x - 0.5, 1, 0});
    }
    std::vector<uint32_t> tris;
    ASSERT_TRUE(triangulatePolygon(comb, tris));
    EXPECT_EQ(tris.size(), 3 * (comb.size() - 2));
    expectTiles(comb, tris);
}

TEST(PolygonTriangulate, ClockwiseInputIsCorrected) {
    const Points cw{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
    std::vector<uint32_t> tris;
    ASSERT_TRUE(triangulatePolygon(cw, tris));
    expectTiles(cw, tris);
}

TEST(PolygonTriangulate, CollinearAndRepeatedPointsAddNoTriangles) {
    const Points poly{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 1, 0}};
    std::vector<uint32_t> tris;
    ASSERT_TRUE(triangulatePolygon(poly, tris));
    EXPECT_LE(tris.size(), 3u * 4u);
    expectTiles(poly, tris);
}

TEST(PolygonTriangulate, DegenerateInputIsRejected) {
    std::vector<uint32_t> tris;
    EXPECT_FALSE(triangulatePolygon({}, tris));
    EXPECT_FALSE(triangulatePolygon({{0, 0, 0}, {1, 0, 0}}, tris));
    EXPECT_FALSE(triangulatePolygon({{0, 0, 0}, {1, 1, 0}, {2, 2, 0}}, tris));  // no area
    EXPECT_FALSE(triangulatePolygon({{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}}, tris));  // bow tie
    EXPECT_FALSE(triangulatePolygon({{0, 0, 0}, {NAN, 0, 0}, {1, 1, 0}}, tris));
}

TEST(PolygonTriangulate, RandomStarShapedPolygons) {
    // One point per equal angular slot around a centre, at a random radius: a
    // simple polygon (every gap between neighbours is under half a turn), usually
    // very concave.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<uint32_t> tris;
    for (int trial = 0; trial < 200; ++trial) {
        const int n = 4 + int(unit(rng) * 40);
        Points poly;
        for (int k = 0; k < n; ++k) {
            const double a = (k + 0.1 + 0.8 * unit(rng)) * 6.283185307179586 / n;
            const double r = 0.2 + unit(rng) * 10.0;
            poly.push_back({r * std::cos(a) + 50.0, r * std::sin(a) - 20.0, 0.0});
        }
        SCOPED_TRACE("trial " + std::to_string(trial));
        ASSERT_TRUE(triangulatePolygon(poly, tris));
        EXPECT_EQ(tris.size(), 3u * (poly.size() - 2));
        expectTiles(poly, tris);
    }
}

}  // namespace
}  // namespace gridcull
