// The culler registry, counter names, timedCull and the `all` baseline.
#include <algorithm>
#include <cctype>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/baseline/all_culler.h"
#include "culling/api/culler.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

using V = std::vector<int>;

TEST(CounterNames, AreTheSpecNamesInSnakeCase) {
    const std::vector<std::string> expected = {
        "voxels_visited", "tbv_created",     "tbv_expired",    "tbv_revealed",
        "object_updates", "update_messages", "pixel_queries",  "occlusion_queries",
        "nodes_visited",  "triangles_drawn", "objects_tested", "pixels_sampled",
        "occlusion_tests", "pixels_read",   "cell_updates",   "bvh_rebuilds",
        "probability_skips"};
    ASSERT_EQ(int(expected.size()), kCounterCount);
    std::set<std::string> seen;
    for (int i = 0; i < kCounterCount; ++i) {
        const std::string name = counterName(Counter(i));
        EXPECT_EQ(name, expected[size_t(i)]);
        EXPECT_TRUE(std::all_of(name.begin(), name.end(), [](char c) {
            return std::islower(c) || c == '_';
        })) << name;
        seen.insert(name);
    }
    EXPECT_EQ(int(seen.size()), kCounterCount);
}

TEST(CullerRegistry, MakesEveryListedCullerUnderItsName) {
    const std::vector<std::string> names = cullerNames();
    EXPECT_EQ(names, (std::vector<std::string>{"all", "vfc", "exact", "rgvc", "lazy-grid",
                                              "lazy-grid-z", "busy-grid", "busy-grid-tight"}));
    for (const std::string& name : names) {
        std::string error;
        auto culler = makeCuller(name, CullerOptions{}, error);
        ASSERT_TRUE(culler) << name << ": " << error;
        EXPECT_EQ(std::string(culler->name()), name);
        EXPECT_TRUE(error.empty());
    }
}

TEST(CullerRegistry, UnknownNameIsAnErrorThatListsTheKnownOnes) {
    std::string error;
    EXPECT_EQ(makeCuller("rgvcc", CullerOptions{}, error), nullptr);
    EXPECT_NE(error.find("rgvcc"), std::string::npos) << error;
    for (const std::string& name : cullerNames())
        EXPECT_NE(error.find(name), std::string::npos) << error;
    error.clear();
    EXPECT_EQ(makeCuller("", CullerOptions{}, error), nullptr);
    EXPECT_FALSE(error.empty());
}

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
    for (const std::string& name : cullerNames()) {
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
