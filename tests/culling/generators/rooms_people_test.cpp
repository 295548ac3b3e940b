// The `rooms` generator's people (scene_generators.h, "rooms"; the paper's Fig.
// 13a building with moving men): counts and sizes, paths that never cross a wall
// or a table (every keyframe segment stays inside one room's walkable floor or
// crosses a door gap), people_rooms keeps them in their block, and the same seed
// gives the same paths while adding people changes no other object; `ground`
// puts the building on another floor than world.min.y.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/generators/scene_generators.h"
#include "culling/io/scene_loader.h"

namespace gridcull {
namespace {

// World [0, 100] x [0, 40] x [0, 100] (3D) or [0, 100]^2 (2D); `frames` of 0.04 s.
Scene loadRooms(int dimensions, const std::string& rooms_keys, uint64_t seed = 3,
                int frames = 500) {
    const std::string world = dimensions == 3 ? R"({"min": [0, 0, 0], "max": [100, 40, 100]})"
                                              : R"({"min": [0, 0], "max": [100, 100]})";
    const std::string eye = dimensions == 3 ? "[1, 1, 1]" : "[1, 1]";
    const std::string text =
        R"({"format": "gridcull-scene/1", "dimensions": )" + std::to_string(dimensions) +
        R"(, "world": )" + world + R"(, "seed": )" + std::to_string(seed) +
        R"(, "time": {"frames": )" + std::to_string(frames) +
        R"(, "dt": 0.04}, "camera": {"path": [{"t": 0, "position": )" + eye + R"(, "target": )" +
        eye + R"(}]}, "generators": [{"type": "rooms", )" + rooms_keys + "}]}";
    SceneLoadResult r = loadSceneText(text, "people.json", "");
    EXPECT_TRUE(r.errors.empty()) << (r.errors.empty() ? "" : r.errors[0]);
    return r.scene ? *r.scene : Scene{};
}

const char* kBuilding =
    R"("rooms": [4, 3], "room_size": 10, "wall_thickness": 0.3, "door_width": 1.5,
       "chairs_per_room": 2, "chair_speed": 1)";

// The building of kBuilding spans [30, 70] x [35, 65] on the floor plan.
constexpr double kA0 = 30.0, kB0 = 35.0, kSize = 10.0, kWall = 0.3, kDoor = 1.5;
constexpr int kRoomsA = 4, kRoomsB = 3;

std::vector<const SceneObject*> people(const Scene& s, size_t count) {
    std::vector<const SceneObject*> out;
    for (size_t i = s.objects.size() - count; i < s.objects.size(); ++i)
        out.push_back(&s.objects[i]);
    return out;
}

// The floor-plan box (a, b) a person's box sweeps between two keys: the hull of
// its boxes at both ends (exact for the axis-aligned segments the generator makes).
struct Flat {
    double a0, a1, b0, b1;
};

Flat sweep(const SceneObject& o, const PositionKey& k0, const PositionKey& k1, int b) {
    const glm::dvec3 half = (o.bounds.max - o.bounds.min) * 0.5;
    return {std::min(k0.position.x, k1.position.x) - half.x,
            std::max(k0.position.x, k1.position.x) + half.x,
            std::min(k0.position[b], k1.position[b]) - half[b],
            std::max(k0.position[b], k1.position[b]) + half[b]};
}

// Inside room (i, j) between its walls' inner faces.
bool insideRoom(const Flat& f, int i, int j) {
    const double a_lo = kA0 + i * kSize + kWall / 2, a_hi = kA0 + (i + 1) * kSize - kWall / 2;
    const double b_lo = kB0 + j * kSize + kWall / 2, b_hi = kB0 + (j + 1) * kSize - kWall / 2;
    return f.a0 >= a_lo && f.a1 <= a_hi && f.b0 >= b_lo && f.b1 <= b_hi;
}

// Inside rooms (i, j) and its neighbour across one wall, crossing it within the
// door gap: within both rooms' span, and inside the gap across the wall.
bool throughDoor(const Flat& f, int i, int j, int di, int dj) {
    const double lo_a = kA0 + std::min(i, i + di) * kSize + kWall / 2;
    const double hi_a = kA0 + (std::max(i, i + di) + 1) * kSize - kWall / 2;
    const double lo_b = kB0 + std::min(j, j + dj) * kSize + kWall / 2;
    const double hi_b = kB0 + (std::max(j, j + dj) + 1) * kSize - kWall / 2;
    if (!(f.a0 >= lo_a && f.a1 <= hi_a && f.b0 >= lo_b && f.b1 <= hi_b)) return false;
    if (di != 0) {  // the wall runs along b; its gap is centred on the row's middle
        const double mid = kB0 + (j + 0.5) * kSize;
        return f.b0 >= mid - kDoor / 2 && f.b1 <= mid + kDoor / 2;
    }
    const double mid = kA0 + (i + 0.5) * kSize;
    return f.a0 >= mid - kDoor / 2 && f.a1 <= mid + kDoor / 2;
}

bool overlaps(const Flat& f, const Aabb& box, int b) {
    return f.a0 < box.max.x && box.min.x < f.a1 && f.b0 < box.max[b] && box.min[b] < f.b1;
}

int roomA(double a) {
    return int(std::floor((a - kA0) / kSize));
}
int roomB(double b) {
    return int(std::floor((b - kB0) / kSize));
}

TEST(RoomsPeople, CountsSizesAndSpeed) {
    const Scene s = loadRooms(3, std::string(kBuilding) + R"(, "people": 25, "people_speed": 1.4)");
    ASSERT_EQ(s.objects.size(), size_t(kRoomsA * kRoomsB * (5 + 2) + 25));
    for (const SceneObject* o : people(s, 25)) {
        EXPECT_EQ(o->shape, ShapeKind::Box);
        EXPECT_EQ(o->motion.kind, MotionKind::Keyframes);
        EXPECT_NEAR(o->box.max.x - o->box.min.x, 0.5, 1e-12);
        EXPECT_NEAR(o->box.max.z - o->box.min.z, 0.5, 1e-12);
        EXPECT_NEAR(o->box.max.y - o->box.min.y, 1.8, 1e-12);
        EXPECT_EQ(o->box.min.y, 0.0);  // on the floor, below the 3-high walls
        EXPECT_NEAR(o->motion.max_speed, 1.4, 1e-9);
        ASSERT_GE(o->motion.keys.size(), 2u);
        // Keys cover the run: the last one at or after its end.
        EXPECT_GE(o->motion.keys.back().t, s.frames * s.dt - 1e-9);
    }
    // With people_speed 0 the people stand still.
    const Scene still =
        loadRooms(3, std::string(kBuilding) + R"(, "people": 4, "people_speed": 0)");
    ASSERT_EQ(still.objects.size(), size_t(kRoomsA * kRoomsB * 7 + 4));
    for (const SceneObject* o : people(still, 4)) EXPECT_FALSE(o->isDynamic());
}

TEST(RoomsPeople, EverySegmentStaysInARoomOrPassesThroughADoor) {
    for (int dimensions : {3, 2}) {
        const int b = dimensions == 3 ? 2 : 1;
        const Scene s = loadRooms(
            dimensions, std::string(kBuilding) + R"(, "people": 40, "people_speed": 1.4)");
        ASSERT_EQ(s.objects.size(), size_t(kRoomsA * kRoomsB * 7 + 40)) << dimensions;
        // Walls and tables: the static boxes.
        std::vector<Aabb> obstacles;
        for (const SceneObject& o : s.objects)
            if (!o.isDynamic()) obstacles.push_back(o.box);
        ASSERT_EQ(obstacles.size(), size_t(kRoomsA * kRoomsB * 5));
        int doors_crossed = 0, segments = 0;
        for (const SceneObject* o : people(s, 40)) {
            const std::vector<PositionKey>& keys = o->motion.keys;
            for (size_t k = 0; k + 1 < keys.size(); ++k) {
                ++segments;
                const Flat f = sweep(*o, keys[k], keys[k + 1], b);
                for (const Aabb& wall : obstacles)
                    ASSERT_FALSE(overlaps(f, wall, b))
                        << dimensions << "D person " << o->id << " key " << k << " crosses a wall";
                const int i = roomA(keys[k].position.x), j = roomB(keys[k].position[b]);
                const int i1 = roomA(keys[k + 1].position.x), j1 = roomB(keys[k + 1].position[b]);
                if (i == i1 && j == j1) {
                    EXPECT_TRUE(insideRoom(f, i, j)) << o->id << " key " << k;
                } else {
                    ++doors_crossed;
                    ASSERT_EQ(std::abs(i1 - i) + std::abs(j1 - j), 1) << o->id << " key " << k;
                    EXPECT_TRUE(throughDoor(f, i, j, i1 - i, j1 - j)) << o->id << " key " << k;
                }
            }
        }
        // 20 s of walking: people do go from room to room.
        EXPECT_GT(doors_crossed, 40) << dimensions;
        EXPECT_GT(segments, 200) << dimensions;
    }
}

TEST(RoomsPeople, PeopleRoomsKeepsThemInTheirBlock) {
    const Scene s =
        loadRooms(3, std::string(kBuilding) +
                         R"(, "people": 30, "people_speed": 2, "people_rooms": [2, 1, 3, 2])");
    std::vector<int> visited(kRoomsA * kRoomsB, 0);
    for (const SceneObject* o : people(s, 30)) {
        for (const PositionKey& key : o->motion.keys) {
            const int i = roomA(key.position.x), j = roomB(key.position.z);
            ASSERT_GE(i, 2);
            ASSERT_LE(i, 3);
            ASSERT_GE(j, 1);
            ASSERT_LE(j, 2);
            ++visited[size_t(j * kRoomsA + i)];
        }
    }
    // Every room of the block is walked through.
    for (int j = 1; j <= 2; ++j)
        for (int i = 2; i <= 3; ++i) EXPECT_GT(visited[size_t(j * kRoomsA + i)], 0) << i << j;
    // A block of one room: the people circle its walkway, in the room.
    const Scene one =
        loadRooms(3, std::string(kBuilding) +
                         R"(, "people": 5, "people_speed": 2, "people_rooms": [1, 1, 1, 1])");
    for (const SceneObject* o : people(one, 5)) {
        EXPECT_GT(o->motion.keys.size(), 4u);
        for (size_t k = 0; k + 1 < o->motion.keys.size(); ++k)
            EXPECT_TRUE(insideRoom(sweep(*o, o->motion.keys[k], o->motion.keys[k + 1], 2), 1, 1));
    }
}

TEST(RoomsPeople, DeterministicAndIndependentOfTheOtherObjects) {
    const std::string with = std::string(kBuilding) + R"(, "people": 12, "people_speed": 1.4)";
    const Scene a = loadRooms(3, with, 7), b = loadRooms(3, with, 7), c = loadRooms(3, with, 8);
    const Scene none = loadRooms(3, kBuilding, 7);
    ASSERT_EQ(a.objects.size(), b.objects.size());
    ASSERT_EQ(a.objects.size(), none.objects.size() + 12);
    bool differ = false;
    for (size_t i = 0; i < a.objects.size(); ++i) {
        const SceneObject& x = a.objects[i];
        const SceneObject& y = b.objects[i];
        EXPECT_EQ(x.box.min, y.box.min);
        ASSERT_EQ(x.motion.keys.size(), y.motion.keys.size());
        for (size_t k = 0; k < x.motion.keys.size(); ++k) {
            EXPECT_EQ(x.motion.keys[k].t, y.motion.keys[k].t);
            EXPECT_EQ(x.motion.keys[k].position, y.motion.keys[k].position);
        }
        if (i >= none.objects.size()) {
            differ = differ || x.box.min != c.objects[i].box.min;
            continue;
        }
        // Adding people leaves the walls, tables and chairs as they were.
        const SceneObject& z = none.objects[i];
        EXPECT_EQ(x.box.min, z.box.min);
        ASSERT_EQ(x.motion.keys.size(), z.motion.keys.size());
        for (size_t k = 0; k < x.motion.keys.size(); ++k)
            EXPECT_EQ(x.motion.keys[k].position, z.motion.keys[k].position);
    }
    EXPECT_TRUE(differ);
}

TEST(RoomsPeople, GroundLiftsTheBuildingAndItsPeople) {
    // A world reaching 20 below the floor at y = 0 (ground), so that whatever
    // reaches below the floor stays in the world.
    const std::string text = R"({"format": "gridcull-scene/1", "dimensions": 3,
        "world": {"min": [0, -20, 0], "max": [100, 20, 100]}, "time": {"frames": 50},
        "camera": {"path": [{"t": 0, "position": [1, 1, 1], "target": [5, 1, 5]}]},
        "generators": [{"type": "rooms", "rooms": [2, 2], "room_size": 10,
            "wall_thickness": 0.3, "door_width": 1.5, "chairs_per_room": 1, "chair_speed": 1,
            "people": 3, "people_speed": 1, "ground": 0}]})";
    const SceneLoadResult r = loadSceneText(text, "ground.json", "");
    ASSERT_TRUE(r.errors.empty()) << r.errors[0];
    for (const SceneObject& o : r.scene->objects) {
        EXPECT_EQ(o.bounds.min.y, 0.0);
        for (const PositionKey& k : o.motion.keys) EXPECT_EQ(k.position.y - (o.anchor.y), 0.0);
    }
    // Without it, on world.min.y.
    const Scene low = loadRooms(3, std::string(kBuilding) + R"(, "people": 2, "people_speed": 1)");
    for (const SceneObject& o : low.objects) EXPECT_EQ(o.bounds.min.y, low.grid.world.min.y);
}

