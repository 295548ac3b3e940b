// The `plant` generator (an addition of ours standing in for Kovalcik &
// Sochor's power plant; layout in culling/generators/scene_generators.h):
// object counts, determinism from the seed, every object inside the world,
// pipes along all three axes and sizes spread over two orders of magnitude.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "culling/generators/scene_generators.h"
#include "culling/io/scene_loader.h"

namespace gridcull {
namespace {

const std::string kPlant = R"({"type": "plant", "units": [3, 2], "unit_size": 20,
    "aisle_width": 4, "tank_height": [6, 18], "tanks_per_unit": 5, "pipes_per_unit": 12,
    "pipe_width": [0.1, 0.3], "valves_per_pipe": 2, "platforms_per_unit": 2,
    "rack_pipes": 3})";

Scene loadPlant(const std::string& generator, uint64_t seed = 1,
                const std::string& world = R"({"min": [0, 0, 0], "max": [100, 20, 80]})") {
    const std::string text =
        R"({"format": "gridcull-scene/1", "dimensions": 3, "world": )" + world + R"(, "seed": )" +
        std::to_string(seed) +
        R"(, "camera": {"path": [{"t": 0, "position": [1, 1, 1], "target": [5, 1, 5]}]},
            "generators": [)" +
        generator + "]}";
    SceneLoadResult r = loadSceneText(text, "plant.json", "");
    EXPECT_TRUE(r.errors.empty()) << (r.errors.empty() ? "" : r.errors[0]);
    return r.scene ? *r.scene : Scene{};
}

double longestSide(const Aabb& b) {
    const glm::dvec3 d = b.max - b.min;
    return std::max({d.x, d.y, d.z});
}

TEST(PlantGenerator, CountsFollowTheParameters) {
    const Scene s = loadPlant(kPlant);
    // 6 units of 5 tanks, 12 pipes with 2 valves each and 2 platforms of 5
    // boxes; 3 rack pipes over each of the 2 + 1 inner aisles.
    ASSERT_EQ(s.objects.size(), size_t(6 * (5 + 12 * 3 + 2 * 5) + 3 * 3));
    PlantParams p;
    p.units_x = 3;
    p.units_z = 2;
    p.tanks_per_unit = 5;
    p.pipes_per_unit = 12;
    p.valves_per_pipe = 2;
    p.platforms_per_unit = 2;
    p.rack_pipes = 3;
    EXPECT_EQ(plantObjectCount(p), int64_t(s.objects.size()));
    int spheres = 0;
    for (const SceneObject& o : s.objects) {
        EXPECT_FALSE(o.isDynamic()) << o.id;
        if (o.shape == ShapeKind::Sphere) ++spheres;
    }
    // About one tank in three is a sphere, the rest are boxes.
    EXPECT_GT(spheres, 0);
    EXPECT_LT(spheres, 30);
    // No racks with a single unit row and column; nothing at all with zero counts.
    const Scene one = loadPlant(R"({"type": "plant", "units": [1, 1], "unit_size": 20,
        "aisle_width": 4, "tank_height": [6, 18], "tanks_per_unit": 0, "pipes_per_unit": 1,
        "pipe_width": [0.1, 0.3], "valves_per_pipe": 0, "platforms_per_unit": 0,
        "rack_pipes": 5})");
    EXPECT_EQ(one.objects.size(), 1u);
}

TEST(PlantGenerator, SameSeedSameSiteOtherSeedOtherSite) {
    const Scene a = loadPlant(kPlant, 7), b = loadPlant(kPlant, 7), c = loadPlant(kPlant, 8);
    ASSERT_EQ(a.objects.size(), b.objects.size());
    ASSERT_EQ(a.objects.size(), c.objects.size());
    bool differ = false;
    for (size_t i = 0; i < a.objects.size(); ++i) {
        EXPECT_EQ(a.objects[i].shape, b.objects[i].shape);
        EXPECT_EQ(a.objects[i].bounds.min, b.objects[i].bounds.min) << i;
        EXPECT_EQ(a.objects[i].bounds.max, b.objects[i].bounds.max) << i;
        differ = differ || a.objects[i].bounds.min != c.objects[i].bounds.min;
    }
    EXPECT_TRUE(differ);
}

