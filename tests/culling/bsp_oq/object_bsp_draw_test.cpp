// An object drawn part by part (its BSP leaves' triangle pieces, through
// IdDepthBuffer::drawTriangles, as the BSP culler draws it) covers the same
// pixels at the same depths as the whole mesh drawn at once: splitting keeps
// the surface, and the rasterizer's edge rule covers each pixel centre on a
// cut once. Also drawTriangles on the mesh's own triangles equals drawMesh
// exactly (same transform, same clipping, same rule).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "culling/bsp_oq/object_bsp.h"
#include "culling/raster/id_depth_buffer.h"
#include "culling/scene/camera.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/bsp_oq/bsp_random_scenes.h"

namespace gridcull {
namespace {

// Depths of one pixel drawn two ways differ by rounding only: the pieces'
// corners are points of the same planes, computed by another sum.
constexpr double kRelativeDepthTolerance = 1e-9;
// Pixel centres on a cut where the two sides' rounding disagree by one
// covered pixel, per thousand covered.
constexpr double kCutPixelShare = 0.002;

Camera cameraLookingAt(const glm::dvec3& eye, const glm::dvec3& target) {
    Scene scene = test::scene3d();
    test::setCamera(scene, eye, target, 60.0);
    return cameraAt(scene, 0.0);
}

struct Comparison {
    long long covered = 0, differ = 0;
    double worst_depth = 0.0;
};

Comparison compare(const IdDepthBuffer& a, const IdDepthBuffer& b) {
    Comparison c;
    for (int py = 0; py < a.height(); ++py) {
        const double* ra = a.depthRow(py);
        const double* rb = b.depthRow(py);
        for (int px = 0; px < a.width(); ++px) {
            const bool ca = std::isfinite(ra[px]), cb = std::isfinite(rb[px]);
            c.covered += ca;
            if (ca != cb) {
                ++c.differ;
            } else if (ca) {
                c.worst_depth = std::max(c.worst_depth, std::abs(ra[px] - rb[px]) / ra[px]);
            }
        }
    }
    return c;
}

std::vector<glm::dvec3> cornersOf(const TriangleMesh& mesh) {
    std::vector<glm::dvec3> corners;
    for (uint32_t i : mesh.indices) corners.push_back(mesh.vertices[i]);
    return corners;
}

TEST(ObjectBspDraw, LeavesDrawnOneByOneCoverWhatTheMeshCovers) {
    long long covered = 0, differ = 0;
    for (uint64_t seed = 1; seed <= 20; ++seed) {
        SeededRandom rng(seed);
        const auto mesh = rng.uniform() < 0.7 ? test::bumpySphereMesh(rng, 5.0, 24, 16, 0.3)
                                              : test::wavySheetMesh(rng, 10.0, 16, 3.0);
        ObjectBspParams params;
        params.max_leaf_triangles = 1 + int(rng.below(40));
        const ObjectBsp tree(*mesh, params);
        std::vector<glm::dvec3> pieces;
        for (const BspTrianglePiece& p : tree.pieces())
            pieces.insert(pieces.end(), {p.v[0], p.v[1], p.v[2]});
        const glm::dvec3 at{50, 50, 50};
        const Camera camera =
            cameraLookingAt(at + 20.0 * randomDirection(rng, 3) * rng.uniform(0.8, 2.0), at);
        IdDepthBuffer whole, parts;
        whole.resize(200, 150);
        parts.resize(200, 150);
        whole.begin(camera);
        parts.begin(camera);
        whole.drawMesh(0, *mesh, at);
        for (int k = 0; k < tree.nodeCount(); ++k) {
            const ObjectBspNode& n = tree.node(k);
            if (!n.isLeaf() || n.piece_count == 0) continue;
            parts.drawTriangles(0, pieces.data() + 3 * size_t(n.first_piece), size_t(n.piece_count),
                                at);
        }
        const Comparison c = compare(whole, parts);
        EXPECT_LE(c.worst_depth, kRelativeDepthTolerance) << "seed " << seed;
        EXPECT_GT(c.covered, 500) << "seed " << seed;
        covered += c.covered;
        differ += c.differ;
    }
    std::printf("[object bsp draw] %lld covered pixels, %lld covered one way only\n", covered,
                differ);
    EXPECT_LE(double(differ), kCutPixelShare * double(covered));
}

TEST(ObjectBspDraw, MeshTrianglesDrawnAsASetEqualTheMesh) {
    SeededRandom rng(3);
    const auto mesh = test::wavySheetMesh(rng, 10.0, 12, 2.0);  // open: no near-plane fill
    const std::vector<glm::dvec3> corners = cornersOf(*mesh);
    for (const glm::dvec3& eye : {glm::dvec3{50, 70, 30}, glm::dvec3{50, 50.5, 50.5}}) {
        const Camera camera = cameraLookingAt(eye, {50, 50, 50});
        IdDepthBuffer a, b;
        a.resize(160, 120);
        b.resize(160, 120);
        a.begin(camera);
        b.begin(camera);
        a.drawMesh(4, *mesh, {50, 50, 50});
        b.drawTriangles(4, corners.data(), corners.size() / 3, {50, 50, 50});
        const Comparison c = compare(a, b);
        EXPECT_EQ(c.differ, 0);
        EXPECT_EQ(c.worst_depth, 0.0);
        EXPECT_GT(c.covered, 100);
        EXPECT_EQ(a.lastDrawCols().lo, b.lastDrawCols().lo);
        EXPECT_EQ(a.lastDrawRows().hi, b.lastDrawRows().hi);
    }
}

TEST(ObjectBspDraw, EmptyOrFarSetsWriteNothing) {
    const Camera camera = cameraLookingAt({50, 50, 0}, {50, 50, 100});
    IdDepthBuffer buffer;
    buffer.resize(64, 48);
    buffer.begin(camera);
    const std::vector<glm::dvec3> behind{{0, 0, -5}, {1, 0, -5}, {0, 1, -5}};
    EXPECT_FALSE(buffer.drawTriangles(1, behind.data(), 0, {50, 50, 0}));
    EXPECT_FALSE(buffer.drawTriangles(1, behind.data(), 1, {50, 50, 0}));
    IdDepthBuffer empty;
    empty.resize(64, 48);
    empty.begin(camera);
    EXPECT_EQ(compare(buffer, empty).covered, 0);
}

}  // namespace
}  // namespace gridcull
