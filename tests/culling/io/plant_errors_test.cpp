// The loader's checks of the `plant` generator (docs/scene-format.md,
// "gridcull's additions"): each bad value is rejected with a message naming the
// key's JSON path and what was expected, and the site must fit the world.
#include <string>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"

namespace gridcull {
namespace {

// A good plant with `key` set to `value` ("" removes nothing, a value of
// "REMOVE" drops the key).
std::string plantScene(const std::string& key, const std::string& value, int dimensions = 3) {
    std::string keys[][2] = {{"units", "[3, 2]"},          {"unit_size", "20"},
                             {"aisle_width", "4"},         {"tank_height", "[6, 18]"},
                             {"tanks_per_unit", "5"},      {"pipes_per_unit", "12"},
                             {"pipe_width", "[0.1, 0.3]"}, {"valves_per_pipe", "2"},
                             {"platforms_per_unit", "2"},  {"rack_pipes", "3"}};
    std::string g = R"({"type": "plant")";
    bool replaced = false;
    for (auto& kv : keys) {
        if (kv[0] == key) {
            replaced = true;
            if (value == "REMOVE") continue;
            kv[1] = value;
        }
        g += ", \"" + kv[0] + "\": " + kv[1];
    }
    if (!replaced && !key.empty()) g += ", \"" + key + "\": " + value;
    g += "}";
    const std::string world = dimensions == 3 ? R"({"min": [0, 0, 0], "max": [100, 20, 80]})"
                                              : R"({"min": [0, 0], "max": [100, 80]})";
    const std::string eye = dimensions == 3 ? "[1, 1, 1]" : "[1, 1]";
    const std::string target = dimensions == 3 ? "[5, 1, 5]" : "[5, 5]";
    return R"({"format": "gridcull-scene/1", "dimensions": )" + std::to_string(dimensions) +
           R"(, "world": )" + world + R"(, "camera": {"path": [{"t": 0, "position": )" + eye +
           R"(, "target": )" + target + R"(}]}, "generators": [)" + g + "]}";
}

std::string errorsOf(const std::string& text) {
    const SceneLoadResult r = loadSceneText(text, "plant.json", "");
    EXPECT_FALSE(r.scene.has_value()) << text;
    std::string all;
    for (const std::string& e : r.errors) all += e + "\n";
    return all;
}

void expectError(const std::string& key, const std::string& value, const std::string& message) {
    const std::string all = errorsOf(plantScene(key, value));
    EXPECT_NE(all.find(message), std::string::npos)
        << key << " = " << value << "\nexpected: " << message << "\ngot: " << all;
}

TEST(PlantErrors, GoodKeysLoad) {
    const SceneLoadResult r = loadSceneText(plantScene("", ""), "plant.json", "");
    ASSERT_TRUE(r.errors.empty()) << r.errors[0];
    EXPECT_EQ(r.scene->objects.size(), size_t(6 * (5 + 12 * 3 + 2 * 5) + 3 * 3));
}

TEST(PlantErrors, BadValuesNameTheKeyAndWhatWasExpected) {
    expectError("units", "[0, 2]",
                "plant.json: generators[0].units[0]: must be integers in [1, 100]");
    expectError("units", "[3]", "generators[0].units: must be 2 integers in [1, 100]");
    expectError("unit_size", "-1", "generators[0].unit_size: must be a finite number > 0, got -1");
    expectError("aisle_width", "-0.5",
                "generators[0].aisle_width: must be a finite number >= 0, got -0.5");
    expectError("tank_height", "[18, 6]", "generators[0].tank_height");
    expectError("tank_height", "[0, 6]", "generators[0].tank_height");
    expectError("pipe_width", "\"thin\"", "generators[0].pipe_width");
    expectError("tanks_per_unit", "65",
                "generators[0].tanks_per_unit: must be an integer in [0, 64], got 65");
    expectError("pipes_per_unit", "1.5",
                "generators[0].pipes_per_unit: must be an integer in [0, 1000]");
    expectError("valves_per_pipe", "-1",
                "generators[0].valves_per_pipe: must be an integer in [0, 16], got -1");
    expectError("platforms_per_unit", "17",
                "generators[0].platforms_per_unit: must be an integer in [0, 16], got 17");
    expectError("rack_pipes", "65",
                "generators[0].rack_pipes: must be an integer in [0, 64], got 65");
    expectError("rack_pipes", "REMOVE", "generators[0].rack_pipes");
    expectError("unit_size", "REMOVE", "generators[0].unit_size");
    expectError("chimneys", "3", "generators[0].chimneys:");
}

TEST(PlantErrors, TheSiteMustFitTheWorld) {
    // 3 * (20 + 4) + 4 = 76 fits 100 along x; 4 rows make 100 along z, more than 80.
    expectError("units", "[3, 4]",
                "plant.json: generators[0].units[1]: make the site 100 wide along z, more than "
                "the world's 80 (units * (unit_size + aisle_width) + aisle_width must fit the "
                "world)");
    expectError("aisle_width", "20", "generators[0].units[0]: make the site 140 wide along x");
    expectError("tank_height", "[6, 21]",
                "plant.json: generators[0].tank_height[1]: must be at most the world's height "
                "20, got 21");
    expectError("pipe_width", "[0.1, 0.4]",
                "plant.json: generators[0].pipe_width[1]: must be less than min(unit_size, "
                "tank_height[0]) / 15 = 0.4 (pipes and valves must fit a unit), got 0.4");
}

TEST(PlantErrors, PlantIsThreeDimensionalOnly) {
    const std::string all = errorsOf(plantScene("", "", 2));
    EXPECT_NE(all.find("plant.json: generators[0].type: generator 'plant' does not exist in a 2D "
                       "scene; must be sphere_cluster or rooms, got \"plant\""),
              std::string::npos)
        << all;
}

TEST(PlantErrors, TooManyObjectsAreRefusedBeforeAnythingIsMade) {
    // 100 x 100 units of 1000 pipes with 16 valves: 1.7e8 objects.
    std::string text = plantScene("units", "[100, 100]");
    for (const auto& kv :
         {std::pair<std::string, std::string>{"\"unit_size\": 20", "\"unit_size\": 0.5"},
          {"\"aisle_width\": 4", "\"aisle_width\": 0"},
          {"\"tank_height\": [6, 18]", "\"tank_height\": [6, 6]"},
          {"\"pipe_width\": [0.1, 0.3]", "\"pipe_width\": [0.01, 0.01]"},
          {"\"pipes_per_unit\": 12", "\"pipes_per_unit\": 1000"},
          {"\"valves_per_pipe\": 2", "\"valves_per_pipe\": 16"}})
        text.replace(text.find(kv.first), kv.first.size(), kv.second);
    const std::string all = errorsOf(text);
    EXPECT_NE(all.find("plant.json: generators: would make the scene 170150594 objects, more than "
                       "the limit of 1000000"),
              std::string::npos)
        << all;
}

}  // namespace
}  // namespace gridcull
