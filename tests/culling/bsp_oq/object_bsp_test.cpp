// The local BSP tree of an object (culling/bsp_oq/object_bsp.h; Kovalčík &
// Sochor, "Fast rendering of complex dynamic scenes", section 3.1, traversal of
// 3.3), against brute-force checks written here:
// - splitting keeps the triangle set: every mesh triangle has pieces, its
//   pieces' areas add up to its area, each piece lies in its source triangle,
//   and the whole tree's piece area is the mesh's;
// - every piece lies in its leaf's bounds and cell (exactly: the intersection
//   points are snapped to the plane and clamped to their edge), bounds lie in
//   cells, children's cells are their parent's halves, ranges nest;
// - leaves stop by the threshold unless the depth bound, the progress rule
//   (checked by re-running it here) or the piece budget stopped them;
// - front-to-back order from random eyes: near child before far child, and every
//   two leaves in an order that some axis-aligned plane between their cells,
//   with the eye on the first one's side, justifies (cells only, not the tree);
// - the object's translation is applied at query time.
// On the bunny (scenes/meshes/bunny.obj), seeded random triangle soups and
// degenerate meshes. GRIDCULL_SEED=N replays one seed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "culling/bsp_oq/object_bsp.h"
#include "culling/io/mesh_loader.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/test_seeds.h"

namespace gridcull {
namespace {

// Areas are compared up to this many times the square of the longest edge of
// the triangle (or of the mesh's bounds for totals). A clip computes each
// intersection point with a handful of roundings (relative 2^-53 each), and a
// triangle goes through at most kMaxObjectBspDepth clips, each of whose pieces'
// areas is a sum of a few rounded cross products: the error stays far below
// 1e-12 of edge^2; 1e-9 leaves room and still catches a lost piece of any
// visible size.
constexpr double kAreaTolerance = 1e-9;
// A piece's vertex may lie off its source triangle's plane and edges by this
// much times the triangle's longest edge (roundings of the interpolation).
constexpr double kInsideTolerance = 1e-9;

TriangleMesh makeMesh(const std::vector<glm::dvec3>& corners) {  // three per triangle
    TriangleMesh mesh;
    mesh.vertices = corners;
    for (size_t i = 0; i < corners.size(); ++i) mesh.indices.push_back(uint32_t(i));
    if (!corners.empty()) {
        mesh.bounds = {corners[0], corners[0]};
        for (const glm::dvec3& c : corners) mesh.bounds.merge({c, c});
    }
    return mesh;
}

glm::dvec3 corner(const TriangleMesh& mesh, int t, int k) {
    return mesh.vertices[mesh.indices[3 * size_t(t) + size_t(k)]];
}

double longestEdge(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
}

bool inClosedBox(const Aabb& box, const glm::dvec3& p) {
    return box.contains(p);
}

bool boxInBox(const Aabb& inner, const Aabb& outer) {
    return inClosedBox(outer, inner.min) && inClosedBox(outer, inner.max);
}

// Is p within the triangle (a, b, c), up to tol? (Nondegenerate triangles only.)
bool inTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                double tol) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double n2 = glm::dot(n, n);
    if (std::abs(glm::dot(p - a, n)) / std::sqrt(n2) > tol) return false;
    // Barycentric coordinates, each scaled by the longest edge to compare with tol.
    const double l = longestEdge(a, b, c);
    const double u = glm::dot(glm::cross(c - b, p - b), n) / n2;
    const double v = glm::dot(glm::cross(a - c, p - c), n) / n2;
    const double w = 1.0 - u - v;
    return u * l >= -tol && v * l >= -tol && w * l >= -tol;
}

