// writeCameraPath (culling/io/camera_path_writer.h): the keys become the scene's
// camera path, read back equal, with time.frames spanning them and every other
// key of the file kept in order; the old file is kept as FILE~; a file that no
// longer parses is refused and left as it was.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "culling/io/camera_path_writer.h"
#include "culling/io/scene_loader.h"

namespace gridcull {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

class CameraPathWriterTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("gridcull-path-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    // A copy of a scene of the source tree in the test's folder.
    std::string copyScene(const char* name) {
        const fs::path to = dir_ / name;
        fs::copy_file(fs::path(GRIDCULL_SOURCE_DIR) / "scenes" / name, to);
        return to.string();
    }
    fs::path dir_;
};

std::vector<CameraKey> flight(int count, double dt) {
    std::vector<CameraKey> keys;
    for (int k = 0; k < count; ++k) {
        CameraKey key;
        key.t = k * dt;
        key.position = {10.0 + k, 12.0, 5.0 + 0.5 * k};
        key.target = key.position + glm::dvec3(0.0, 0.0, 10.0);
        keys.push_back(key);
    }
    return keys;
}

TEST_F(CameraPathWriterTest, TheFlightBecomesTheCameraPathAndTheRestIsKept) {
    const std::string file = copyScene("walkthrough-3d.json");
    const SceneLoadResult before = loadSceneFile(file);
    ASSERT_TRUE(before.scene);
    const std::vector<CameraKey> keys = flight(25, before.scene->dt);
    std::string error;
    ASSERT_TRUE(writeCameraPath(file, keys, before.scene->dt, error)) << error;

    const SceneLoadResult after = loadSceneFile(file);
    ASSERT_TRUE(after.scene) << after.errors.front();
    const std::vector<CameraKey>& path = after.scene->camera.path;
    ASSERT_EQ(path.size(), keys.size());
    for (size_t k = 0; k < keys.size(); ++k) {
        EXPECT_DOUBLE_EQ(path[k].t, keys[k].t);
        EXPECT_EQ(path[k].position, keys[k].position);
        EXPECT_EQ(path[k].target, keys[k].target);
    }
    EXPECT_EQ(after.scene->frames, 25) << "frames 0..24 fly the 25 keys";
    EXPECT_EQ(after.scene->objects.size(), before.scene->objects.size());
    EXPECT_EQ(after.scene->name, before.scene->name);
    const std::string text = readAll(file);
    EXPECT_LT(text.find("\"format\""), text.find("\"camera\"")) << "keys keep their order";
    EXPECT_TRUE(fs::exists(file + "~"));
    EXPECT_EQ(readAll(file + "~"), readAll(fs::path(GRIDCULL_SOURCE_DIR) / "scenes/walkthrough-3d.json"));
}

TEST_F(CameraPathWriterTest, A2dSceneGetsTwoNumbersAPosition) {
    const std::string file = copyScene("walls-2d.json");
    std::string error;
    ASSERT_TRUE(writeCameraPath(file, flight(3, 0.04), 0.04, error)) << error;
    const SceneLoadResult after = loadSceneFile(file);
    ASSERT_TRUE(after.scene) << after.errors.front();
    EXPECT_EQ(after.scene->camera.path.size(), 3u);
}

TEST_F(CameraPathWriterTest, ABrokenFileIsRefusedAndLeftAsItWas) {
    const std::string file = (dir_ / "broken.json").string();
    std::ofstream(file) << "{\"camera\": ";
    std::string error;
    EXPECT_FALSE(writeCameraPath(file, flight(2, 0.04), 0.04, error));
    EXPECT_NE(error.find("broken.json"), std::string::npos) << error;
    EXPECT_EQ(readAll(file), "{\"camera\": ");
    EXPECT_FALSE(fs::exists(file + "~"));
    EXPECT_FALSE(writeCameraPath((dir_ / "none.json").string(), flight(2, 0.04), 0.04, error));
    EXPECT_FALSE(writeCameraPath(copyScene("walls-2d.json"), {}, 0.04, error));
}

}  // namespace
}  // namespace gridcull
