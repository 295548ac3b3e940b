// Replays the inputs the scene-loader fuzzer found (tests/scenes/fuzz-regressions,
// see its README.md and docs/FUZZING.md): each must load into a scene or be
// rejected with clean messages, satisfy the fuzzer's properties
// (tests/fuzz/scene_fuzz_checks.h), and, when small enough, be culled by every
// algorithm without a false cull. Runs in the sanitizer build, so a crash,
// leak or undefined behaviour that comes back fails here too.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"
#include "tests/fuzz/scene_fuzz_checks.h"

namespace gridcull {
namespace {

const std::string kDir = std::string(GRIDCULL_SOURCE_DIR) + "/tests/scenes/fuzz-regressions";

std::vector<std::filesystem::path> regressionInputs() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(kDir))
        if (entry.is_regular_file() && entry.path().extension() == ".json")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

TEST(SceneFuzzRegression, EveryFoundInputLoadsOrFailsCleanly) {
    const std::vector<std::filesystem::path> files = regressionInputs();
    ASSERT_FALSE(files.empty()) << "no inputs in " << kDir;
    for (const std::filesystem::path& file : files) {
        SCOPED_TRACE(file.filename().string());
        std::ifstream in(file, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        // As the fuzzer loads it: text, meshes resolved against scenes/.
        const std::string name = "fuzz.json";
        const SceneLoadResult result =
            loadSceneText(text.str(), name, std::string(GRIDCULL_SOURCE_DIR) + "/scenes");
        EXPECT_EQ(fuzz::checkLoadResult(result, name), "");
        if (result.scene && fuzz::smallEnoughToCull(*result.scene)) {
            EXPECT_EQ(fuzz::checkCulling(*result.scene), "");
        }
        std::printf("[fuzz-regression] %s: %s\n", file.filename().string().c_str(),
                    result.scene ? "loads" : result.errors.front().c_str());
    }
}

}  // namespace
}  // namespace gridcull