// `ceiling`: one slab over the whole building on the walls' tops, made right
// after the walls; every other object is the same as without it.
TEST(RoomsPeople, CeilingCoversTheBuildingOnTheWallsTops) {
    const std::string keys = std::string(kBuilding) + R"(, "people": 2, "people_speed": 1)";
    const Scene open = loadRooms(3, keys);
    const Scene closed = loadRooms(3, keys + R"(, "ceiling": 1)");
    ASSERT_EQ(closed.objects.size(), open.objects.size() + 1);
    Aabb walls_and_tables{glm::dvec3(1e300), glm::dvec3(-1e300)};
    double wall_top = -1e300;
    for (const SceneObject& o : open.objects)
        if (!o.isDynamic()) {
            walls_and_tables.merge(o.bounds);
            wall_top = std::max(wall_top, o.bounds.max.y);
        }
    // The slab: the first object after the walls (tables come after it).
    const SceneObject* slab = nullptr;
    for (const SceneObject& o : closed.objects)
        if (!o.isDynamic() && o.bounds.min.y == wall_top) slab = &o;
    ASSERT_NE(slab, nullptr);
    EXPECT_GT(slab->bounds.max.y, wall_top);
    for (const int axis : {0, 2}) {
        EXPECT_LE(slab->bounds.min[axis], walls_and_tables.min[axis]);
        EXPECT_GE(slab->bounds.max[axis], walls_and_tables.max[axis]);
    }
    // Everything else unchanged, in the same order.
    size_t k = 0;
    for (const SceneObject& o : closed.objects) {
        if (&o == slab) continue;
        EXPECT_EQ(o.bounds.min, open.objects[k].bounds.min);
        EXPECT_EQ(o.bounds.max, open.objects[k].bounds.max);
        EXPECT_EQ(o.motion.keys.size(), open.objects[k].motion.keys.size());
        ++k;
    }
}

}  // namespace
}  // namespace gridcull
