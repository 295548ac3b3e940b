// The scene loader against the format (docs/scene-format.md): every
// malformed file under tests/scenes/bad is rejected with a message naming the
// place (tests/scenes/bad/expected.tsv), every shipped scene loads, defaults,
// id numbering and 2D storage follow the format, and no input makes it throw.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "tests/common/bad_scene_manifest.h"

#include "culling/io/scene_loader.h"

namespace gridcull {
namespace {

std::string sourcePath(const std::string& relative) {
    return std::string(GRIDCULL_SOURCE_DIR) + "/" + relative;
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string joined(const std::vector<std::string>& lines) {
    std::string all;
    for (const std::string& line : lines) all += line + "\n";
    return all;
}

// A valid 3D scene with `objects` spliced in, for tests that vary one part.
std::string scene3d(const std::string& objects, const std::string& extra = "") {
    return R"({"format": "gridcull-scene/1", "dimensions": 3,
               "world": {"min": [0, 0, 0], "max": [100, 60, 100]},
               "camera": {"path": [{"t": 0, "position": [1, 1, 1], "target": [5, 5, 5]}]},
               "objects": [)" +
           objects + "]" + extra + "}";
}

Scene loadOk(const std::string& text, const std::string& base_dir = "") {
    SceneLoadResult r = loadSceneText(text, "test.json", base_dir);
    EXPECT_TRUE(r.errors.empty()) << joined(r.errors);
    EXPECT_TRUE(r.scene.has_value());
    return r.scene ? *r.scene : Scene{};
}

TEST(SceneLoader, EveryBadFileIsRejectedNamingThePlace) {
    const std::vector<test::BadScene> cases = test::readBadSceneManifest(GRIDCULL_SOURCE_DIR);
    ASSERT_GE(cases.size(), 34u);
    for (const test::BadScene& c : cases) {
        const std::string path = sourcePath("tests/scenes/bad/" + c.file);
        ASSERT_TRUE(std::filesystem::exists(path)) << path;
        const SceneLoadResult r = loadSceneFile(path);
        EXPECT_FALSE(r.scene.has_value()) << c.file;
        ASSERT_FALSE(r.errors.empty()) << c.file;
        const std::string all = joined(r.errors);
        EXPECT_NE(all.find(c.expected), std::string::npos)
            << c.file << ": expected a message containing '" << c.expected << "', got\n"
            << all;
        // Every message starts with the file it is about.
        for (const std::string& message : r.errors)
            EXPECT_EQ(message.rfind(path, 0), 0u) << message;
    }
}

TEST(SceneLoader, ManifestCoversEveryBadFile) {
    std::set<std::string> listed;
    for (const test::BadScene& c : test::readBadSceneManifest(GRIDCULL_SOURCE_DIR))
        listed.insert(c.file);
    size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath("tests/scenes/bad"))) {
        if (entry.path().extension() != ".json") continue;
        ++files;
        EXPECT_EQ(listed.count(entry.path().filename().string()), 1u) << entry.path();
    }
    EXPECT_EQ(files, listed.size());
}

TEST(SceneLoader, ReportsEveryProblemInOneFile) {
    const SceneLoadResult r = loadSceneFile(sourcePath("tests/scenes/bad/several-problems.json"));
    const std::string all = joined(r.errors);
    EXPECT_EQ(r.errors.size(), 5u) << all;
    for (const char* place : {"time.frames:", "time.dt:", "camera.fov_deg:", "objects[0].radius:",
                              "objects[1].max[0]:"})
        EXPECT_NE(all.find(place), std::string::npos) << place << "\n" << all;
}

TEST(SceneLoader, ParseErrorsGiveLineAndColumn) {
    SceneLoadResult r = loadSceneText("{\n  \"a\": [1, 2,\n    ]\n}", "x.json", "");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].rfind("x.json:3:5: parse error in a[2]: ", 0), 0u) << r.errors[0];
    r = loadSceneText("{\"format\": 1e400}", "y.json", "");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(
        r.errors[0].rfind("y.json:1:12: parse error in format: number 1e400 is out of range", 0),
        0u)
        << r.errors[0];
}

TEST(SceneLoader, CapsTheNumberOfMessages) {
    std::string objects;
    for (int i = 0; i < 500; ++i)
        objects +=
            std::string(i ? "," : "") + R"({"shape": "sphere", "center": [1, 1, 1], "radius": -1})";
    const SceneLoadResult r = loadSceneText(scene3d(objects), "many.json", "");
    ASSERT_EQ(r.errors.size(), 201u);
    EXPECT_EQ(r.errors.back(), "many.json: 300 more problems not shown");
}

