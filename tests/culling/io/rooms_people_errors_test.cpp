// The loader's checks of the `rooms` generator's people keys (people,
// people_speed, people_rooms) and of its `ground` (docs/scene-format.md): each
// bad value is rejected with a message naming the key's JSON path and what was
// expected.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"

namespace gridcull {
namespace {

std::string roomsScene(const std::string& extra_keys) {
    return R"({"format": "gridcull-scene/1", "dimensions": 3,
               "world": {"min": [0, 0, 0], "max": [100, 40, 100]},
               "camera": {"path": [{"t": 0, "position": [1, 1, 1], "target": [5, 5, 5]}]},
               "generators": [{"type": "rooms", "rooms": [4, 3], "room_size": 10,
                               "wall_thickness": 0.3, "door_width": 1.5,
                               "chairs_per_room": 0, "chair_speed": 0)" +
           extra_keys + "}]}";
}

std::string errorsOf(const std::string& extra_keys) {
    const SceneLoadResult r = loadSceneText(roomsScene(extra_keys), "people.json", "");
    EXPECT_FALSE(r.scene.has_value()) << extra_keys;
    std::string all;
    for (const std::string& e : r.errors) all += e + "\n";
    return all;
}

void expectError(const std::string& extra_keys, const std::string& message) {
    const std::string all = errorsOf(extra_keys);
    EXPECT_NE(all.find(message), std::string::npos)
        << extra_keys << "\nexpected: " << message << "\ngot: " << all;
}

TEST(RoomsPeopleErrors, GoodKeysLoad) {
    const SceneLoadResult r = loadSceneText(
        roomsScene(R"(, "people": 3, "people_speed": 1.4, "people_rooms": [0, 0, 3, 2])"),
        "people.json", "");
    ASSERT_TRUE(r.errors.empty()) << r.errors[0];
    EXPECT_EQ(r.scene->objects.size(), size_t(4 * 3 * 5 + 3));
}

TEST(RoomsPeopleErrors, BadValuesNameTheKeyAndWhatWasExpected) {
    expectError(R"(, "people": -1)",
                "people.json: generators[0].people: must be an integer in [0, 1000000], got -1");
    expectError(R"(, "people": 2.5)", "generators[0].people: must be an integer in [0, 1000000]");
    expectError(R"(, "people": 3)",
                "generators[0].people_speed: must be given when people > 0: a finite number >= "
                "0 (0: they stand still), got nothing (the key is missing)");
    expectError(R"(, "people": 3, "people_speed": "fast")",
                "generators[0].people_speed: must be a finite number >= 0");
    expectError(R"(, "people_speed": -2)",
                "generators[0].people_speed: must be a finite number >= 0, got -2");
    expectError(R"(, "people": 3, "people_speed": 1, "people_rooms": [0, 0, 3])",
                "generators[0].people_rooms: must be 4 integers in [0, 199]");
    expectError(R"(, "people": 3, "people_speed": 1, "people_rooms": [0, -1, 3, 2])",
                "generators[0].people_rooms[1]: must be integers in [0, 199]");
    expectError(R"(, "people": 3, "people_speed": 1, "people_rooms": [2, 0, 1, 2])",
                "generators[0].people_rooms[2]: must be at least people_rooms[0] = 2, got 1");
    expectError(R"(, "people": 3, "people_speed": 1, "people_rooms": [0, 0, 3, 3])",
                "generators[0].people_rooms[3]: must be a room of the building, less than "
                "rooms[1] = 3, got 3");
    expectError(R"(, "people": 3, "people_speed": 1, "people_room": [0, 0, 1, 1])",
                "generators[0].people_room:");
    expectError(R"(, "ground": 40)",
                "generators[0].ground: must be a number in [world.min[1], world.max[1]) = [0, "
                "40) (the floor's y, 3D only), got 40");
    expectError(R"(, "ground": -1)", "generators[0].ground: must be a number in [world.min[1]");
    expectError(R"(, "ceiling": 2)",
                "generators[0].ceiling: must be 0 or 1 (1: a ceiling over the building), got 2");
    expectError(R"(, "ceiling": true)", "generators[0].ceiling: must be 0 or 1");
}

TEST(RoomsPeopleErrors, GroundIsThreeDimensionalOnly) {
    const std::string text = R"({"format": "gridcull-scene/1", "dimensions": 2,
        "world": {"min": [0, 0], "max": [100, 100]},
        "camera": {"path": [{"t": 0, "position": [1, 1], "target": [5, 5]}]},
        "generators": [{"type": "rooms", "rooms": [2, 2], "room_size": 10,
                        "wall_thickness": 0.3, "door_width": 1.5, "chairs_per_room": 0,
                        "chair_speed": 0, "ground": 1}]})";
    const SceneLoadResult r = loadSceneText(text, "flat.json", "");
    ASSERT_FALSE(r.scene.has_value());
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0],
              "flat.json: generators[0].ground: does not exist in a 2D scene (the "
              "floor's y, 3D only)");
}

TEST(RoomsPeopleErrors, CeilingIsThreeDimensionalOnly) {
    const std::string text = R"({"format": "gridcull-scene/1", "dimensions": 2,
        "world": {"min": [0, 0], "max": [100, 100]},
        "camera": {"path": [{"t": 0, "position": [1, 1], "target": [5, 5]}]},
        "generators": [{"type": "rooms", "rooms": [2, 2], "room_size": 10,
                        "wall_thickness": 0.3, "door_width": 1.5, "chairs_per_room": 0,
                        "chair_speed": 0, "ceiling": 1}]})";
    const SceneLoadResult r = loadSceneText(text, "flat.json", "");
    ASSERT_FALSE(r.scene.has_value());
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0],
              "flat.json: generators[0].ceiling: does not exist in a 2D scene (a ceiling over "
              "the building, 3D only)");
}

TEST(RoomsPeopleErrors, DoorMustBeWiderThanAPerson) {
    const std::string text = R"({"format": "gridcull-scene/1", "dimensions": 3,
        "world": {"min": [0, 0, 0], "max": [100, 40, 100]},
        "camera": {"path": [{"t": 0, "position": [1, 1, 1], "target": [5, 5, 5]}]},
        "generators": [{"type": "rooms", "rooms": [2, 2], "room_size": 10,
                        "wall_thickness": 0.3, "door_width": 0.5, "chairs_per_room": 0,
                        "chair_speed": 0, "people": 1, "people_speed": 1}]})";
    const SceneLoadResult r = loadSceneText(text, "door.json", "");
    ASSERT_FALSE(r.scene.has_value());
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0],
              "door.json: generators[0].door_width: must be wider than a person (0.05 * "
              "room_size = 0.5) when people > 0, got 0.5");
}

}  // namespace
}  // namespace gridcull