// Everything the header promises of a built tree, brute force.
void expectTreeValid(const TriangleMesh& mesh, const ObjectBsp& bsp) {
    const int triangles = int(mesh.indices.size() / 3);
    ASSERT_EQ(bsp.sourceTriangleCount(), triangles);
    ASSERT_GE(bsp.nodeCount(), 1);
    const ObjectBspParams& params = bsp.params();

    // Structure: pre-order, ranges nest, children's cells halve the parent's.
    int leaves = 0, leaf_pieces = 0, next_leaf_piece = 0;
    for (int i = 0; i < bsp.nodeCount(); ++i) {
        const ObjectBspNode& n = bsp.node(i);
        ASSERT_TRUE(boxInBox(n.bounds, n.cell)) << "node " << i;
        ASSERT_LE(n.depth, params.max_depth);
        if (n.isLeaf()) {
            ++leaves;
            EXPECT_EQ(n.first_piece, next_leaf_piece) << "leaves in piece order";
            next_leaf_piece += n.piece_count;
            leaf_pieces += n.piece_count;
            EXPECT_NE(n.reason, BspLeafReason::Inner);
            continue;
        }
        ASSERT_EQ(n.low, i + 1);
        ASSERT_GT(n.high, n.low);
        ASSERT_LT(n.high, bsp.nodeCount());
        ASSERT_TRUE(n.axis >= 0 && n.axis < 3);
        const ObjectBspNode& lo = bsp.node(n.low);
        const ObjectBspNode& hi = bsp.node(n.high);
        EXPECT_EQ(lo.depth, n.depth + 1);
        EXPECT_EQ(hi.depth, n.depth + 1);
        EXPECT_EQ(lo.first_piece, n.first_piece);
        EXPECT_EQ(hi.first_piece, lo.first_piece + lo.piece_count);
        EXPECT_EQ(n.piece_count, lo.piece_count + hi.piece_count);
        Aabb low_cell = n.cell, high_cell = n.cell;
        low_cell.max[n.axis] = n.split;
        high_cell.min[n.axis] = n.split;
        EXPECT_EQ(lo.cell.min, low_cell.min);
        EXPECT_EQ(lo.cell.max, low_cell.max);
        EXPECT_EQ(hi.cell.min, high_cell.min);
        EXPECT_EQ(hi.cell.max, high_cell.max);
        EXPECT_EQ(n.reason, BspLeafReason::Inner);
    }
    EXPECT_EQ(leaves, bsp.leafCount());
    EXPECT_EQ(leaf_pieces, bsp.pieceCount());
    EXPECT_EQ(bsp.node(ObjectBsp::kRoot).piece_count, bsp.pieceCount());

    // Every piece inside its leaf's bounds and cell, and inside its source triangle.
    std::vector<double> area_of_source(size_t(triangles), 0.0);
    std::vector<int> pieces_of_source(size_t(triangles), 0);
    for (int i = 0; i < bsp.nodeCount(); ++i) {
        const ObjectBspNode& n = bsp.node(i);
        if (!n.isLeaf()) continue;
        for (int k = n.first_piece; k < n.first_piece + n.piece_count; ++k) {
            const BspTrianglePiece& p = bsp.piece(k);
            ASSERT_TRUE(p.source >= 0 && p.source < triangles);
            for (const glm::dvec3& v : p.v) {
                ASSERT_TRUE(inClosedBox(n.bounds, v)) << "piece " << k << " of leaf " << i;
                ASSERT_TRUE(inClosedBox(n.cell, v)) << "piece " << k << " of leaf " << i;
            }
            const glm::dvec3 a = corner(mesh, p.source, 0), b = corner(mesh, p.source, 1),
                             c = corner(mesh, p.source, 2);
            const double l = longestEdge(a, b, c);
            if (triangleArea(a, b, c) > 1e-6 * l * l) {
                for (const glm::dvec3& v : p.v) {
                    ASSERT_TRUE(inTriangle(v, a, b, c, kInsideTolerance * l))
                        << "piece " << k << " leaves triangle " << p.source;
                }
            }
            area_of_source[size_t(p.source)] += triangleArea(p.v[0], p.v[1], p.v[2]);
            ++pieces_of_source[size_t(p.source)];
        }
    }
    // No triangle lost, none grown: each one's pieces add up to its area.
    double mesh_area = 0.0, piece_area = 0.0;
    for (int t = 0; t < triangles; ++t) {
        const glm::dvec3 a = corner(mesh, t, 0), b = corner(mesh, t, 1), c = corner(mesh, t, 2);
        const double area = triangleArea(a, b, c);
        const double l = longestEdge(a, b, c);
        EXPECT_GE(pieces_of_source[size_t(t)], 1) << "triangle " << t << " lost";
        EXPECT_NEAR(area_of_source[size_t(t)], area, kAreaTolerance * l * l) << "triangle " << t;
        mesh_area += area;
        piece_area += area_of_source[size_t(t)];
    }
    const glm::dvec3 e = bsp.node(ObjectBsp::kRoot).cell.extent();
    EXPECT_NEAR(piece_area, mesh_area, kAreaTolerance * glm::dot(e, e) * std::max(triangles, 1));
}