std::vector<std::string> shippedScenes() {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath("scenes")))
        if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

TEST(SceneLoader, EveryShippedSceneLoads) {
    const std::vector<std::string> files = shippedScenes();
    ASSERT_GE(files.size(), 3u);
    bool has_2d = false, has_mesh = false;
    for (const std::string& file : files) {
        const SceneLoadResult r = loadSceneFile(file);
        ASSERT_TRUE(r.scene.has_value()) << file << "\n" << joined(r.errors);
        const Scene& s = *r.scene;
        EXPECT_EQ(s.source_path, file);
        EXPECT_FALSE(s.objects.empty()) << file;
        EXPECT_TRUE(checkResolution(s.dimensions, s.grid.resolution).empty()) << file;
        std::set<int> ids;
        for (const SceneObject& o : s.objects) {
            EXPECT_TRUE(ids.insert(o.id).second) << file << ": id " << o.id;
            EXPECT_EQ(s.indexOf(o.id), int(&o - s.objects.data()));
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_TRUE(std::isfinite(o.bounds.min[axis]) && std::isfinite(o.bounds.max[axis]));
                EXPECT_LE(o.bounds.min[axis], o.bounds.max[axis]);
            }
            if (o.isDynamic()) {
                EXPECT_GE(o.motion.max_speed, 0.0);
            }
            has_mesh = has_mesh || o.shape == ShapeKind::Mesh;
        }
        has_2d = has_2d || s.dimensions == 2;
    }
    EXPECT_TRUE(has_2d);
    EXPECT_TRUE(has_mesh);
}

TEST(SceneLoader, DefaultSceneIsTheFileEmbedded) {
    EXPECT_EQ(std::string(defaultSceneJson()), readText(sourcePath("scenes/default.json")));
    const Scene builtin = defaultScene();
    const SceneLoadResult file = loadSceneFile(sourcePath("scenes/default.json"));
    ASSERT_TRUE(file.scene.has_value());
    ASSERT_EQ(builtin.objects.size(), file.scene->objects.size());
    for (size_t i = 0; i < builtin.objects.size(); ++i) {
        EXPECT_EQ(builtin.objects[i].id, file.scene->objects[i].id);
        EXPECT_EQ(builtin.positionAt(builtin.objects[i].id, 2.5),
                  file.scene->positionAt(builtin.objects[i].id, 2.5));
    }
    // Batagelo & Wu's scene as scenes/default.json describes it.
    EXPECT_EQ(builtin.dimensions, 3);
    EXPECT_EQ(builtin.grid.resolution, glm::ivec3(100, 60, 100));
    EXPECT_EQ(builtin.frames, 150);
    EXPECT_DOUBLE_EQ(builtin.dt, 0.04);
    int dynamic = 0;
    for (const SceneObject& o : builtin.objects) dynamic += o.isDynamic() ? 1 : 0;
    EXPECT_EQ(builtin.objects.size(), 2000u);
    EXPECT_EQ(dynamic, 200);
    EXPECT_EQ(builtin.source_path, "");
}

TEST(SceneLoader, DefaultsFollowTheFormat) {
    const Scene s = loadOk(scene3d(R"({"shape": "sphere", "center": [5, 5, 5], "radius": 1})"));
    EXPECT_EQ(s.frames, 100);
    EXPECT_DOUBLE_EQ(s.dt, 0.04);
    EXPECT_EQ(s.seed, 1u);
    EXPECT_EQ(s.name, "test");
    EXPECT_EQ(s.grid.resolution, defaultResolution(3, s.grid.world));
    EXPECT_DOUBLE_EQ(s.camera.fov_deg, 60.0);
    EXPECT_DOUBLE_EQ(s.camera.near, 0.1);
    EXPECT_DOUBLE_EQ(s.camera.far, 1000.0);
    EXPECT_EQ(s.camera.path[0].up, glm::dvec3(0, 1, 0));
    EXPECT_EQ(s.objects[0].motion.kind, MotionKind::Static);
}

