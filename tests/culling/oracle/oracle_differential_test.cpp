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
#include "tests/culling/oracle/oracle_random_scene.h"

namespace gridcull {
namespace {

using V = std::vector<int>;

constexpr int kSceneCount = 200;
constexpr double kFrameTimes[] = {0.0, 0.7, 2.3};

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
            const Scene scene = test::oracleRandomScene(seed);
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
    options.refine = 0;             // the centres alone, as the reference casts them
    ExactOracle exact{options};
    FrameResult out;
    int compared_ids = 0;
    for (const uint64_t seed : test::seedsToRun(0, kSceneCount))
        test::withSeed(seed, [&] {
            const Scene scene = test::oracleRandomScene(seed);
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