// The progress rule of the build, re-run: does some axis's median plane of the
// pieces' centroids leave each side with fewer pieces than the node has?
bool someMedianPlaneMakesProgress(const ObjectBsp& bsp, const ObjectBspNode& n) {
    const int count = n.piece_count;
    for (int a = 0; a < 3; ++a) {
        std::vector<double> keys;
        for (int k = n.first_piece; k < n.first_piece + count; ++k) {
            const BspTrianglePiece& p = bsp.piece(k);
            keys.push_back((p.v[0][a] + p.v[1][a] + p.v[2][a]) / 3.0);
        }
        std::sort(keys.begin(), keys.end());
        const double s = keys[size_t(count / 2)];
        int low = 0, high = 0;
        for (int k = n.first_piece; k < n.first_piece + count; ++k) {
            const BspTrianglePiece& p = bsp.piece(k);
            const double lo = std::min({p.v[0][a], p.v[1][a], p.v[2][a]});
            const double hi = std::max({p.v[0][a], p.v[1][a], p.v[2][a]});
            low += hi <= s || lo < s;  // wholly low (in the plane too), or straddling
            high += hi > s;            // wholly high, or straddling
        }
        if (low < count && high < count) return true;
    }
    return false;
}

// Leaves hold at most the threshold unless a bound stopped them; inner nodes
// were worth splitting.
void expectLeavesRespectThreshold(const ObjectBsp& bsp) {
    const ObjectBspParams& params = bsp.params();
    for (int i = 0; i < bsp.nodeCount(); ++i) {
        const ObjectBspNode& n = bsp.node(i);
        if (!n.isLeaf()) {
            EXPECT_GT(n.piece_count, params.max_leaf_triangles) << "inner node " << i;
            EXPECT_LT(n.depth, params.max_depth) << "inner node " << i;
            continue;
        }
        switch (n.reason) {
            case BspLeafReason::Threshold:
                EXPECT_LE(n.piece_count, params.max_leaf_triangles) << "leaf " << i;
                break;
            case BspLeafReason::Depth:
                EXPECT_GT(n.piece_count, params.max_leaf_triangles) << "leaf " << i;
                EXPECT_EQ(n.depth, params.max_depth) << "leaf " << i;
                break;
            case BspLeafReason::Unsplittable:
                EXPECT_GT(n.piece_count, params.max_leaf_triangles) << "leaf " << i;
                EXPECT_LT(n.depth, params.max_depth) << "leaf " << i;
                EXPECT_FALSE(someMedianPlaneMakesProgress(bsp, n)) << "leaf " << i;
                break;
            case BspLeafReason::Budget:
                EXPECT_GT(n.piece_count, params.max_leaf_triangles) << "leaf " << i;
                EXPECT_GT(bsp.pieceCount() - bsp.sourceTriangleCount(),
                          int(params.max_extra_pieces_ratio * bsp.sourceTriangleCount()))
                    << "leaf " << i;
                break;
            case BspLeafReason::Inner:
                ADD_FAILURE() << "leaf " << i << " says inner";
        }
    }
}

int countLeaves(const ObjectBsp& bsp, BspLeafReason reason) {
    int count = 0;
    for (const ObjectBspNode& n : bsp.nodes()) count += n.isLeaf() && n.reason == reason;
    return count;
}