TEST(SceneLoader, DefaultResolutionIsAboutOneVoxelPerUnitAndBounded) {
    EXPECT_EQ(defaultResolution(3, {{0, 0, 0}, {100, 60, 100}}), glm::ivec3(100, 60, 100));
    EXPECT_EQ(defaultResolution(3, {{0, 0, 0}, {1, 1, 0.5}}), glm::ivec3(16, 16, 8));
    EXPECT_EQ(defaultResolution(2, {{0, 0, 0}, {50, 20, 0}}), glm::ivec3(50, 20, 1));
    for (const Aabb& world : {Aabb{{0, 0, 0}, {1e6, 1e6, 1e6}}, Aabb{{-5e6, 0, 0}, {5e6, 1, 1}},
                              Aabb{{0, 0, 0}, {300, 300, 300}}}) {
        const glm::ivec3 r = defaultResolution(3, world);
        EXPECT_TRUE(checkResolution(3, r).empty());
        EXPECT_LE(int64_t(r.x) * r.y * r.z, int64_t(1) << 21);
        EXPECT_LE(std::max({r.x, r.y, r.z}), 256);
        EXPECT_GE(std::min({r.x, r.y, r.z}), 1);
    }
    const glm::ivec3 flat = defaultResolution(2, {{0, 0, 0}, {1e6, 1e6, 0}});
    EXPECT_EQ(flat, glm::ivec3(256, 256, 1));
}

TEST(SceneLoader, MissingIdsAreNumberedAfterTheLargestThenGenerators) {
    const Scene s = loadOk(scene3d(R"(
        {"id": 5, "shape": "sphere", "center": [5, 5, 5], "radius": 1},
        {"shape": "sphere", "center": [6, 5, 5], "radius": 1},
        {"id": 2, "shape": "sphere", "center": [7, 5, 5], "radius": 1},
        {"shape": "box", "min": [1, 1, 1], "max": [2, 2, 2]})",
                                   R"(, "generators": [{"type": "sphere_cluster", "count": 3,
                                        "radius": [1, 1]}])"));
    std::vector<int> ids;
    for (const SceneObject& o : s.objects) ids.push_back(o.id);
    EXPECT_EQ(ids, (std::vector<int>{5, 6, 2, 7, 8, 9, 10}));
    EXPECT_EQ(s.objects[1].center, glm::dvec3(6, 5, 5));
    EXPECT_EQ(s.indexOf(7), 3);
    EXPECT_EQ(s.indexOf(3), -1);

    const Scene none = loadOk(scene3d(R"(
        {"shape": "sphere", "center": [5, 5, 5], "radius": 1},
        {"shape": "sphere", "center": [6, 5, 5], "radius": 1})"));
    EXPECT_EQ(none.objects[0].id, 0);
    EXPECT_EQ(none.objects[1].id, 1);
}

TEST(SceneLoader, TwoDimensionalVectorsAreStoredWithZeroZ) {
    const SceneLoadResult r = loadSceneFile(sourcePath("scenes/walls-2d.json"));
    ASSERT_TRUE(r.scene.has_value()) << joined(r.errors);
    const Scene& s = *r.scene;
    EXPECT_EQ(s.dimensions, 2);
    EXPECT_EQ(s.grid.resolution.z, 1);
    EXPECT_EQ(s.grid.world.min.z, 0.0);
    EXPECT_EQ(s.grid.world.max.z, 0.0);
    for (const CameraKey& k : s.camera.path) {
        EXPECT_EQ(k.position.z, 0.0);
        EXPECT_EQ(k.target.z, 0.0);
    }
    std::set<ShapeKind> shapes;
    std::set<MotionKind> motions;
    for (const SceneObject& o : s.objects) {
        shapes.insert(o.shape);
        motions.insert(o.motion.kind);
        EXPECT_EQ(o.bounds.min.z, 0.0);
        EXPECT_EQ(o.bounds.max.z, 0.0);
        EXPECT_EQ(o.anchor.z, 0.0);
        EXPECT_EQ(o.center.z, 0.0);
        EXPECT_EQ(o.motion.velocity.z, 0.0);
        for (const glm::dvec3& p : o.points) EXPECT_EQ(p.z, 0.0);
        for (const PositionKey& k : o.motion.keys) EXPECT_EQ(k.position.z, 0.0);
        for (const glm::dvec3& v : o.motion.segment_velocities) EXPECT_EQ(v.z, 0.0);
        for (double t = 0.0; t < 10.0; t += 0.37) EXPECT_EQ(s.positionAt(o.id, t).z, 0.0);
    }
    EXPECT_EQ(shapes.size(), 3u);   // circle, box, polygon
    EXPECT_EQ(motions.size(), 4u);  // every motion type
    const SceneObject& circle = s.objects[size_t(s.indexOf(10))];
    EXPECT_EQ(circle.shape, ShapeKind::Sphere);
    EXPECT_EQ(circle.center, glm::dvec3(30, 30, 0));
    EXPECT_EQ(circle.bounds.min, glm::dvec3(27, 27, 0));
    EXPECT_STREQ(shapeName(circle.shape, 2), "circle");
    EXPECT_STREQ(shapeName(circle.shape, 3), "sphere");
}

