// Generators (scene-format.md, "Generators"; layouts in culling/generators/scene_generators.h):
// counts, placement, motion, determinism, and ids after the listed objects.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "culling/io/scene_loader.h"

namespace gridcull {
namespace {

std::string sourcePath(const std::string& relative) {
    return std::string(GRIDCULL_SOURCE_DIR) + "/" + relative;
}

Scene load(int dimensions, const std::string& generators, const std::string& objects = "",
           uint64_t seed = 1, const std::string& base_dir = "") {
    const std::string world = dimensions == 3 ? R"({"min": [0, 0, 0], "max": [100, 40, 100]})"
                                              : R"({"min": [0, 0], "max": [100, 100]})";
    const std::string eye = dimensions == 3 ? "[1, 1, 1]" : "[1, 1]";
    const std::string text =
        R"({"format": "gridcull-scene/1", "dimensions": )" + std::to_string(dimensions) +
        R"(, "world": )" + world + R"(, "seed": )" + std::to_string(seed) +
        R"(, "camera": {"path": [{"t": 0, "position": )" + eye + R"(, "target": )" + eye +
        R"(}]}, "objects": [)" + objects + R"(], "generators": [)" + generators + "]}";
    SceneLoadResult r = loadSceneText(text, "gen.json", base_dir);
    EXPECT_TRUE(r.errors.empty()) << (r.errors.empty() ? "" : r.errors[0]);
    return r.scene ? *r.scene : Scene{};
}

bool within(const Aabb& inner, const Aabb& outer, int dimensions) {
    for (int axis = 0; axis < dimensions; ++axis)
        if (inner.min[axis] < outer.min[axis] || inner.max[axis] > outer.max[axis]) return false;
    return true;
}

bool overlap(const Aabb& a, const Aabb& b, int dimensions) {
    for (int axis = 0; axis < dimensions; ++axis)
        if (a.max[axis] <= b.min[axis] || b.max[axis] <= a.min[axis]) return false;
    return true;
}

TEST(SceneGenerators, SphereClusterCountsRadiiRegionAndMotion) {
    const Scene s = load(3, R"({"type": "sphere_cluster", "count": 400, "radius": [0.5, 1.5],
        "dynamic_fraction": 0.25, "max_speed": 4,
        "region": {"min": [10, 0, 10], "max": [40, 20, 40]}})");
    ASSERT_EQ(s.objects.size(), 400u);
    int dynamic = 0, linear = 0, random = 0;
    const Aabb region{{10, 0, 10}, {40, 20, 40}};
    for (const SceneObject& o : s.objects) {
        EXPECT_EQ(o.shape, ShapeKind::Sphere);
        EXPECT_GE(o.radius, 0.5);
        EXPECT_LE(o.radius, 1.5);
        EXPECT_TRUE(within(o.bounds, region, 3));
        if (!o.isDynamic()) continue;
        ++dynamic;
        EXPECT_LE(o.motion.max_speed, 4.0 + 1e-12);
        if (o.motion.kind == MotionKind::Linear) {
            ++linear;
            EXPECT_GE(glm::length(o.motion.velocity), 1.0 - 1e-12);
            EXPECT_DOUBLE_EQ(o.motion.max_speed, glm::length(o.motion.velocity));
        } else {
            ASSERT_EQ(o.motion.kind, MotionKind::Random);
            ++random;
            EXPECT_DOUBLE_EQ(o.motion.max_speed, 4.0);
            EXPECT_FALSE(o.motion.segment_velocities.empty());
        }
    }
    EXPECT_EQ(dynamic, 100);
    EXPECT_GT(linear, 20);
    EXPECT_GT(random, 20);
}

TEST(SceneGenerators, SphereClusterIn2DMakesCirclesInThePlane) {
    const Scene s = load(2, R"({"type": "sphere_cluster", "count": 50, "radius": [1, 2],
        "dynamic_fraction": 1, "max_speed": 2, "motion": "linear"})");
    ASSERT_EQ(s.objects.size(), 50u);
    for (const SceneObject& o : s.objects) {
        EXPECT_EQ(o.center.z, 0.0);
        EXPECT_EQ(o.motion.kind, MotionKind::Linear);
        EXPECT_EQ(o.motion.velocity.z, 0.0);
        EXPECT_TRUE(within(o.bounds, s.grid.world, 2));
    }
}