// Node visits from `eye` (translation 0), all nodes taken.
std::vector<int> visitOrder(const ObjectBsp& bsp, const glm::dvec3& eye) {
    std::vector<int> order;
    bsp.traverseFrontToBack(eye, glm::dvec3(0.0), [&](const ObjectBspNodeView& v) {
        order.push_back(v.id);
        return true;
    });
    return order;
}

// May leaf cell `a` go before leaf cell `b` from `eye`? Yes when some
// axis-aligned plane between them has the eye on a's side (closed): then no
// segment from the eye into a crosses b's interior.
bool mayPrecede(const Aabb& a, const Aabb& b, const glm::dvec3& eye) {
    for (int k = 0; k < 3; ++k) {
        if (a.max[k] <= b.min[k] && eye[k] <= b.min[k]) return true;
        if (b.max[k] <= a.min[k] && eye[k] >= b.max[k]) return true;
    }
    return false;
}

void expectFrontToBack(const ObjectBsp& bsp, const glm::dvec3& eye) {
    const std::vector<int> order = visitOrder(bsp, eye);
    ASSERT_EQ(int(order.size()), bsp.nodeCount());
    std::vector<int> position(size_t(bsp.nodeCount()), -1);
    for (int k = 0; k < int(order.size()); ++k) {
        ASSERT_EQ(position[size_t(order[size_t(k)])], -1) << "node visited twice";
        position[size_t(order[size_t(k)])] = k;
    }
    // Near child (the eye's side of the plane) before far child, parent first;
    // subtrees are contiguous in pre-order, so near subtree before far subtree.
    for (int i = 0; i < bsp.nodeCount(); ++i) {
        const ObjectBspNode& n = bsp.node(i);
        if (n.isLeaf()) continue;
        const int near = eye[n.axis] < n.split ? n.low : n.high;
        const int far = near == n.low ? n.high : n.low;
        EXPECT_LT(position[size_t(i)], position[size_t(near)]);
        EXPECT_EQ(position[size_t(near)], position[size_t(i)] + 1) << "node " << i;
        EXPECT_LT(position[size_t(near)], position[size_t(far)]) << "node " << i;
    }
    // Every two leaves, against their cells alone.
    std::vector<int> leaves;
    for (int id : order)
        if (bsp.node(id).isLeaf()) leaves.push_back(id);
    for (size_t x = 0; x < leaves.size(); ++x)
        for (size_t y = x + 1; y < leaves.size(); ++y)
            if (!mayPrecede(bsp.node(leaves[x]).cell, bsp.node(leaves[y]).cell, eye)) {
                ADD_FAILURE() << "leaf " << leaves[x] << " before leaf " << leaves[y];
                return;
            }
}

glm::dvec3 randomPoint(SeededRandom& rng, const Aabb& box, double margin) {
    return {rng.uniform(box.min.x - margin, box.max.x + margin),
            rng.uniform(box.min.y - margin, box.max.y + margin),
            rng.uniform(box.min.z - margin, box.max.z + margin)};
}

// A soup of random triangles: small, medium and long ones, some degenerate.
TriangleMesh randomSoup(SeededRandom& rng) {
    const int n = 1 + int(rng.below(400));
    const Aabb space{{-5, -5, -5}, {5, 5, 5}};
    std::vector<glm::dvec3> corners;
    for (int t = 0; t < n; ++t) {
        const glm::dvec3 a = randomPoint(rng, space, 0.0);
        const double size = rng.below(4) == 0 ? 8.0 : (rng.below(2) ? 1.0 : 0.1);
        glm::dvec3 b = a + size * (randomPoint(rng, space, 0.0) / 5.0);
        glm::dvec3 c = a + size * (randomPoint(rng, space, 0.0) / 5.0);
        if (rng.below(20) == 0) c = b;              // two corners equal
        if (rng.below(20) == 0) c = 0.5 * (a + b);  // collinear
        corners.insert(corners.end(), {a, b, c});
    }
    return makeMesh(corners);
}

