// Differential tests on seeded random scenes (2D and 3D, spheres, boxes, meshes
// and polygons, static and moving, cameras inside and outside the world):
//  - vfc contains exact, all is every id, and every PVS is sorted and unique;
//  - the exact oracle equals a brute-force reference that casts every pixel's
//    (ray's) documented ray against every object with no bounds, no ordering and
//    no early-outs. Both use culling/scene/ray_intersect.h; this checks everything the
//    oracle adds on top (screen bounds, per-row spans, angular intervals, front-
//    to-back skipping, triangle rasterization and near clipping, the parity fill).
// On failure the seed and the command that replays it are printed
// (tests/common/test_seeds.h: GRIDCULL_SEED=N runs seed N alone).
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "culling/oracle/exact_oracle.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/oracle/oracle_brute_force.h"

namespace gridcull {
namespace {

using V = std::vector<int>;

constexpr int kSceneCount = 200;
constexpr double kFrameTimes[] = {0.0, 0.7, 2.3};

glm::dvec3 randomPoint(SeededRandom& rng, double lo, double hi, int dimensions) {
    return {rng.uniform(lo, hi), rng.uniform(lo, hi), dimensions == 2 ? 0.0 : rng.uniform(lo, hi)};
}

Scene randomScene(uint64_t seed) {
    SeededRandom rng(seed);
    const int dims = seed % 2 == 0 ? 3 : 2;
    const int res = 4 + int(rng.below(17));
    Scene scene = dims == 3 ? test::makeScene(3, Aabb{{0, 0, 0}, {100, 100, 100}}, {res, res, res})
                            : test::makeScene(2, Aabb{{0, 0, 0}, {100, 100, 0}}, {res, res, 1});
    const int count = 1 + int(rng.below(30));
    for (int id = 0; id < count; ++id) {
        const glm::dvec3 c = randomPoint(rng, 0, 100, dims);
        const double kind = rng.uniform();
        if (kind < 0.45) {
            test::addSphere(scene, id, c, rng.uniform(0.5, 8.0));
        } else if (kind < 0.8) {
            const glm::dvec3 half = randomPoint(rng, 0.25, 8.0, dims);
            test::addBox(scene, id, c - half, c + half);
        } else if (dims == 3) {
            const double size = rng.uniform(1.0, 10.0);
            const double shape = rng.uniform();
            test::addMesh(scene, id, c,
                          shape < 0.4   ? test::cubeMesh(size)
                          : shape < 0.8 ? test::tetrahedronMesh(size)
                                        : test::quadMesh(size));
        } else {
            // A star-shaped polygon around c: simple and counter-clockwise.
            const int corners = 3 + int(rng.below(6));
            std::vector<glm::dvec3> points;
            for (int k = 0; k < corners; ++k) {
                const double angle = (k + rng.uniform(0.0, 0.8)) * 2.0 * 3.14159265358979 / corners;
                const double radius = rng.uniform(1.0, 10.0);
                points.push_back(c + glm::dvec3(std::cos(angle), std::sin(angle), 0) * radius);
            }
            test::addPolygon(scene, id, points);
        }
        if (rng.uniform() < 0.3) {
            scene.objects.back().motion.kind = MotionKind::Linear;
            scene.objects.back().motion.velocity = randomPoint(rng, -10, 10, dims);
        }
    }
    // Cameras inside and outside the world, now and then inside an object or
    // with a near plane deep enough to cut into objects.
    glm::dvec3 eye = randomPoint(rng, -30, 130, dims);
    const double placement = rng.uniform();
    const SceneObject& near_object = scene.objects[rng.below(scene.objects.size())];
    if (placement < 0.2) {
        eye = near_object.anchor;
    } else if (placement < 0.4) {
        // Just outside the object's bounds, so that it crosses the eye plane.
        const glm::dvec3 reach = near_object.bounds.extent() * 0.5;
        eye = near_object.anchor + randomPoint(rng, -1, 1, dims) * reach * rng.uniform(1.0, 1.6);
    }
    const double near = rng.uniform() < 0.3 ? rng.uniform(1.0, 8.0) : rng.uniform(0.05, 1.0);
    const glm::dvec3 target = randomPoint(rng, 0, 100, dims);
    const double fov =
        dims == 3 ? rng.uniform(20, 120) : (rng.uniform() < 0.2 ? 360.0 : rng.uniform(20, 360));
    test::setCamera(scene, eye, target, fov, near, rng.uniform(20, 300));
    scene.camera.aspect = rng.uniform(0.5, 2.5);
    scene.finalize();
    return scene;
}

bool sortedUnique(const V& ids) {
    return std::adjacent_find(ids.begin(), ids.end(), [](int a, int b) { return a >= b; }) ==
           ids.end();
}

TEST(OracleDifferential, VfcContainsExactAndAllIsEveryId) {
    ExactOracle exact;
    auto vfc = test::makeOrDie("vfc");
    auto all = test::makeOrDie("all");
    FrameResult exact_out, vfc_out, all_out;
    for (const uint64_t seed : test::seedsToRun(0, kSceneCount))
        test::withSeed(seed, [&] {
            const Scene scene = randomScene(seed);
            V ids;
            for (const SceneObject& o : scene.objects) ids.push_back(o.id);
            std::sort(ids.begin(), ids.end());
            exact.reset(scene);
            vfc->reset(scene);
            all->reset(scene);
            for (const double t : kFrameTimes) {
                SCOPED_TRACE("t " + std::to_string(t));
                const Camera camera = cameraAt(scene, t);
                exact.cull(scene, camera, t, exact_out);
                vfc->cull(scene, camera, t, vfc_out);
                all->cull(scene, camera, t, all_out);
                ASSERT_TRUE(sortedUnique(exact_out.pvs));
                ASSERT_TRUE(sortedUnique(vfc_out.pvs));
                ASSERT_EQ(all_out.pvs, ids);
                ASSERT_TRUE(test::isSubset(exact_out.pvs, vfc_out.pvs));
                ASSERT_TRUE(test::isSubset(vfc_out.pvs, ids));
            }
        });
}

TEST(OracleDifferential, ExactEqualsBruteForceRayCasting) {
    OracleOptions options;
    options.resolution = 160;       // 160 x (160 / aspect) rays per 3D frame
    options.rays_per_turn = 16384;  // the default in 2D
    ExactOracle exact{options};
    FrameResult out;
    int compared_ids = 0;
    for (const uint64_t seed : test::seedsToRun(0, kSceneCount))
        test::withSeed(seed, [&] {
            const Scene scene = randomScene(seed);
            exact.reset(scene);
            const double t = kFrameTimes[seed % 3];
            exact.cull(scene, cameraAt(scene, t), t, out);
            const test::Reference ref = test::bruteForce(scene, t, options);
            const std::set<int> got(out.pvs.begin(), out.pvs.end());
            for (const int id : ref.required) EXPECT_TRUE(got.count(id)) << "missed id " << id;
            for (const int id : got) EXPECT_TRUE(ref.allowed.count(id)) << "extra id " << id;
            compared_ids += int(got.size());
        });
    // The random scenes must actually show things, or the comparison proves little.
    if (!test::singleSeedRun()) {
        EXPECT_GT(compared_ids, kSceneCount);
    }
}

}  // namespace
}  // namespace gridcull
