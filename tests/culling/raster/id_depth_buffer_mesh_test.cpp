// The ID buffer's meshes (culling/raster/id_depth_buffer_mesh.cpp) pixel by pixel
// against an independent per-pixel ray cast with its own ray-triangle test
// (raster_brute_force.h): closed and open meshes, near-plane clipping, the
// solid fill of a closed mesh the near plane cuts, the camera inside a mesh,
// and the fill rule on pixel centres lying exactly on a shared edge.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "culling/raster/id_depth_buffer.h"
#include "tests/culling/raster/raster_brute_force.h"

namespace gridcull {
namespace {

using test::atView;
using test::TestShape;

constexpr int kWidth = test::kRasterWidth;
constexpr int kHeight = test::kRasterHeight;
using test::obliqueCamera;

test::PixelTally expectMatches(const Camera& cam, const TestShape& shape, const char* what) {
    const test::PixelTally tally = test::expectShapeMatches(cam, kWidth, kHeight, shape, what);
    EXPECT_GT(tally.covered, 0) << what;
    EXPECT_LE(tally.boundary, 2) << what;  // a designed case is not about grazing rays
    return tally;
}

long long pixelsAtNear(const Camera& cam, const TestShape& shape) {
    const std::vector<double> drawn = test::drawnAlone(cam, kWidth, kHeight, shape);
    return std::count(drawn.begin(), drawn.end(), cam.near);
}

TEST(IdDepthBufferMesh, ClosedTetrahedronAndCubeMatchTheRayCast) {
    const Camera cam = obliqueCamera();
    expectMatches(
        cam,
        test::meshShape(test::tetrahedronOn({2, 2, 2}, {2, -2, -2}, {-2, 2, -2}, {-2, -2, 2}),
                        atView(cam, 0.5, 0.0, 10.0)),
        "tetrahedron");
    // Off to the upper left, so three of its faces show.
    expectMatches(cam,
                  test::meshShape(test::boxSurfaceMesh({1.5, 1.0, 2.0}), atView(cam, -5, 3, 11)),
                  "cube");
}

TEST(IdDepthBufferMesh, OpenTriangleMatchesTheRayCastFromBothSides) {
    const Camera cam = obliqueCamera();
    const glm::dvec3 a{-3, -2, 0.5}, b{4, -1, -1}, c{0.5, 3, 1};
    const glm::dvec3 at = atView(cam, 0.3, -0.4, 9.0);
    expectMatches(cam, test::meshShape(test::triangleOn(a, b, c), at), "triangle abc");
    expectMatches(cam, test::meshShape(test::triangleOn(a, c, b), at), "triangle acb");
    // Two-sided: the winding changes nothing.
    EXPECT_EQ(
        test::drawnAlone(cam, kWidth, kHeight, test::meshShape(test::triangleOn(a, b, c), at)),
        test::drawnAlone(cam, kWidth, kHeight, test::meshShape(test::triangleOn(a, c, b), at)));
}

TEST(IdDepthBufferMesh, MeshesCrossingTheNearPlaneAreClipped) {
    const Camera cam = obliqueCamera();  // near 0.5
    // A triangle with one vertex behind the eye (clipped to a quad) and one with
    // two (clipped to a triangle).
    expectMatches(cam,
                  test::meshShape(test::triangleOn(atView(cam, -2, -1, 4), atView(cam, 2, -1.5, 5),
                                                   atView(cam, 0.2, 0.5, -2)),
                                  glm::dvec3(0.0)),
                  "one vertex behind");
    expectMatches(
        cam,
        test::meshShape(test::triangleOn(atView(cam, -1, -1, -1), atView(cam, 1, -0.5, -2),
                                         atView(cam, 0.3, 0.4, 6)),
                        glm::dvec3(0.0)),
        "two vertices behind");
    // The box of IdDepthBufferBox.BoxCrossingTheNearPlaneShowsItsCutAtNear as a
    // surface: closed, the cut shows at depth near; open, the inside shows.
    const glm::dvec3 c = atView(cam, 0.5, 0.3, 0.6);
    const TestShape closed = test::meshShape(test::boxSurfaceMesh(glm::dvec3(0.4), true), c);
    const TestShape open = test::meshShape(test::boxSurfaceMesh(glm::dvec3(0.4), false), c);
    expectMatches(cam, closed, "closed box surface");
    expectMatches(cam, open, "open box surface");
    EXPECT_GT(pixelsAtNear(cam, closed), 20);
    EXPECT_LT(pixelsAtNear(cam, open), 3);  // only where the clipped faces meet near
}

TEST(IdDepthBufferMesh, CameraInsideAClosedMeshSeesItAtNearEverywhere) {
    const Camera cam = obliqueCamera();
    const long long pixels = kWidth * kHeight;
    EXPECT_EQ(pixelsAtNear(cam, test::meshShape(test::boxSurfaceMesh({3, 2, 4}),
                                                cam.position + glm::dvec3(0.3, -0.2, 0.5))),
              pixels);
    EXPECT_EQ(pixelsAtNear(cam, test::meshShape(test::tetrahedronOn({6, 6, 6}, {6, -6, -6},
                                                                    {-6, 6, -6}, {-6, -6, 6}),
                                                cam.position + glm::dvec3(0.2, 0.1, -0.3))),
              pixels);
    // The same box surface open: no solid, the faces show at their own depths.
    const TestShape open = test::meshShape(test::boxSurfaceMesh({3, 2, 4}, false),
                                           cam.position + glm::dvec3(0.3, -0.2, 0.5));
    const test::PixelTally tally = expectMatches(cam, open, "open, around the eye");
    EXPECT_EQ(tally.covered + tally.boundary, int(pixels));  // every ray meets a face
    EXPECT_EQ(pixelsAtNear(cam, open), 0);
}

// ---- The fill rule on shared edges ----
//
// The camera sits at the origin looking down +z with up +y and aspect 1, so its
// basis is exact: right = (-1, 0, 0), up = (0, 1, 0), forward = (0, 0, 1). A world
// point (X, Y, 1) has view (-X, Y, 1) and lies at the continuous pixel position
// (centres at +0.5)
//   sx = width / 2 * (1 - X / tan),  sy = height / 2 * (1 - Y / tan),
// tan = tan(fov_y / 2). With X / tan and Y / tan in {0, +-1/2} every step of that
// is exact in floating point, so vertices land exactly where intended and a
// pixel centre on the edge between two of them has edge function exactly 0.

Camera axisCamera() {
    volatile double fov = 70.0;  // not folded at compile time: tan must round as in the buffer
    Camera camera;
    camera.position = {0, 0, 0};
    camera.target = {0, 0, 1};
    camera.up = {0, 1, 0};
    camera.fov_deg = fov;
    camera.aspect = 1.0;
    camera.near = 0.1;
    camera.far = 100.0;
    return camera;
}

struct ScreenPoint {
    double x, y;
};

// The world point at depth 1 that projects to continuous pixel position p.
glm::dvec3 worldAt(const Camera& cam, int width, int height, ScreenPoint p) {
    const double tan = std::tan(glm::radians(cam.fov_deg) * 0.5);  // as the buffer computes it
    return {(1.0 - 2.0 * p.x / width) * tan, (1.0 - 2.0 * p.y / height) * tan, 1.0};
}

double cross2(ScreenPoint o, ScreenPoint a, ScreenPoint b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The convex quad q[0..3] split along q[0]-q[2] into (q0, q1, q2) and (q0, q2, q3),
// each drawn alone and the two drawn as one mesh. Every pixel centre inside the
// quad (by more than kOuterMargin pixels from its outer edges) is covered by
// exactly one triangle and by the quad, none outside is, none is covered by both;
// the `diagonal_pixels` centres lying exactly on the shared edge all go to the
// same triangle; `corner_pixels` centres lie on the outer edges (either way).
// Which triangle owns the shared edge is printed, not asserted: the buffer's
// header calls its rule top-left, while ownsEdge (dy > 0, or dy == 0 and dx < 0,
// rows counted from the top, after normalizing the winding) gives a vertical
// edge to the triangle on its left and a horizontal one to the triangle above,
// i.e. owns right and bottom edges as the image is shown. Either convention
// gives each centre to exactly one triangle, which is what the ID buffer and the
// closed-mesh parity rely on.
void expectSharedEdgeCoveredOnce(int width, int height, const ScreenPoint (&q)[4],
                                 int diagonal_pixels, int corner_pixels, const char* what) {
    // Far more than rounding of the generic vertices (~1e-14 px), far less than
    // their distance to any pixel centre.
    constexpr double kOuterMargin = 1e-6;
    const Camera cam = axisCamera();
    glm::dvec3 w[4];
    for (int i = 0; i < 4; ++i) w[i] = worldAt(cam, width, height, q[i]);
    const glm::dvec3 origin(0.0);
    const std::vector<double> first = test::drawnAlone(
        cam, width, height, test::meshShape(test::triangleOn(w[0], w[1], w[2]), origin));
    const std::vector<double> second = test::drawnAlone(
        cam, width, height, test::meshShape(test::triangleOn(w[0], w[2], w[3]), origin));
    const std::vector<double> whole = test::drawnAlone(
        cam, width, height,
        test::meshShape(test::finishMesh({w[0], w[1], w[2], w[3]}, {0, 1, 2, 0, 2, 3}, false),
                        origin));
    // The reversed winding covers the same pixels (at depths equal up to rounding).
    const std::vector<double> reversed = test::drawnAlone(
        cam, width, height, test::meshShape(test::triangleOn(w[2], w[1], w[0]), origin));
    for (size_t k = 0; k < first.size(); ++k) {
        EXPECT_TRUE(first[k] == reversed[k] || test::depthsAgree(first[k], reversed[k]))
            << what << ": pixel " << k << " " << first[k] << " reversed " << reversed[k];
    }

    const double orientation = cross2(q[0], q[1], q[2]) > 0.0 ? 1.0 : -1.0;
    const double inf = std::numeric_limits<double>::infinity();
    int diagonal = 0, owned_by_first = 0, corners = 0, inside_count = 0;
    for (int py = 0; py < height; ++py) {
        for (int px = 0; px < width; ++px) {
            const ScreenPoint p{px + 0.5, py + 0.5};
            double margin = inf;  // signed distance inside the outer edges
            for (int i = 0; i < 4; ++i) {
                const ScreenPoint a = q[i], b = q[(i + 1) % 4];
                margin = std::min(margin,
                                  orientation * cross2(a, b, p) / std::hypot(b.x - a.x, b.y - a.y));
            }
            const size_t k = size_t(py) * size_t(width) + size_t(px);
            const int covered = int(first[k] < inf) + int(second[k] < inf);
            EXPECT_LE(covered, 1) << what << ": pixel (" << px << ", " << py << ") drawn twice";
            if (std::abs(margin) <= kOuterMargin) {
                ++corners;
                continue;
            }
            const bool inside = margin > 0.0;
            inside_count += inside;
            EXPECT_EQ(covered, int(inside)) << what << ": pixel (" << px << ", " << py << ")";
            EXPECT_EQ(whole[k] < inf, inside) << what << ": pixel (" << px << ", " << py << ")";
            if (inside && cross2(q[0], q[2], p) == 0.0) {
                ++diagonal;
                owned_by_first += first[k] < inf;
            }
        }
    }
    EXPECT_EQ(diagonal, diagonal_pixels) << what;
    EXPECT_EQ(corners, corner_pixels) << what;
    EXPECT_GT(inside_count, 100) << what;
    // The owner depends only on the edge's direction, so it is one triangle throughout.
    EXPECT_TRUE(owned_by_first == 0 || owned_by_first == diagonal)
        << what << ": " << owned_by_first << " of " << diagonal;
    std::printf(
        "[raster fill rule] %s: %d centres on the shared edge, %d owned by the first "
        "triangle, %d by the second\n",
        what, diagonal, owned_by_first, diagonal - owned_by_first);
}

TEST(IdDepthBufferMesh, SharedEdgeWithPixelCentresOnADiagonalIsCoveredOnce) {
    // 26 x 26: the diagonal runs from (6.5, 6.5) to (19.5, 19.5) (X / tan, Y / tan
    // = +-1/2), through the centres (k + 0.5, k + 0.5), k = 7..18 inside the quad;
    // its two ends are pixel centres on the outer edges too.
    expectSharedEdgeCoveredOnce(26, 26, {{6.5, 6.5}, {21.3, 4.2}, {19.5, 19.5}, {3.7, 22.4}}, 12, 2,
                                "diagonal");
}

TEST(IdDepthBufferMesh, SharedEdgeWithPixelCentresOnAVerticalLineIsCoveredOnce) {
    // 27 x 27: X = 0 puts the edge on x = 13.5, the centres of column 13; its
    // ends at y = 3.2 and 23.7 leave rows 3..23 inside.
    expectSharedEdgeCoveredOnce(27, 27, {{13.5, 3.2}, {24.2, 14.8}, {13.5, 23.7}, {2.9, 12.6}}, 21,
                                0, "vertical");
}

TEST(IdDepthBufferMesh, SharedEdgeWithPixelCentresOnAHorizontalLineIsCoveredOnce) {
    // 27 x 27: Y = 0 puts the edge on y = 13.5 (row 13), columns 3..23 inside.
    expectSharedEdgeCoveredOnce(27, 27, {{2.9, 13.5}, {12.6, 3.2}, {24.2, 13.5}, {14.8, 23.7}}, 21,
                                0, "horizontal");
}

}  // namespace
}  // namespace gridcull