ObjectBspParams randomParams(SeededRandom& rng) {
    ObjectBspParams params;
    params.max_leaf_triangles = 1 + int(rng.below(20));
    params.max_depth = int(rng.below(22));
    return params;
}

TEST(ObjectBspClip, PiecesKeepTheAreaAndLieOnTheirSides) {
    for (uint64_t seed : test::seedsToRun(1, 200)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const Aabb space{{-1, -1, -1}, {1, 1, 1}};
            const glm::dvec3 a = randomPoint(rng, space, 0), b = randomPoint(rng, space, 0),
                             c = randomPoint(rng, space, 0);
            const int axis = int(rng.below(3));
            // Planes through a corner, through the triangle, and missing it.
            const double choices[3] = {a[axis], rng.uniform(-1, 1), 2.0};
            const double split = choices[rng.below(3)];
            std::vector<BspTrianglePiece> low, high;
            clipTriangle(a, b, c, 7, axis, split, low, high);
            double area = 0.0;
            for (const BspTrianglePiece& p : low) {
                EXPECT_EQ(p.source, 7);
                for (const glm::dvec3& v : p.v) EXPECT_LE(v[axis], split);
                area += triangleArea(p.v[0], p.v[1], p.v[2]);
            }
            for (const BspTrianglePiece& p : high) {
                for (const glm::dvec3& v : p.v) EXPECT_GE(v[axis], split);
                area += triangleArea(p.v[0], p.v[1], p.v[2]);
            }
            EXPECT_LE(low.size() + high.size(), 3u);
            EXPECT_NEAR(area, triangleArea(a, b, c), kAreaTolerance);
        });
    }
}

TEST(ObjectBspClip, TriangleInThePlaneGoesLowWhole) {
    std::vector<BspTrianglePiece> low, high;
    clipTriangle({1, 0, 0}, {1, 1, 0}, {1, 0, 1}, 0, 0, 1.0, low, high);
    EXPECT_EQ(low.size(), 1u);
    EXPECT_TRUE(high.empty());
}

TEST(ObjectBspBuild, BunnyKeepsItsTriangles) {
    const MeshLoadResult loaded =
        loadObjMesh(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/meshes/bunny.obj", "bunny.obj", 1.0,
                    glm::dvec3(0.0));
    ASSERT_TRUE(loaded.mesh) << loaded.error;
    const TriangleMesh& mesh = *loaded.mesh;
    for (int threshold : {1, 8, 64, 256, 100000}) {  // 256: --bsp-leaf-triangles' default
        SCOPED_TRACE("threshold " + std::to_string(threshold));
        ObjectBspParams params;
        params.max_leaf_triangles = threshold;
        const ObjectBsp bsp(mesh, params);
        expectTreeValid(mesh, bsp);
        expectLeavesRespectThreshold(bsp);
        EXPECT_GE(bsp.pieceCount(), bsp.sourceTriangleCount());
        std::printf(
            "bunny, threshold %d: %d nodes, %d leaves, height %d, %d pieces from %d "
            "triangles, %d budget leaves, %zu bytes\n",
            threshold, bsp.nodeCount(), bsp.leafCount(), bsp.height(), bsp.pieceCount(),
            bsp.sourceTriangleCount(), countLeaves(bsp, BspLeafReason::Budget), bsp.memoryBytes());
        if (threshold == 100000) {
            EXPECT_EQ(bsp.nodeCount(), 1);
        }
        if (threshold >= 64) {
            // The bunny is coarse (3674 triangles): leaves of 64 pieces are 8 x 8
            // patches, half of whose triangles touch a cut; the piece budget is not
            // reached.
            EXPECT_EQ(countLeaves(bsp, BspLeafReason::Budget), 0);
            EXPECT_LT(bsp.pieceCount(), 4 * bsp.sourceTriangleCount());
        }
        SeededRandom rng(threshold);
        for (int k = 0; k < 5; ++k) expectFrontToBack(bsp, randomPoint(rng, mesh.bounds, 0.5));
    }
}