TEST(SceneLoader, DerivesMaxSpeedOfEveryMotion) {
    const Scene s = loadOk(scene3d(R"(
        {"shape": "sphere", "center": [50, 30, 50], "radius": 1,
         "motion": {"type": "linear", "velocity": [3, 0, 4]}},
        {"shape": "sphere", "center": [50, 30, 50], "radius": 1,
         "motion": {"type": "linear", "velocity": [3, 0, 4], "max_speed": 7}},
        {"shape": "sphere", "center": [50, 30, 50], "radius": 1,
         "motion": {"type": "keyframes", "keys": [{"t": 0, "position": [50, 30, 50]},
                   {"t": 1, "position": [52, 30, 50]}, {"t": 3, "position": [52, 30, 60]}]}},
        {"shape": "sphere", "center": [50, 30, 50], "radius": 1,
         "motion": {"type": "random", "max_speed": 2.5}},
        {"shape": "sphere", "center": [50, 30, 50], "radius": 1,
         "motion": {"type": "linear", "velocity": [3, 0, 4], "max_speed": 5}})"));
    EXPECT_DOUBLE_EQ(s.objects[0].motion.max_speed, 5.0);
    EXPECT_DOUBLE_EQ(s.objects[1].motion.max_speed, 7.0);
    EXPECT_DOUBLE_EQ(s.objects[2].motion.max_speed, 5.0);  // 10 units in 2 s
    EXPECT_DOUBLE_EQ(s.objects[3].motion.max_speed, 2.5);
    EXPECT_DOUBLE_EQ(s.objects[4].motion.max_speed, 5.0);  // declared exactly the real one
}

TEST(SceneLoader, AcceptsExtremesInsideTheLimits) {
    // Objects may stick out of the world or lie wholly outside it (the format
    // says so), and the largest accepted coordinates load.
    const Scene s = loadOk(scene3d(R"(
        {"shape": "sphere", "center": [-9999990, 5, 5], "radius": 5},
        {"shape": "box", "min": [90, 50, 90], "max": [200, 70, 200]})"));
    EXPECT_EQ(s.objects.size(), 2u);
    const SceneLoadResult big = loadSceneText(
        scene3d(R"({"shape": "sphere", "center": [10000001, 5, 5], "radius": 1})"), "big.json", "");
    EXPECT_FALSE(big.scene.has_value());
}

// Truncating a valid file anywhere, or flipping bytes in it, must give
// messages, never an exception or a crash.
TEST(SceneLoader, DamagedFilesNeverThrow) {
    const std::string text = defaultSceneJson();
    for (size_t length = 0; length < text.size(); length += 37) {
        const SceneLoadResult r = loadSceneText(text.substr(0, length), "cut.json", "");
        EXPECT_FALSE(r.scene.has_value()) << length;
        EXPECT_FALSE(r.errors.empty()) << length;
    }
    const std::string walls = readText(sourcePath("scenes/walls-2d.json"));
    uint64_t state = 12345;
    for (int round = 0; round < 300; ++round) {
        std::string damaged = walls;
        for (int k = 0; k < 3; ++k) {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            const size_t at = size_t(state >> 33) % damaged.size();
            const char replacement[] = {'0', '9', '-', '"', '{', ']', ',', 'e', '.', 'x', ' '};
            damaged[at] = replacement[(state >> 20) % sizeof replacement];
        }
        const SceneLoadResult r = loadSceneText(damaged, "damaged.json", "");
        EXPECT_NE(r.scene.has_value(), !r.errors.empty());
    }
}

TEST(SceneLoader, MissingOrDirectoryFileIsAnError) {
    SceneLoadResult r = loadSceneFile(sourcePath("tests/scenes/no-such-scene.json"));
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_NE(r.errors[0].find("cannot open"), std::string::npos);
    r = loadSceneFile(sourcePath("tests/scenes"));
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_NE(r.errors[0].find("directory"), std::string::npos);
}

}  // namespace
}  // namespace gridcull
