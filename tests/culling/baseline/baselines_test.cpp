// timedCull and the `all` baseline.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/api/culler.h"
#include "culling/baseline/all_culler.h"
#include "culling/registry/registry.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

using V = std::vector<int>;

Scene smallScene() {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 50, 5}, {50, 50, 100}, 60.0);
    // Listed out of id order on purpose.
    test::addSphere(scene, 7, {50, 50, 60}, 2);
    test::addBox(scene, 3, {10, 10, 10}, {12, 12, 12});
    test::addSphere(scene, 42, {50, 50, -60}, 2);
    test::addSphere(scene, 0, {80, 50, 60}, 2);
    scene.finalize();
    return scene;
}

TEST(AllCuller, ReportsEveryIdSortedAndNoCounters) {
    const Scene scene = smallScene();
    AllCuller all;
    all.reset(scene);
    FrameResult out;
    out.pvs = {99, 98};  // stale content must be replaced, not appended to
    out.stats.set(Counter::VoxelsVisited, 5);
    all.cull(scene, cameraAt(scene, 0.0), 0.0, out);
    EXPECT_EQ(out.pvs, (V{0, 3, 7, 42}));
    EXPECT_EQ(out.stats.present, 0u);
    Scene empty = test::scene3d();
    empty.finalize();
    all.reset(empty);
    all.cull(empty, cameraAt(empty, 0.0), 0.0, out);
    EXPECT_TRUE(out.pvs.empty());
}

TEST(TimedCull, SetsCullMsAndKeepsTheResult) {
    const Scene scene = smallScene();
    for (const std::string& name : algorithmNames()) {
        SCOPED_TRACE(name);
        auto culler = test::makeOrDie(name);
        culler->reset(scene);
        FrameResult out;
        out.stats.cull_ms = -1.0;
        timedCull(*culler, scene, cameraAt(scene, 0.0), 0.0, out);
        EXPECT_GE(out.stats.cull_ms, 0.0);
        EXPECT_LT(out.stats.cull_ms, 60000.0);
        EXPECT_TRUE(std::is_sorted(out.pvs.begin(), out.pvs.end()));
        // Every culler sees the two spheres ahead; only `all` reports the one behind.
        EXPECT_TRUE(test::isSubset(V{0, 7}, out.pvs));
        EXPECT_EQ(std::count(out.pvs.begin(), out.pvs.end(), 42), name == "all" ? 1 : 0);
    }
}

}  // namespace
}  // namespace gridcull