TEST(ObjectBspBuild, RandomSoupsKeepTheirTriangles) {
    for (uint64_t seed : test::seedsToRun(1, 60)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const TriangleMesh mesh = randomSoup(rng);
            const ObjectBsp bsp(mesh, randomParams(rng));
            expectTreeValid(mesh, bsp);
            expectLeavesRespectThreshold(bsp);
        });
    }
}

TEST(ObjectBspBuild, DegenerateMeshes) {
    SeededRandom rng(5);
    const Aabb space{{0, 0, 0}, {1, 1, 1}};
    std::vector<std::pair<std::string, std::vector<glm::dvec3>>> cases;
    {  // all coplanar, in a plane perpendicular to an axis and in a slanted one
        std::vector<glm::dvec3> flat, slanted;
        for (int t = 0; t < 300; ++t)
            for (int k = 0; k < 3; ++k) {
                glm::dvec3 p = randomPoint(rng, space, 0);
                flat.push_back({p.x, p.y, 0.25});
                slanted.push_back({p.x, p.y, p.x + 2 * p.y});
            }
        cases.push_back({"coplanar on an axis plane", flat});
        cases.push_back({"coplanar slanted", slanted});
    }
    {  // one triangle many times
        std::vector<glm::dvec3> dup;
        for (int t = 0; t < 200; ++t) dup.insert(dup.end(), {{0, 0, 0}, {1, 0, 0}, {0, 1, 1}});
        cases.push_back({"duplicates", dup});
    }
    {  // zero-area triangles: points, segments, collinear corners
        std::vector<glm::dvec3> zero;
        for (int t = 0; t < 200; ++t) {
            const glm::dvec3 a = randomPoint(rng, space, 0), b = randomPoint(rng, space, 0);
            if (t % 3 == 0) zero.insert(zero.end(), {a, a, a});
            if (t % 3 == 1) zero.insert(zero.end(), {a, b, b});
            if (t % 3 == 2) zero.insert(zero.end(), {a, b, 0.25 * a + 0.75 * b});
        }
        cases.push_back({"zero area", zero});
    }
    {  // triangles in the planes x = y = z = 0.5, all sharing the plane of the median
        std::vector<glm::dvec3> planes;
        for (int t = 0; t < 100; ++t) {
            const glm::dvec3 p = randomPoint(rng, space, 0), q = randomPoint(rng, space, 0);
            planes.insert(planes.end(), {{0.5, p.y, p.z}, {0.5, q.y, q.z}, {0.5, p.z, q.y}});
        }
        cases.push_back({"one plane at the median", planes});
    }
    {  // long thin triangles through one point: every plane cuts most of them
        std::vector<glm::dvec3> fan;
        for (int t = 0; t < 300; ++t) {
            const double angle = 0.0209 * t;
            fan.insert(fan.end(),
                       {{0, 0, 0},
                        {100 * std::cos(angle), 100 * std::sin(angle), 1},
                        {100 * std::cos(angle + 0.01), 100 * std::sin(angle + 0.01), -1}});
        }
        cases.push_back({"fan", fan});
    }
    cases.push_back({"single triangle", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
    cases.push_back({"empty", {}});
    for (const auto& [name, corners] : cases)
        for (int threshold : {1, 4}) {
            SCOPED_TRACE(name + ", threshold " + std::to_string(threshold));
            const TriangleMesh mesh = makeMesh(corners);
            ObjectBspParams params;
            params.max_leaf_triangles = threshold;
            params.max_depth = 30;
            const ObjectBsp bsp(mesh, params);
            expectTreeValid(mesh, bsp);
            expectLeavesRespectThreshold(bsp);
            expectFrontToBack(bsp, {0.3, 0.6, -0.2});
            if (name == "duplicates") {
                EXPECT_EQ(bsp.nodeCount(), 1);
                EXPECT_EQ(countLeaves(bsp, BspLeafReason::Unsplittable), 1);
            }
            // The budget, overshot by at most the split during which it ran out.
            if (name == "fan") {
                EXPECT_LE(bsp.pieceCount(), 12 * 300);
            }
        }
}

TEST(ObjectBspBuild, DepthBoundStopsLeaves) {
    SeededRandom rng(11);
    const TriangleMesh mesh = randomSoup(rng);
    for (int depth : {0, 1, 2, 3}) {
        ObjectBspParams params;
        params.max_leaf_triangles = 1;
        params.max_depth = depth;
        const ObjectBsp bsp(mesh, params);
        expectTreeValid(mesh, bsp);
        expectLeavesRespectThreshold(bsp);
        EXPECT_EQ(bsp.height(), depth);
        EXPECT_GT(countLeaves(bsp, BspLeafReason::Depth), 0);
    }
}

TEST(ObjectBspTraversal, RandomEyesVisitFrontToBack) {
    for (uint64_t seed : test::seedsToRun(1, 30)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const TriangleMesh mesh = randomSoup(rng);
            const ObjectBsp bsp(mesh, randomParams(rng));
            const Aabb& cell = bsp.node(ObjectBsp::kRoot).cell;
            for (int k = 0; k < 10; ++k) expectFrontToBack(bsp, randomPoint(rng, cell, 3.0));
        });
    }
}

