// The exact oracle on the scenes shipped in scenes/: it must agree with the
// brute-force reference (oracle_brute_force.h) at a low resolution, and vfc must
// contain it at the default resolution, on frames spread over each scene's run.
#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"
#include "culling/oracle/exact_oracle.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/oracle/oracle_brute_force.h"

namespace gridcull {
namespace {

std::vector<std::string> shippedScenes() {
    std::vector<std::string> paths;
    const std::filesystem::path dir = std::filesystem::path(GRIDCULL_SOURCE_DIR) / "scenes";
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.path().extension() == ".json") paths.push_back(entry.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

TEST(OracleScenes, ThereAreScenesToTest) {
    EXPECT_FALSE(shippedScenes().empty());
}

TEST(OracleScenes, ExactEqualsBruteForceOnShippedScenes) {
    OracleOptions options;
    options.resolution = 64;
    options.rays_per_turn = 4096;
    ExactOracle exact{options};
    FrameResult out;
    for (const std::string& path : shippedScenes()) {
        SCOPED_TRACE(path);
        const SceneLoadResult loaded = loadSceneFile(path);
        ASSERT_TRUE(loaded.scene) << (loaded.errors.empty() ? "" : loaded.errors.front());
        const Scene& scene = *loaded.scene;
        exact.reset(scene);
        for (const int frame : {0, scene.frames / 2, scene.frames - 1}) {
            SCOPED_TRACE("frame " + std::to_string(frame));
            const double t = scene.timeOfFrame(frame);
            exact.cull(scene, cameraAt(scene, t), t, out);
            const test::Reference ref = test::bruteForce(scene, t, options);
            const std::set<int> got(out.pvs.begin(), out.pvs.end());
            for (const int id : ref.required) EXPECT_TRUE(got.count(id)) << "missed id " << id;
            for (const int id : got) EXPECT_TRUE(ref.allowed.count(id)) << "extra id " << id;
        }
    }
}

TEST(OracleScenes, VfcContainsExactOnShippedScenes) {
    ExactOracle exact;
    auto vfc = test::makeOrDie("vfc");
    FrameResult exact_out, vfc_out;
    for (const std::string& path : shippedScenes()) {
        SCOPED_TRACE(path);
        const SceneLoadResult loaded = loadSceneFile(path);
        ASSERT_TRUE(loaded.scene);
        const Scene& scene = *loaded.scene;
        exact.reset(scene);
        vfc->reset(scene);
        for (int frame = 0; frame < scene.frames; frame += std::max(1, scene.frames / 12)) {
            SCOPED_TRACE("frame " + std::to_string(frame));
            const double t = scene.timeOfFrame(frame);
            const Camera camera = cameraAt(scene, t);
            exact.cull(scene, camera, t, exact_out);
            vfc->cull(scene, camera, t, vfc_out);
            EXPECT_TRUE(test::isSubset(exact_out.pvs, vfc_out.pvs));
            EXPECT_FALSE(exact_out.pvs.empty());  // every shipped camera sees something
        }
    }
}

}  // namespace
}  // namespace gridcull
