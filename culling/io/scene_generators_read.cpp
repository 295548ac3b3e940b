// Reading and checking the `generators` array (scene_generators.h). Nothing is
// generated here, so the object-count limit can be checked first.
#include <algorithm>
#include <cmath>

#include "culling/io/scene_loader.h"
#include "culling/io/scene_loader_internal.h"

namespace gridcull {

namespace {

const NumberRule kPositive{"a finite number > 0", 0.0, true};
const NumberRule kNonNegative{"a finite number >= 0", 0.0, false};

bool readRegion(JsonObjectReader& g, SceneLoadContext& c, Aabb& region) {
    const Json* value = g.find("region");
    if (!value) return true;
    JsonObjectReader r(*value, g.pathOf("region"), c.errors);
    if (!r.ok()) return false;
    bool good = r.checkKeys({"min", "max"});
    Aabb box;
    const bool has_min = r.vector("min", true, c.dimensions, box.min);
    const bool has_max = r.vector("max", true, c.dimensions, box.max);
    if (!has_min || !has_max) return false;
    for (int axis = 0; axis < c.dimensions; ++axis) {
        if (box.max[axis] > box.min[axis]) continue;
        c.errors.add(indexPath(r.pathOf("max"), size_t(axis)),
                     "must be greater than min[" + std::to_string(axis) + "] = " +
                         formatNumber(box.min[axis]) + ", got " + formatNumber(box.max[axis]));
        good = false;
    }
    if (good) region = box;
    return good;
}

bool readCount(JsonObjectReader& g, int64_t limit, int64_t& count) {
    return g.integer("count", true, 0, limit, "an integer in [0, " + std::to_string(limit) + "]",
                     count);
}

bool readSphereCluster(JsonObjectReader& g, SceneLoadContext& c, GeneratorPlan& plan) {
    SphereClusterParams p;
    p.region = c.scene.grid.world;
    bool good = g.checkKeys(
        {"type", "count", "radius", "dynamic_fraction", "max_speed", "region", "motion"},
        "for generator 'sphere_cluster'");
    good = readCount(g, kMaxSceneObjects, p.count) && good;
    good = g.range("radius", true, kPositive, p.radius_min, p.radius_max) && good;
    good = g.number("dynamic_fraction", false, NumberRule{"a number in [0, 1]", 0.0, false, 1.0},
                    p.dynamic_fraction) &&
           good;
    const bool speed_ok = g.number("max_speed", false, kNonNegative, p.max_speed);
    good = speed_ok && good;
    if (speed_ok && p.dynamic_fraction > 0.0 && !(p.max_speed > 0.0))
        c.errors.add(g.pathOf("max_speed"),
                     "must be a finite number > 0 when dynamic_fraction > 0, got " +
                         (g.has("max_speed") ? describe(*g.find("max_speed"))
                                             : std::string("nothing (the key is missing)")));
    good = readRegion(g, c, p.region) && good;
    std::string motion = "mixed";
    if (g.string("motion", false, motion)) {
        if (motion == "mixed") {
            p.motion = ClusterMotion::Mixed;
        } else if (motion == "random") {
            p.motion = ClusterMotion::Random;
        } else if (motion == "linear") {
            p.motion = ClusterMotion::Linear;
        } else {
            c.errors.add(g.pathOf("motion"), "must be \"mixed\", \"random\" or \"linear\", got " +
                                                 describe(*g.find("motion")));
            good = false;
        }
    } else {
        good = false;
    }
    plan.count = p.count;
    plan.params = p;
    return good;
}

// The width a row of `n` cells of `cell` with `gap` before, between and after
// them must fit the coordinate limit.
bool checkSpan(JsonObjectReader& g, SceneLoadContext& c, const char* key, double span) {
    if (span <= kMaxMagnitude) return true;
    c.errors.add(g.pathOf(key), "make the layout " + formatNumber(span) +
                                    " wide, more than the limit of " + formatNumber(kMaxMagnitude));
    return false;
}

bool readCity(JsonObjectReader& g, SceneLoadContext& c, GeneratorPlan& plan) {
    CityParams p;
    bool good = g.checkKeys({"type", "blocks", "block_size", "street_width", "height"},
                            "for generator 'city'");
    int64_t blocks[2] = {1, 1};
    good = g.integers("blocks", true, 2, 1, kMaxCityBlocksPerAxis,
                      "integers in [1, " + std::to_string(kMaxCityBlocksPerAxis) + "] ([nx, nz])",
                      blocks) &&
           good;
    good = g.number("block_size", true, kPositive, p.block_size) && good;
    good = g.number("street_width", true, kNonNegative, p.street_width) && good;
    good = g.range("height", true, kPositive, p.height_min, p.height_max) && good;
    p.blocks_x = blocks[0];
    p.blocks_z = blocks[1];
    if (good) {
        const int64_t n = std::max(p.blocks_x, p.blocks_z);
        good = checkSpan(g, c, "blocks", double(n) * p.block_size + double(n + 1) * p.street_width);
    }
    plan.count = p.blocks_x * p.blocks_z;
    plan.params = p;
    return good;
}

bool readForest(JsonObjectReader& g, SceneLoadContext& c, GeneratorPlan& plan) {
    ForestParams p;
    bool good = g.checkKeys({"type", "count", "trunk_radius", "crown_radius", "height"},
                            "for generator 'forest'");
    good = readCount(g, kMaxSceneObjects / 2, p.count) && good;
    good = g.number("trunk_radius", true, kPositive, p.trunk_radius) && good;
    const bool crown_ok = g.number("crown_radius", true, kPositive, p.crown_radius);
    const bool height_ok = g.range("height", true, kPositive, p.height_min, p.height_max);
    good = good && crown_ok && height_ok;
    if (crown_ok && height_ok && !(p.height_min > p.crown_radius)) {
        c.errors.add(g.pathOf("height"),
                     "must have min greater than crown_radius = " + formatNumber(p.crown_radius) +
                         " (the crown sits on a trunk), got " + describe(*g.find("height")));
        good = false;
    }
    plan.count = 2 * p.count;
    plan.params = p;
    return good;
}

// The rooms generator's people (scene_generators.h): `people`, `people_speed`
// (required when people > 0; 0: standing people), `people_rooms` ([i0, j0, i1, j1] inside the
// building), and a door wide enough for a person. `rooms` has been read (or left at 1 x 1);
// `sizes_ok`: room_size and door_width were read.
bool readPeople(JsonObjectReader& g, SceneLoadContext& c, const int64_t rooms[2], bool sizes_ok,
                RoomsParams& p) {
    bool good = g.integer("people", false, 0, kMaxSceneObjects,
                          "an integer in [0, " + std::to_string(kMaxSceneObjects) + "]", p.people);
    const bool speed_ok = g.number("people_speed", false, kNonNegative, p.people_speed);
    good = speed_ok && good;
    if (good && p.people > 0 && !g.has("people_speed")) {
        c.errors.add(g.pathOf("people_speed"),
                     "must be given when people > 0: a finite number >= 0 (0: they stand "
                     "still), got nothing (the key is missing)");
        good = false;
    }
    if (good && sizes_ok && p.people > 0 && !(p.door_width > kPersonWidth * p.room_size)) {
        c.errors.add(g.pathOf("door_width"),
                     "must be wider than a person (" + formatNumber(kPersonWidth) +
                         " * room_size = " + formatNumber(kPersonWidth * p.room_size) +
                         ") when people > 0, got " + formatNumber(p.door_width));
        good = false;
    }
    if (!g.has("people_rooms")) return good;
    int64_t r[4] = {0, 0, 0, 0};
    const std::string expected = "integers in [0, " + std::to_string(kMaxRoomsPerAxis - 1) +
                                 "] ([i0, j0, i1, j1]: the first and last room on each axis)";
    if (!g.integers("people_rooms", false, 4, 0, kMaxRoomsPerAxis - 1, expected, r)) return false;
    for (int axis = 0; axis < 2; ++axis) {
        const std::string path = indexPath(g.pathOf("people_rooms"), size_t(axis + 2));
        if (r[axis + 2] < r[axis]) {
            c.errors.add(path, "must be at least people_rooms[" + std::to_string(axis) +
                                   "] = " + std::to_string(r[axis]) + ", got " +
                                   std::to_string(r[axis + 2]));
            good = false;
        } else if (r[axis + 2] >= rooms[axis]) {
            c.errors.add(path, "must be a room of the building, less than rooms[" +
                                   std::to_string(axis) + "] = " + std::to_string(rooms[axis]) +
                                   ", got " + std::to_string(r[axis + 2]));
            good = false;
        }
        p.people_room_min[axis] = r[axis];
        p.people_room_max[axis] = r[axis + 2];
    }
    return good;
}

bool readRooms(JsonObjectReader& g, SceneLoadContext& c, GeneratorPlan& plan) {
    RoomsParams p;
    bool good = g.checkKeys(
        {"type", "rooms", "room_size", "wall_thickness", "door_width", "chairs_per_room",
         "chair_speed", "people", "people_speed", "people_rooms", "ground", "ceiling"},
        "for generator 'rooms'");
    int64_t rooms[2] = {1, 1};
    good =
        g.integers("rooms", true, 2, 1, kMaxRoomsPerAxis,
                   "integers in [1, " + std::to_string(kMaxRoomsPerAxis) + "] ([nx, nz])", rooms) &&
        good;
    const bool size_ok = g.number("room_size", true, kPositive, p.room_size);
    const bool wall_ok = g.number("wall_thickness", true, kPositive, p.wall_thickness);
    const bool door_ok = g.number("door_width", true, kPositive, p.door_width);
    good = good && size_ok && wall_ok && door_ok;
    good = g.integer("chairs_per_room", true, 0, kMaxChairsPerRoom,
                     "an integer in [0, " + std::to_string(kMaxChairsPerRoom) + "]",
                     p.chairs_per_room) &&
           good;
    good = g.number("chair_speed", true, kNonNegative, p.chair_speed) && good;
    if (size_ok && wall_ok && !(p.wall_thickness < 0.5 * p.room_size)) {
        c.errors.add(g.pathOf("wall_thickness"),
                     "must be less than half of room_size = " + formatNumber(p.room_size) +
                         ", got " + formatNumber(p.wall_thickness));
        good = false;
    } else if (size_ok && wall_ok && door_ok && !(p.door_width < p.room_size - p.wall_thickness)) {
        c.errors.add(g.pathOf("door_width"), "must be less than room_size - wall_thickness = " +
                                                 formatNumber(p.room_size - p.wall_thickness) +
                                                 ", got " + formatNumber(p.door_width));
        good = false;
    }
    if (g.has("ground")) {
        const Aabb& world = c.scene.grid.world;
        const std::string expected = "a number in [world.min[1], world.max[1]) = [" +
                                     formatNumber(world.min.y) + ", " + formatNumber(world.max.y) +
                                     ") (the floor's y, 3D only)";
        if (c.dimensions != 3) {
            c.errors.add(g.pathOf("ground"),
                         "does not exist in a 2D scene (the floor's y, 3D only)");
            good = false;
        } else if (g.number("ground", false,
                            NumberRule{expected.c_str(), world.min.y, false, world.max.y, true},
                            p.ground)) {
            p.has_ground = true;
        } else {
            good = false;
        }
    }
    if (g.has("ceiling")) {
        int64_t ceiling = 0;
        if (c.dimensions != 3) {
            c.errors.add(g.pathOf("ceiling"),
                         "does not exist in a 2D scene (a ceiling over the building, 3D only)");
            good = false;
        } else if (g.integer("ceiling", false, 0, 1, "0 or 1 (1: a ceiling over the building)",
                             ceiling)) {
            p.ceiling = ceiling == 1;
        } else {
            good = false;
        }
    }
    p.rooms_x = rooms[0];
    p.rooms_z = rooms[1];
    good = readPeople(g, c, rooms, size_ok && door_ok, p) && good;
    if (good) good = checkSpan(g, c, "rooms", double(std::max(p.rooms_x, p.rooms_z)) * p.room_size);
    plan.count = p.rooms_x * p.rooms_z * (5 + p.chairs_per_room) + p.people + (p.ceiling ? 1 : 0);
    plan.params = p;
    return good;
}

bool readMeshCrowd(JsonObjectReader& g, SceneLoadContext& c, GeneratorPlan& plan) {
    MeshCrowdParams p;
    bool good =
        g.checkKeys({"type", "file", "count", "scale", "max_speed"}, "for generator 'mesh_crowd'");
    good = readCount(g, kMaxSceneObjects, p.count) && good;
    good = g.range("scale", true, kPositive, p.scale_min, p.scale_max) && good;
    good = g.number("max_speed", true, kNonNegative, p.max_speed) && good;
    std::string file;
    good = g.string("file", true, file) && good;
    if (good) {
        const int levels = p.scale_max > p.scale_min ? kMeshCrowdScaleLevels : 1;
        for (int level = 0; level < levels && good; ++level) {
            const double f = levels == 1 ? 0.0 : double(level) / double(levels - 1);
            const double scale = p.scale_min + (p.scale_max - p.scale_min) * f;
            auto mesh = loadSceneMeshFile(file, scale, glm::dvec3(0.0), g.pathOf("file"), c);
            good = mesh != nullptr;
            p.meshes.push_back(std::move(mesh));
            p.scales.push_back(scale);
        }
    }
    plan.count = p.count;
    plan.params = std::move(p);
    return good;
}

// The plant generator (scene_generators.h, "plant"): its sizes, and a site that
// fits the world, so that every object lies inside it.
bool readPlant(JsonObjectReader& g, SceneLoadContext& c, GeneratorPlan& plan) {
    PlantParams p;
    bool good = g.checkKeys(
        {"type", "units", "unit_size", "aisle_width", "tank_height", "tanks_per_unit",
         "pipes_per_unit", "pipe_width", "valves_per_pipe", "platforms_per_unit", "rack_pipes"},
        "for generator 'plant'");
    int64_t units[2] = {1, 1};
    const bool units_ok = g.integers(
        "units", true, 2, 1, kMaxPlantUnitsPerAxis,
        "integers in [1, " + std::to_string(kMaxPlantUnitsPerAxis) + "] ([nx, nz])", units);
    const bool unit_ok = g.number("unit_size", true, kPositive, p.unit_size);
    const bool aisle_ok = g.number("aisle_width", true, kNonNegative, p.aisle_width);
    const bool tank_ok =
        g.range("tank_height", true, kPositive, p.tank_height_min, p.tank_height_max);
    const bool pipe_ok = g.range("pipe_width", true, kPositive, p.pipe_width_min, p.pipe_width_max);
    good = good && units_ok && unit_ok && aisle_ok && tank_ok && pipe_ok;
    const auto count = [&](const char* key, int64_t limit, int64_t& out) {
        return g.integer(key, true, 0, limit, "an integer in [0, " + std::to_string(limit) + "]",
                         out);
    };
    good = count("tanks_per_unit", kMaxPlantTanksPerUnit, p.tanks_per_unit) && good;
    good = count("pipes_per_unit", kMaxPlantPipesPerUnit, p.pipes_per_unit) && good;
    good = count("valves_per_pipe", kMaxPlantValvesPerPipe, p.valves_per_pipe) && good;
    good = count("platforms_per_unit", kMaxPlantPlatformsPerUnit, p.platforms_per_unit) && good;
    good = count("rack_pipes", kMaxPlantRackPipes, p.rack_pipes) && good;
    p.units_x = units[0];
    p.units_z = units[1];
    const Aabb& world = c.scene.grid.world;
    if (units_ok && unit_ok && aisle_ok) {
        for (int i = 0; i < 2; ++i) {
            const int axis = i == 0 ? 0 : 2;
            const double span = double(units[i]) * (p.unit_size + p.aisle_width) + p.aisle_width;
            const double room = world.max[axis] - world.min[axis];
            if (span <= room) continue;
            c.errors.add(indexPath(g.pathOf("units"), size_t(i)),
                         std::string("make the site ") + formatNumber(span) + " wide along " +
                             (i == 0 ? "x" : "z") + ", more than the world's " +
                             formatNumber(room) +
                             " (units * (unit_size + aisle_width) + "
                             "aisle_width must fit the world)");
            good = false;
        }
    }
    const double world_height = world.max.y - world.min.y;
    if (tank_ok && p.tank_height_max > world_height) {
        c.errors.add(indexPath(g.pathOf("tank_height"), 1),
                     "must be at most the world's height " + formatNumber(world_height) + ", got " +
                         formatNumber(p.tank_height_max));
        good = false;
    }
    if (unit_ok && tank_ok && pipe_ok) {
        const double limit = std::min(p.unit_size, p.tank_height_min) / 15.0;
        if (!(p.pipe_width_max < limit)) {
            c.errors.add(
                indexPath(g.pathOf("pipe_width"), 1),
                "must be less than min(unit_size, tank_height[0]) / 15 = " + formatNumber(limit) +
                    " (pipes and valves must fit a unit), got " + formatNumber(p.pipe_width_max));
            good = false;
        }
    }
    plan.count = plantObjectCount(p);
    plan.params = p;
    return good;
}

}  // namespace

void readGenerators(const Json& generators, SceneLoadContext& c, std::vector<GeneratorPlan>& out) {
    for (size_t i = 0; i < generators.size(); ++i) {
        const std::string path = indexPath("generators", i);
        JsonObjectReader g(generators[i], path, c.errors);
        if (!g.ok()) continue;
        std::string type;
        if (!g.string("type", true, type)) continue;
        GeneratorPlan plan;
        plan.path = path;
        const bool is_3d = c.dimensions == 3;
        bool good = false;
        if (type == "sphere_cluster") {
            good = readSphereCluster(g, c, plan);
        } else if (type == "rooms") {
            good = readRooms(g, c, plan);
        } else if ((type == "city" || type == "forest" || type == "mesh_crowd" ||
                    type == "plant") &&
                   !is_3d) {
            c.errors.add(g.pathOf("type"), "generator '" + type +
                                               "' does not exist in a 2D scene; must be "
                                               "sphere_cluster or rooms, got \"" +
                                               type + "\"");
        } else if (type == "city") {
            good = readCity(g, c, plan);
        } else if (type == "forest") {
            good = readForest(g, c, plan);
        } else if (type == "mesh_crowd") {
            good = readMeshCrowd(g, c, plan);
        } else if (type == "plant") {
            good = readPlant(g, c, plan);
        } else {
            c.errors.add(g.pathOf("type"),
                         std::string("must be one of sphere_cluster, rooms") +
                             (is_3d ? ", city, forest, mesh_crowd, plant" : " (the scene is 2D)") +
                             ", got " + describe(*g.find("type")));
        }
        if (good) out.push_back(std::move(plan));
    }
}

}  // namespace gridcull