TEST(SceneGenerators, SameSeedSameSceneOtherSeedOtherScene) {
    const std::string g = R"({"type": "sphere_cluster", "count": 30, "radius": [1, 2],
        "dynamic_fraction": 0.5, "max_speed": 2})";
    const Scene a = load(3, g, "", 5), b = load(3, g, "", 5), c = load(3, g, "", 6);
    ASSERT_EQ(a.objects.size(), b.objects.size());
    bool differ = false;
    for (size_t i = 0; i < a.objects.size(); ++i) {
        EXPECT_EQ(a.objects[i].center, b.objects[i].center);
        EXPECT_EQ(a.objects[i].radius, b.objects[i].radius);
        EXPECT_EQ(a.positionAt(a.objects[i].id, 3.3), b.positionAt(b.objects[i].id, 3.3));
        differ = differ || a.objects[i].center != c.objects[i].center;
    }
    EXPECT_TRUE(differ);
}

TEST(SceneGenerators, GeneratedIdsComeAfterListedOnes) {
    const Scene s = load(3, R"({"type": "sphere_cluster", "count": 3, "radius": [1, 1]},
                               {"type": "sphere_cluster", "count": 2, "radius": [1, 1]})",
                         R"({"id": 10, "shape": "sphere", "center": [5, 5, 5], "radius": 1},
                            {"shape": "sphere", "center": [9, 5, 5], "radius": 1},
                            {"id": 3, "shape": "sphere", "center": [7, 5, 5], "radius": 1})");
    std::vector<int> ids;
    for (const SceneObject& o : s.objects) ids.push_back(o.id);
    EXPECT_EQ(ids, (std::vector<int>{10, 11, 3, 12, 13, 14, 15, 16}));
}

TEST(SceneGenerators, CityIsAStreetGridOfBuildings) {
    const Scene s = load(3, R"({"type": "city", "blocks": [4, 3], "block_size": 10,
        "street_width": 5, "height": [5, 30]})");
    ASSERT_EQ(s.objects.size(), 12u);
    for (size_t i = 0; i < s.objects.size(); ++i) {
        const SceneObject& o = s.objects[i];
        EXPECT_EQ(o.shape, ShapeKind::Box);
        EXPECT_EQ(o.box.min.y, 0.0);
        const double height = o.box.max.y - o.box.min.y;
        EXPECT_GE(height, 5.0);
        EXPECT_LE(height, 30.0);
        EXPECT_DOUBLE_EQ(o.box.max.x - o.box.min.x, 10.0);
        for (size_t j = 0; j < i; ++j) EXPECT_FALSE(overlap(o.box, s.objects[j].box, 3));
    }
    // Centred on the world: 4 blocks of 10 and 5 streets of 5 span 65 in x.
    EXPECT_DOUBLE_EQ(s.objects[0].box.min.x, 50.0 - 32.5 + 5.0);
}

TEST(SceneGenerators, ForestTreesAreTrunkAndCrown) {
    const Scene s = load(3, R"({"type": "forest", "count": 25, "trunk_radius": 0.3,
        "crown_radius": 2, "height": [6, 10]})");
    ASSERT_EQ(s.objects.size(), 50u);
    for (size_t i = 0; i < s.objects.size(); i += 2) {
        const SceneObject& trunk = s.objects[i];
        const SceneObject& crown = s.objects[i + 1];
        ASSERT_EQ(trunk.shape, ShapeKind::Box);
        ASSERT_EQ(crown.shape, ShapeKind::Sphere);
        EXPECT_EQ(trunk.box.min.y, 0.0);
        EXPECT_EQ(crown.center.y, trunk.box.max.y);
        EXPECT_EQ(crown.center.x, trunk.box.center().x);
        const double height = crown.center.y + crown.radius;
        EXPECT_GE(height, 6.0 - 1e-12);
        EXPECT_LE(height, 10.0 + 1e-12);
        EXPECT_TRUE(within(crown.bounds, s.grid.world, 3));
    }
}