TEST(ObjectBspTraversal, SkippedSubtreesAreNotVisited) {
    SeededRandom rng(3);
    const TriangleMesh mesh = randomSoup(rng);
    ObjectBspParams params;
    params.max_leaf_triangles = 2;
    const ObjectBsp bsp(mesh, params);
    ASSERT_GT(bsp.nodeCount(), 7);
    std::vector<int> parent(size_t(bsp.nodeCount()), -1);
    for (int i = 0; i < bsp.nodeCount(); ++i)
        if (!bsp.node(i).isLeaf())
            parent[size_t(bsp.node(i).low)] = parent[size_t(bsp.node(i).high)] = i;
    std::vector<int> visited;
    bsp.traverseFrontToBack({0, 0, 0}, glm::dvec3(0.0), [&](const ObjectBspNodeView& v) {
        visited.push_back(v.id);
        return v.depth < 2;
    });
    int depth2 = 0;
    for (int id : visited) {
        EXPECT_LE(bsp.node(id).depth, 2);
        depth2 += bsp.node(id).depth == 2;
    }
    EXPECT_GT(depth2, 0);
}

TEST(ObjectBspTraversal, TranslationIsAppliedAtQueryTime) {
    SeededRandom rng(8);
    const TriangleMesh mesh = randomSoup(rng);
    const ObjectBsp bsp(mesh);
    const glm::dvec3 translation{100.0, -20.0, 3.5};
    for (int k = 0; k < 10; ++k) {
        const glm::dvec3 eye = randomPoint(rng, bsp.node(0).cell, 2.0);
        std::vector<int> moved, local;
        bsp.traverseFrontToBack(eye + translation, translation, [&](const ObjectBspNodeView& v) {
            moved.push_back(v.id);
            EXPECT_EQ(v.bounds.min, bsp.node(v.id).bounds.min + translation);
            EXPECT_EQ(v.bounds.max, bsp.node(v.id).bounds.max + translation);
            EXPECT_EQ(v.bounds.min, bsp.worldBounds(v.id, translation).min);
            return true;
        });
        local = visitOrder(bsp, eye);
        EXPECT_EQ(moved, local);
    }
}

TEST(ObjectBspBuild, ReportsItsSizes) {
    SeededRandom rng(2);
    const TriangleMesh mesh = randomSoup(rng);
    const ObjectBsp bsp(mesh);
    EXPECT_GE(bsp.memoryBytes(), size_t(bsp.nodeCount()) * sizeof(ObjectBspNode) +
                                     size_t(bsp.pieceCount()) * sizeof(BspTrianglePiece));
    EXPECT_EQ(int(bsp.nodes().size()), bsp.nodeCount());
    EXPECT_EQ(int(bsp.pieces().size()), bsp.pieceCount());
}

}  // namespace
}  // namespace gridcull
