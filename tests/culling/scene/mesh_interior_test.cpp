// meshInteriorBoxes (culling/scene/mesh_interior.h): the boxes regular-grid culling
// may treat as opaque. A box that pokes out of its mesh would hide what is visible,
// so every box returned is checked by code independent of the implementation: no
// triangle meets it (clipping the triangle to the box, not separating axes) and
// seeded random points in it are inside by parity along random directions (not
// along the lattice's axes). Then the shapes: what an open or flat mesh gives
// (nothing), where the boxes may not go (a notch, a hole, a cavity), and how much
// of the volume they cover, which the divergence theorem measures.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "culling/io/mesh_loader.h"
#include "culling/scene/mesh_interior.h"
#include "culling/scene/ray_intersect.h"
#include "culling/scene/seeded_random.h"

namespace gridcull {
namespace {

using glm::dvec3;

// Box corners sit on lattice planes min + extent * i / n: a few ulps from the exact
// fraction, far inside this.
constexpr double kPlaneTolerance = 1e-12;
constexpr int kPointsPerBox = 1000;  // a multiple of 8 (one share per octant)
// Boxes of the same number of cells differ in volume by rounding alone.
constexpr double kVolumeTolerance = 1e-9;

TriangleMesh makeMesh(std::vector<dvec3> vertices, std::vector<uint32_t> indices) {
    TriangleMesh mesh;
    mesh.file = "test";
    mesh.vertices = std::move(vertices);
    mesh.indices = std::move(indices);
    mesh.bounds = {mesh.vertices[0], mesh.vertices[0]};
    for (const dvec3& v : mesh.vertices) mesh.bounds.merge({v, v});
    mesh.closed = isClosedMesh(mesh.vertices, mesh.indices);
    return mesh;
}

// The box [lo, hi] as 12 triangles; corner i as in Aabb::corner. `outward` false
// turns every triangle round (a cavity's wall).
void appendBox(std::vector<dvec3>& v, std::vector<uint32_t>& idx, const dvec3& lo, const dvec3& hi,
               bool outward = true) {
    const uint32_t base = uint32_t(v.size());
    const Aabb box{lo, hi};
    for (int i = 0; i < 8; ++i) v.push_back(box.corner(i));
    const uint32_t faces[36] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    for (int t = 0; t < 12; ++t) {
        idx.push_back(base + faces[3 * t]);
        idx.push_back(base + faces[3 * t + (outward ? 1 : 2)]);
        idx.push_back(base + faces[3 * t + (outward ? 2 : 1)]);
    }
}

TriangleMesh boxMesh(const dvec3& lo, const dvec3& hi) {
    std::vector<dvec3> v;
    std::vector<uint32_t> idx;
    appendBox(v, idx, lo, hi);
    return makeMesh(v, idx);
}

// Subdivided icosahedron on the sphere of `radius` around `center`.
TriangleMesh icosphere(int subdivisions, double radius, const dvec3& center) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<dvec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                            {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                            {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (dvec3& p : v) p = glm::normalize(p);
    std::vector<uint32_t> idx = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                 6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoint;
        auto mid = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = midpoint.find(key);
            if (it != midpoint.end()) return it->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            return midpoint[key] = uint32_t(v.size() - 1);
        };
        std::vector<uint32_t> finer;
        for (size_t i = 0; i < idx.size(); i += 3) {
            const uint32_t a = idx[i], b = idx[i + 1], c = idx[i + 2];
            const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            finer.insert(finer.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        idx = std::move(finer);
    }
    for (dvec3& p : v) p = center + radius * p;
    return makeMesh(v, idx);
}

// The outer surface of a set of unit voxels (integer corners): a square face, two
// triangles, wherever a voxel meets an empty neighbour.
TriangleMesh voxelMesh(const std::vector<std::array<int, 3>>& voxels) {
    std::map<std::array<int, 3>, bool> filled;
    for (const auto& c : voxels) filled[c] = true;
    std::vector<dvec3> v;
    std::vector<uint32_t> idx;
    for (const auto& c : voxels) {
        for (int axis = 0; axis < 3; ++axis) {
            for (int side : {0, 1}) {
                std::array<int, 3> next = c;
                next[size_t(axis)] += side ? 1 : -1;
                if (filled.count(next)) continue;
                const int u = (axis + 1) % 3, w = (axis + 2) % 3;
                const uint32_t base = uint32_t(v.size());
                for (int k = 0; k < 4; ++k) {
                    dvec3 p(c[0], c[1], c[2]);
                    p[axis] += side;
                    p[u] += (k == 1 || k == 2) ? 1 : 0;
                    p[w] += (k >= 2) ? 1 : 0;
                    v.push_back(p);
                }
                idx.insert(idx.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
            }
        }
    }
    return makeMesh(v, idx);
}

// Volume enclosed, by the divergence theorem (sum of signed tetrahedra).
double meshVolume(const TriangleMesh& mesh) {
    double six_volume = 0.0;
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const dvec3& a = mesh.vertices[mesh.indices[i]];
        const dvec3& b = mesh.vertices[mesh.indices[i + 1]];
        const dvec3& c = mesh.vertices[mesh.indices[i + 2]];
        six_volume += glm::dot(a, glm::cross(b, c));
    }
    return std::abs(six_volume) / 6.0;
}

double boxVolume(const Aabb& b) {
    return b.extent().x * b.extent().y * b.extent().z;
}

double coverage(const TriangleMesh& mesh, const std::vector<Aabb>& boxes) {
    double covered = 0.0;
    for (const Aabb& b : boxes) covered += boxVolume(b);
    return covered / meshVolume(mesh);
}

// Does the triangle meet the closed box? Clips it to the box's six half-spaces
// (Sutherland-Hodgman); anything left, even one point on a face, meets.
bool triangleMeetsBox(const dvec3& a, const dvec3& b, const dvec3& c, const Aabb& box) {
    const dvec3 lo = glm::min(glm::min(a, b), c), hi = glm::max(glm::max(a, b), c);
    if (glm::any(glm::lessThan(hi, box.min)) || glm::any(glm::greaterThan(lo, box.max)))
        return false;  // apart on an axis: nothing to clip
    std::vector<dvec3> polygon = {a, b, c};
    for (int axis = 0; axis < 3 && !polygon.empty(); ++axis) {
        for (int side : {0, 1}) {
            const double plane = side ? box.max[axis] : box.min[axis];
            auto keep = [&](const dvec3& p) { return side ? p[axis] <= plane : p[axis] >= plane; };
            std::vector<dvec3> clipped;
            for (size_t i = 0; i < polygon.size(); ++i) {
                const dvec3& p = polygon[i];
                const dvec3& q = polygon[(i + 1) % polygon.size()];
                if (keep(p)) clipped.push_back(p);
                if (keep(p) != keep(q)) {
                    dvec3 cut = p + (q - p) * ((plane - p[axis]) / (q[axis] - p[axis]));
                    cut[axis] = plane;
                    clipped.push_back(cut);
                }
            }
            polygon = std::move(clipped);
        }
    }
    return !polygon.empty();
}

// Even-odd: the ray from p along dir crosses the surface an odd number of times.
// Only `candidates` (triangle starts in mesh.indices) can be crossed.
bool insideByParity(const TriangleMesh& mesh, const std::vector<size_t>& candidates, const dvec3& p,
                    const dvec3& dir) {
    bool odd = false;
    for (size_t i : candidates) {
        double s;
        if (lineTriangle(p, dir, mesh.vertices[mesh.indices[i]], mesh.vertices[mesh.indices[i + 1]],
                         mesh.vertices[mesh.indices[i + 2]], s) &&
            s > 0.0)
            odd = !odd;
    }
    return odd;
}

// The triangles that a ray along dir from somewhere in `box` may cross: those whose
// shadow along dir overlaps the box's (both as bounding rectangles in a plane
// across dir). Keeps the parity test fast on the bunny.
std::vector<size_t> trianglesAcross(const TriangleMesh& mesh, const Aabb& box, const dvec3& dir) {
    const dvec3 u =
        glm::normalize(glm::cross(dir, std::abs(dir.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    const dvec3 w = glm::cross(dir, u);
    auto shadow = [&](const dvec3* points, int count, double lo[2], double hi[2]) {
        lo[0] = lo[1] = std::numeric_limits<double>::infinity();
        hi[0] = hi[1] = -std::numeric_limits<double>::infinity();
        for (int k = 0; k < count; ++k) {
            const double pu = glm::dot(points[k], u), pw = glm::dot(points[k], w);
            lo[0] = std::min(lo[0], pu);
            hi[0] = std::max(hi[0], pu);
            lo[1] = std::min(lo[1], pw);
            hi[1] = std::max(hi[1], pw);
        }
    };
    dvec3 corners[8];
    for (int i = 0; i < 8; ++i) corners[i] = box.corner(i);
    double box_lo[2], box_hi[2];
    shadow(corners, 8, box_lo, box_hi);
    std::vector<size_t> candidates;
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const dvec3 tri[3] = {mesh.vertices[mesh.indices[i]], mesh.vertices[mesh.indices[i + 1]],
                              mesh.vertices[mesh.indices[i + 2]]};
        double lo[2], hi[2];
        shadow(tri, 3, lo, hi);
        if (lo[0] <= box_hi[0] && hi[0] >= box_lo[0] && lo[1] <= box_hi[1] && hi[1] >= box_lo[1])
            candidates.push_back(i);
    }
    return candidates;
}

// What the header promises of every result: boxes of positive size, largest
// first, without common volume, met by no triangle, and inside by parity. The
// random points are drawn an eighth in each octant of the box, each octant with
// its own random direction, so that few triangles lie across each ray.
void expectBoxesInside(const TriangleMesh& mesh, const std::vector<Aabb>& boxes, uint64_t seed) {
    for (size_t i = 0; i < boxes.size(); ++i) {
        const Aabb& box = boxes[i];
        SCOPED_TRACE("box " + std::to_string(i));
        ASSERT_GT(boxVolume(box), 0.0);
        if (i > 0) {
            EXPECT_LE(boxVolume(box), boxVolume(boxes[i - 1]) * (1.0 + kVolumeTolerance));
        }
        for (size_t j = 0; j < i; ++j) {
            const dvec3 lo = glm::max(box.min, boxes[j].min), hi = glm::min(box.max, boxes[j].max);
            EXPECT_TRUE(lo.x >= hi.x || lo.y >= hi.y || lo.z >= hi.z) << "overlaps box " << j;
        }
        for (size_t t = 0; t < mesh.indices.size(); t += 3) {
            ASSERT_FALSE(triangleMeetsBox(mesh.vertices[mesh.indices[t]],
                                          mesh.vertices[mesh.indices[t + 1]],
                                          mesh.vertices[mesh.indices[t + 2]], box))
                << "triangle " << t / 3;
        }
        // Fixed per box, so a failure replays as it is; the trace names the seed.
        SCOPED_TRACE("seed " + std::to_string(seed + i));
        SeededRandom rng(seed + i);
        int outside = 0;
        for (int octant = 0; octant < 8; ++octant) {
            const dvec3 half = box.extent() * 0.5;
            const dvec3 lo = box.min + half * dvec3(octant & 1, (octant >> 1) & 1, octant >> 2);
            const Aabb part{lo, lo + half};
            const dvec3 dir = randomDirection(rng, 3);
            const std::vector<size_t> candidates = trianglesAcross(mesh, part, dir);
            for (int k = 0; k < kPointsPerBox / 8; ++k) {
                const dvec3 p = lo + half * dvec3(rng.uniform(), rng.uniform(), rng.uniform());
                if (!insideByParity(mesh, candidates, p, dir)) ++outside;
            }
        }
        EXPECT_EQ(outside, 0);
    }
}

// Do the open boxes a and b share volume (more than rounding)?
bool overlaps(const Aabb& a, const Aabb& b) {
    const dvec3 lo = glm::max(a.min, b.min), hi = glm::min(a.max, b.max);
    return hi.x - lo.x > kPlaneTolerance && hi.y - lo.y > kPlaneTolerance &&
           hi.z - lo.z > kPlaneTolerance;
}

TEST(MeshInterior, ClosedUnitCubeIsOneBoxAllButItsOuterCells) {
    const TriangleMesh cube = boxMesh({0, 0, 0}, {1, 1, 1});
    ASSERT_TRUE(cube.closed);
    const std::vector<Aabb> boxes = meshInteriorBoxes(cube);
    // 24 cells a side; the outer layer touches the faces, the 22^3 others are inside.
    ASSERT_EQ(boxes.size(), 1u);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(boxes[0].min[axis], 1.0 / 24.0, kPlaneTolerance);
        EXPECT_NEAR(boxes[0].max[axis], 23.0 / 24.0, kPlaneTolerance);
    }
    EXPECT_NEAR(coverage(cube, boxes), std::pow(22.0 / 24.0, 3), kPlaneTolerance);
    expectBoxesInside(cube, boxes, 100);
}

TEST(MeshInterior, OpenCubeGivesNothing) {
    TriangleMesh cube = boxMesh({0, 0, 0}, {1, 1, 1});
    cube.indices.resize(cube.indices.size() - 6);  // the +z face's two triangles
    cube.closed = isClosedMesh(cube.vertices, cube.indices);
    ASSERT_FALSE(cube.closed);
    EXPECT_TRUE(meshInteriorBoxes(cube).empty());
    EXPECT_TRUE(meshInteriorBoxes(cube, {kMaxMeshInteriorResolution, 64}).empty());
    // The flag decides: a whole cube said to be open is not trusted either.
    TriangleMesh unsure = boxMesh({0, 0, 0}, {1, 1, 1});
    unsure.closed = false;
    EXPECT_TRUE(meshInteriorBoxes(unsure).empty());
}

// The icosphere's faces are all at least the inscribed radius from its centre, so
// a box whose corners are all within that ball is inside. Centred off the origin:
// the boxes are in the vertices' frame.
TEST(MeshInterior, IcosphereBoxesLieInTheInscribedBall) {
    const dvec3 center{3, -2, 5};
    const TriangleMesh sphere = icosphere(3, 2.0, center);
    ASSERT_TRUE(sphere.closed);
    double inscribed = 2.0;
    for (size_t i = 0; i < sphere.indices.size(); i += 3) {
        const dvec3 a = sphere.vertices[sphere.indices[i]] - center;
        const dvec3 b = sphere.vertices[sphere.indices[i + 1]] - center;
        const dvec3 c = sphere.vertices[sphere.indices[i + 2]] - center;
        inscribed =
            std::min(inscribed, std::abs(glm::dot(glm::normalize(glm::cross(b - a, c - a)), a)));
    }
    const std::vector<Aabb> boxes = meshInteriorBoxes(sphere);
    ASSERT_FALSE(boxes.empty());
    for (const Aabb& box : boxes)
        for (int i = 0; i < 8; ++i)
            EXPECT_LE(glm::length(box.corner(i) - center), inscribed + kPlaneTolerance);
    // Measured 0.754 at the default 24 cells; a tenth lower, the floor allows other
    // tie-breaks in the merge but not losing a large box.
    constexpr double kSphereCoverage = 0.68;
    EXPECT_GE(coverage(sphere, boxes), kSphereCoverage);
    expectBoxesInside(sphere, boxes, 200);
}

// An L (three unit voxels): the notch [1, 2] x [1, 2] is outside the solid.
TEST(MeshInterior, LShapedPrismLeavesTheNotchEmpty) {
    const TriangleMesh l_prism = voxelMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    ASSERT_TRUE(l_prism.closed);
    const std::vector<Aabb> boxes = meshInteriorBoxes(l_prism);
    ASSERT_FALSE(boxes.empty());
    const Aabb notch{{1, 1, -1}, {2, 2, 2}};
    for (const Aabb& box : boxes) EXPECT_FALSE(overlaps(box, notch));
    expectBoxesInside(l_prism, boxes, 300);
}

// A square ring (3 x 3 voxels less the middle): genus one, and no box may cross the
// hole. Turned about all three axes, the same ring has no face along the lattice.
TEST(MeshInterior, RingLeavesTheHoleEmpty) {
    std::vector<std::array<int, 3>> voxels;
    for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y)
            if (x != 1 || y != 1) voxels.push_back({x, y, 0});
    const TriangleMesh ring = voxelMesh(voxels);
    ASSERT_TRUE(ring.closed);
    const std::vector<Aabb> boxes = meshInteriorBoxes(ring);
    ASSERT_FALSE(boxes.empty());
    const Aabb hole{{1, 1, -1}, {2, 2, 2}};
    for (const Aabb& box : boxes) EXPECT_FALSE(overlaps(box, hole));
    expectBoxesInside(ring, boxes, 400);

    TriangleMesh turned = ring;
    const double c1 = std::cos(0.5), s1 = std::sin(0.5), c2 = std::cos(1.1), s2 = std::sin(1.1);
    for (dvec3& p : turned.vertices) {
        p = {c1 * p.x - s1 * p.y, s1 * p.x + c1 * p.y, p.z};  // about z
        p = {p.x, c2 * p.y - s2 * p.z, s2 * p.y + c2 * p.z};  // about x
    }
    turned = makeMesh(turned.vertices, turned.indices);
    const std::vector<Aabb> turned_boxes = meshInteriorBoxes(turned);
    ASSERT_FALSE(turned_boxes.empty());
    expectBoxesInside(turned, turned_boxes, 500);
}

// A box with a box-shaped cavity (two shells, the inner one facing in): the cavity
// is enclosed by surface yet outside, so only rays can tell.
TEST(MeshInterior, HollowBoxLeavesTheCavityEmpty) {
    std::vector<dvec3> v;
    std::vector<uint32_t> idx;
    appendBox(v, idx, {0, 0, 0}, {4, 4, 4});
    appendBox(v, idx, {1, 1, 1}, {3, 3, 3}, false);
    const TriangleMesh hollow = makeMesh(v, idx);
    ASSERT_TRUE(hollow.closed);
    const std::vector<Aabb> boxes = meshInteriorBoxes(hollow);
    ASSERT_FALSE(boxes.empty());
    const Aabb cavity{{1, 1, 1}, {3, 3, 3}};
    for (const Aabb& box : boxes) EXPECT_FALSE(overlaps(box, cavity));
    expectBoxesInside(hollow, boxes, 600);
}

// Closed but without volume, or thinner than three cells: nothing can be proven.
TEST(MeshInterior, FlatAndThinMeshesGiveNothing) {
    // A square as two triangles on each side (the back split along the other
    // diagonal): every edge twice, bounds flat in z.
    const TriangleMesh pillow = makeMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                         {0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2});
    ASSERT_TRUE(pillow.closed);
    EXPECT_TRUE(meshInteriorBoxes(pillow).empty());
    // A tetrahedron squashed into the plane x + y + z = 1: the bounds are the unit
    // cube, and every line through it crosses two faces at one point.
    const TriangleMesh squashed =
        makeMesh({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1.0 / 3, 1.0 / 3, 1.0 / 3}},
                 {0, 1, 2, 0, 3, 1, 1, 3, 2, 2, 3, 0});
    ASSERT_TRUE(squashed.closed);
    EXPECT_TRUE(meshInteriorBoxes(squashed).empty());
    // No triangles at all, whatever the flag says.
    TriangleMesh nothing;
    nothing.closed = true;
    EXPECT_TRUE(meshInteriorBoxes(nothing).empty());
    // 1 x 1 x 0.05 at 24 cells a side: two cells thick, both on the outer layer.
    // At 64 cells a side it is four thick, and the middle two are inside.
    const TriangleMesh slab = boxMesh({0, 0, 0}, {1, 1, 0.05});
    EXPECT_TRUE(meshInteriorBoxes(slab).empty());
    const std::vector<Aabb> finer = meshInteriorBoxes(slab, {kMaxMeshInteriorResolution, 64});
    EXPECT_EQ(finer.size(), 1u);
    expectBoxesInside(slab, finer, 800);
}

TEST(MeshInterior, MaxBoxesKeepsTheFirstTaken) {
    const TriangleMesh sphere = icosphere(3, 1.0, dvec3(0.0));
    const std::vector<Aabb> all = meshInteriorBoxes(sphere);
    ASSERT_GT(all.size(), 3u);
    EXPECT_TRUE(meshInteriorBoxes(sphere, {24, 0}).empty());
    const std::vector<Aabb> three = meshInteriorBoxes(sphere, {24, 3});
    ASSERT_EQ(three.size(), 3u);
    // The merge takes boxes in the same order whatever the limit, so three boxes
    // cover less than all of them and are among them.
    double volume_three = 0.0, volume_all = 0.0;
    for (const Aabb& b : three) volume_three += boxVolume(b);
    for (const Aabb& b : all) volume_all += boxVolume(b);
    EXPECT_LT(volume_three, volume_all);
    for (const Aabb& b : three) {
        bool found = false;
        for (const Aabb& a : all) found = found || (a.min == b.min && a.max == b.max);
        EXPECT_TRUE(found);
    }
}

TEST(MeshInterior, BunnyIsClosedAndFilledFromInside) {
    const MeshLoadResult r =
        loadObjMesh(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/meshes/bunny.obj", "bunny.obj", 1.0,
                    dvec3(0.0));
    ASSERT_TRUE(r.mesh) << r.error;
    ASSERT_TRUE(r.mesh->closed);
    const std::vector<Aabb> boxes = meshInteriorBoxes(*r.mesh);
    ASSERT_FALSE(boxes.empty());
    // Measured 0.671 at the default 24 cells; a tenth lower, as for the icosphere.
    constexpr double kBunnyCoverage = 0.60;
    EXPECT_GE(coverage(*r.mesh, boxes), kBunnyCoverage);
    expectBoxesInside(*r.mesh, boxes, 700);
}

}  // namespace
}  // namespace gridcull