TEST(SceneGenerators, RoomsHaveDoorsTablesAndChairsThatStayInTheirRoom) {
    for (int dimensions : {2, 3}) {
        const Scene s = load(dimensions, R"({"type": "rooms", "rooms": [3, 2], "room_size": 10,
            "wall_thickness": 0.4, "door_width": 2, "chairs_per_room": 3, "chair_speed": 2})");
        ASSERT_EQ(s.objects.size(), 6u * (5 + 3)) << dimensions;
        const int a = 0, b = dimensions == 3 ? 2 : 1;
        // The building is centred: rooms span [35, 65] x [40, 60] on the floor plan.
        int chairs = 0;
        for (const SceneObject& o : s.objects) {
            if (o.motion.kind != MotionKind::Keyframes) continue;
            ++chairs;
            EXPECT_NEAR(o.motion.max_speed, 2.0, 1e-9);
            const glm::dvec3 start = o.anchor;
            const int room_a = int((start[a] - 35.0) / 10.0);
            const int room_b = int((start[b] - 40.0) / 10.0);
            const Aabb room_inside = [&] {
                Aabb r{glm::dvec3(0.0), glm::dvec3(0.0)};
                r.min[a] = 35.0 + room_a * 10.0 + 0.2;
                r.max[a] = r.min[a] + 10.0 - 0.4;
                r.min[b] = 40.0 + room_b * 10.0 + 0.2;
                r.max[b] = r.min[b] + 10.0 - 0.4;
                return r;
            }();
            Aabb table = room_inside;
            for (int axis : {a, b}) {
                const double c = room_inside.center()[axis];
                table.min[axis] = c - 1.5;
                table.max[axis] = c + 1.5;
            }
            for (double t = 0.0; t <= s.frames * s.dt; t += 0.05) {
                const Aabb box = s.boundsAt(o, t);
                Aabb flat = box;
                if (dimensions == 3) flat.min.y = flat.max.y = 0.0;
                for (int axis : {a, b}) {
                    EXPECT_GE(flat.min[axis], room_inside.min[axis]) << t;
                    EXPECT_LE(flat.max[axis], room_inside.max[axis]) << t;
                }
                const bool over_table = flat.max[a] > table.min[a] && table.max[a] > flat.min[a] &&
                                        flat.max[b] > table.min[b] && table.max[b] > flat.min[b];
                EXPECT_FALSE(over_table) << t;
            }
            // It does go round.
            EXPECT_GT(glm::length(s.positionAt(o.id, s.frames * s.dt) - start), 0.1);
        }
        EXPECT_EQ(chairs, 18);
        // Every wall between two rooms has a door: between rooms (0, 0) and
        // (1, 0) the line a = 45 is free at the middle of the first row.
        glm::dvec3 door_point{0.0};
        door_point[a] = 45.0;
        door_point[b] = 45.0;
        for (const SceneObject& o : s.objects) {
            if (o.motion.kind == MotionKind::Keyframes) continue;
            Aabb flat = o.bounds;
            if (dimensions == 3) flat.min.y = flat.max.y = door_point.y = 0.0;
            EXPECT_FALSE(flat.contains(door_point)) << o.id;
        }
    }
}

TEST(SceneGenerators, MeshCrowdSharesFewMeshesAndMovesInStraightLines) {
    const Scene s = load(3, R"({"type": "mesh_crowd", "file": "meshes/bunny.obj", "count": 40,
        "scale": [0.2, 0.5], "max_speed": 3})",
                         "", 1, sourcePath("scenes"));
    ASSERT_EQ(s.objects.size(), 40u);
    std::vector<const TriangleMesh*> meshes;
    for (const SceneObject& o : s.objects) {
        ASSERT_EQ(o.shape, ShapeKind::Mesh);
        EXPECT_EQ(o.motion.kind, MotionKind::Linear);
        EXPECT_LE(o.motion.max_speed, 3.0 + 1e-12);
        EXPECT_TRUE(within(o.bounds, s.grid.world, 3));
        const double height = o.mesh->bounds.max.y - o.mesh->bounds.min.y;
        EXPECT_GE(height, 0.2 * 9.65 - 0.01);
        EXPECT_LE(height, 0.5 * 9.66 + 0.01);
        if (std::find(meshes.begin(), meshes.end(), o.mesh.get()) == meshes.end())
            meshes.push_back(o.mesh.get());
    }
    EXPECT_LE(meshes.size(), size_t(8));
    EXPECT_GE(meshes.size(), size_t(2));
}

}  // namespace
}  // namespace gridcull