TEST(PlantGenerator, EveryObjectLiesInsideTheWorld) {
    // A tight world: the site (3 * 24 + 4 = 76 by 2 * 24 + 4 = 52) centred in
    // it, the tallest tank as high as the world; and with no aisles at all.
    const std::string tight = R"({"min": [-10, 2, 5], "max": [66, 20, 57]})";
    std::string no_aisles = kPlant;
    no_aisles.replace(no_aisles.find("\"aisle_width\": 4"), 16, "\"aisle_width\": 0");
    for (uint64_t seed = 1; seed <= 5; ++seed) {
        for (const std::string& generator : {kPlant, no_aisles}) {
            const Scene s = loadPlant(generator, seed, tight);
            ASSERT_FALSE(s.objects.empty());
            const Aabb& w = s.grid.world;
            for (const SceneObject& o : s.objects) {
                for (int axis = 0; axis < 3; ++axis) {
                    EXPECT_GE(o.bounds.min[axis], w.min[axis] - 1e-9) << o.id << " " << axis;
                    EXPECT_LE(o.bounds.max[axis], w.max[axis] + 1e-9) << o.id << " " << axis;
                }
                EXPECT_GT(longestSide(o.bounds), 0.0);
            }
        }
    }
}

TEST(PlantGenerator, SizesSpreadOverTwoOrdersOfMagnitude) {
    const Scene s = loadPlant(kPlant);
    double smallest = 1e300, largest = 0.0;
    for (const SceneObject& o : s.objects) {
        smallest = std::min(smallest, longestSide(o.bounds));
        largest = std::max(largest, longestSide(o.bounds));
    }
    // Valves are 2.5 pipe widths (0.25 at the thinnest); racks run the site's
    // 76 length.
    EXPECT_LE(smallest, 0.75);
    EXPECT_GE(largest, 76.0 - 1e-9);
    EXPECT_GE(largest / smallest, 100.0);
}

TEST(PlantGenerator, PipesRunAlongEveryAxisAtSeveralHeights) {
    const Scene s = loadPlant(kPlant);
    int along[3] = {0, 0, 0};
    std::vector<double> heights;
    for (const SceneObject& o : s.objects) {
        if (o.shape != ShapeKind::Box) continue;
        const glm::dvec3 d = o.box.max - o.box.min;
        for (int axis = 0; axis < 3; ++axis) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            // A pipe: a square section at most 0.3 wide, at least 4 widths long.
            if (std::abs(d[u] - d[v]) < 1e-9 && d[u] <= 0.3 + 1e-9 && d[axis] >= 4.0 * d[u]) {
                ++along[axis];
                if (axis != 1) heights.push_back(o.box.center().y);
            }
        }
    }
    EXPECT_GT(along[0], 10);
    EXPECT_GT(along[1], 10);
    EXPECT_GT(along[2], 10);
    std::sort(heights.begin(), heights.end());
    heights.erase(std::unique(heights.begin(), heights.end(),
                              [](double a, double b) { return b - a < 1e-9; }),
                  heights.end());
    EXPECT_GE(heights.size(), 4u);
}

TEST(PlantGenerator, ShippedSceneIsThePowerPlantsSize) {
    const SceneLoadResult r =
        loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/plant-3d.json");
    ASSERT_TRUE(r.scene) << (r.errors.empty() ? "" : r.errors[0]);
    // The paper's plant has 1185 objects; ours 1192 and three trucks.
    EXPECT_EQ(r.scene->objects.size(), 1195u);
    int moving = 0;
    for (const SceneObject& o : r.scene->objects) moving += o.isDynamic() ? 1 : 0;
    EXPECT_EQ(moving, 3);
}

}  // namespace
}  // namespace gridcull
