// Scene generators (scene-format.md, "Generators"): many objects from a few
// parameters, deterministically from the scene seed and the generator's index.
// The scene loader reads and checks each generator first (readGenerators,
// culling/io/), so the object-count limit is checked before anything is made,
// and generates afterwards (runGenerator).
//
// Choices the format leaves open, made here:
// - sphere_cluster: centres uniform in the world (or in the optional `region`
//   box, an addition of ours), kept so that the whole sphere lies inside it when
//   it fits. Exactly round(count * dynamic_fraction) spheres move. The optional
//   `motion` key (an addition: "mixed" (default), "random" or "linear") says
//   how: random walks with `max_speed`, or straight lines with a speed uniform
//   in [max_speed / 4, max_speed] in a uniform direction.
// - city (3D): one box building per block, blocks of block_size x block_size
//   with streets of street_width between and around them, the whole grid
//   centred on the world in x and z and standing on world.min.y; heights
//   uniform in `height`.
// - forest (3D): `count` trees at uniform x, z in the world, standing on
//   world.min.y, each a square trunk box (side 2 * trunk_radius) up to
//   height - crown_radius and a crown sphere of crown_radius centred on the
//   trunk's top, so a tree is `height` tall; two objects per tree.
// - rooms: nx x nz square rooms of room_size (x-z plane in 3D, x-y in 2D),
//   centred on the world; every wall between two rooms has a door_width gap in
//   its middle, the outer walls are closed. In 3D walls are 0.3 * room_size
//   high, standing on world.min.y, or on the optional `ground` (an addition of
//   ours: a y inside the world, so that the world can reach below the floor),
//   with, optionally (`ceiling`, ours too), a slab wall_thickness thick over
//   the whole building on the walls' tops, made right after the walls, so
//   that nothing is seen over a wall. Each room has a table (a box of side
//   0.3 * room_size at its centre, 0.075 * room_size high) and chairs_per_room
//   chairs (boxes of side 0.05 * room_size, 0.1 * room_size high) that circle
//   the table at chair_speed on a square loop, as keyframe motion; the loop is
//   precomputed for the scene's duration (at most kMaxChairKeys keys each,
//   fewer when there are many chairs) and the chair stops at its end.
//   Optional people (an addition of ours, for Sudarsky & Gotsman's Fig. 13a, a
//   building with moving men): `people` boxes of 0.05 x 0.18 x 0.05 room_size
//   (0.5 x 1.8 x 0.5 at room_size 10; a flat 0.05 x 0.05 square in 2D), below
//   the walls, so a person is hidden from the rooms it is not seen from. Each
//   starts at a uniform room of `people_rooms` ([i0, j0, i1, j1], room indices
//   along a and b, inclusive; the whole building by default) and a uniform
//   point of its room's walkway: the square loop of half-size q around the
//   room's centre, q three quarters of the way from the table's edge to the
//   walls' inner faces (both cleared by half a person's width), so the walkway
//   stays in the room. It walks at people_speed along the walkway, the shorter
//   way, to the middle of a side facing a door (a uniform one of the doors to
//   the rooms of people_rooms, not the one it came through unless there is no
//   other), then straight through the door's gap (door_width must be wider than
//   a person) to the middle of the walkway's side in the next room, and so on:
//   keyframe motion with a key at every corner and door, precomputed for the
//   scene's duration within the same key budget as the chairs (people and
//   chairs share it), held at its end. With a single room in people_rooms the
//   person circles the walkway. People come after the walls, tables and chairs
//   and draw from the random stream after them, so adding people changes no
//   other object.
// - mesh_crowd (3D): `count` copies of the mesh in `file` at scales quantised
//   to kMeshCrowdScaleLevels levels evenly spread over `scale` (so copies share
//   kMeshCrowdScaleLevels meshes at most), placed like sphere_cluster, each in
//   linear motion with a speed uniform in [max_speed / 4, max_speed].
// - plant (3D, an addition of ours standing in for Kovalcik & Sochor's power
//   plant, scene_generators_plant.cpp): a dense static industrial site of many
//   boxes and spheres whose sizes spread over more than two orders of magnitude.
//   nx x nz square process units of unit_size with aisles of aisle_width
//   between and around them, the whole site centred on the world in x and z
//   and standing on world.min.y. Per unit, in this order:
//   * tanks_per_unit tanks in the unit's back half (low z), one per cell of a
//     grid of ceil(sqrt(n)) columns: a tall box (a column or vessel, square
//     footprint 0.4..0.8 of the cell, height uniform in tank_height) or, one
//     time in three, a spherical tank standing on the ground (radius 0.3..0.4
//     of the cell's smaller side, at most half the drawn height);
//   * platforms_per_unit platforms in the front half: a slab 0.25..0.5 x
//     0.15..0.35 unit_size, as thick as the largest pipe, at a height uniform
//     in [0.2, 0.8] tank_height[0], on four legs (boxes of the smallest pipe
//     width) from the ground; five objects each;
//   * pipes_per_unit pipes, each a box of square section (width uniform in
//     pipe_width) along x, y or z (one in three each): a horizontal one 0.3..1
//     unit_size long at one of four levels k / 5 * tank_height[0] (k = 1..4),
//     a vertical one from the ground to such a level; each followed by its
//     valves_per_pipe valves, cubes of 2.5 pipe widths centred on the pipe's
//     axis at uniform points of it (kept off its ends);
//   then rack_pipes pipes over every aisle between two units (not the outer
//   ones), running the whole site's length at 0.85 tank_height[0], spread
//   evenly across the aisle, widths uniform in pipe_width. Pipes and valves
//   keep 1.25 pipe_width[1] off the unit's edges, so nothing leaves the unit
//   (racks: the site); the loader checks that the site fits the world, that
//   tank_height[1] fits its height and that pipe_width[1] < unit_size / 10 and
//   < tank_height[0] / 10, so every object lies inside the world.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "culling/scene/scene.h"

namespace gridcull {

class SeededRandom;

constexpr int kMeshCrowdScaleLevels = 8;
constexpr int kMaxChairKeys = 4096;
constexpr int kMaxRoomsPerAxis = 200;
constexpr int kMaxCityBlocksPerAxis = 1000;
constexpr int kMaxChairsPerRoom = 64;

enum class ClusterMotion { Mixed, Random, Linear };

struct SphereClusterParams {
    int64_t count = 0;
    double radius_min = 1.0, radius_max = 1.0;
    double dynamic_fraction = 0.0;
    double max_speed = 0.0;
    Aabb region;  // the world unless given
    ClusterMotion motion = ClusterMotion::Mixed;
};

struct CityParams {
    int64_t blocks_x = 1, blocks_z = 1;
    double block_size = 1.0, street_width = 0.0;
    double height_min = 1.0, height_max = 1.0;
};

struct ForestParams {
    int64_t count = 0;
    double trunk_radius = 0.1, crown_radius = 1.0;
    double height_min = 2.0, height_max = 2.0;
};

struct RoomsParams {
    int64_t rooms_x = 1, rooms_z = 1;
    double room_size = 10.0, wall_thickness = 0.2, door_width = 1.0;
    int64_t chairs_per_room = 0;
    double chair_speed = 0.0;
    int64_t people = 0;
    double people_speed = 0.0;
    // Rooms people walk in, inclusive: [people_room_min, people_room_max] per
    // floor-plan axis (a, b); -1 in people_room_max means the last room.
    int64_t people_room_min[2] = {0, 0};
    int64_t people_room_max[2] = {-1, -1};
    // 3D: the floor's y; world.min.y unless has_ground.
    bool has_ground = false;
    double ground = 0.0;
    // 3D: a ceiling over the whole building (a slab wall_thickness thick on
    // the walls' tops), so that nothing is seen over a wall, as in a building.
    bool ceiling = false;
};

// A person's size, as fractions of room_size (scene_generators.h, "rooms").
constexpr double kPersonWidth = 0.05;
constexpr double kPersonHeight = 0.18;

struct MeshCrowdParams {
    int64_t count = 0;
    double scale_min = 1.0, scale_max = 1.0;
    double max_speed = 0.0;
    // One mesh per scale level, loaded while reading so a bad file is reported early.
    std::vector<std::shared_ptr<const TriangleMesh>> meshes;
    std::vector<double> scales;
};

constexpr int kMaxPlantUnitsPerAxis = 100;
constexpr int kMaxPlantTanksPerUnit = 64;
constexpr int kMaxPlantPipesPerUnit = 1000;
constexpr int kMaxPlantValvesPerPipe = 16;
constexpr int kMaxPlantPlatformsPerUnit = 16;
constexpr int kMaxPlantRackPipes = 64;

struct PlantParams {
    int64_t units_x = 1, units_z = 1;
    double unit_size = 30.0, aisle_width = 5.0;
    double tank_height_min = 10.0, tank_height_max = 10.0;
    int64_t tanks_per_unit = 0;
    int64_t pipes_per_unit = 0;
    double pipe_width_min = 0.2, pipe_width_max = 0.2;
    int64_t valves_per_pipe = 0;
    int64_t platforms_per_unit = 0;
    int64_t rack_pipes = 0;
};

// How many objects `plant` makes (scene_generators.h, "plant").
int64_t plantObjectCount(const PlantParams& p);

using GeneratorParams = std::variant<SphereClusterParams, CityParams, ForestParams, RoomsParams,
                                     MeshCrowdParams, PlantParams>;

// A generator whose parameters have been checked; `count` is how many objects
// it will make.
struct GeneratorPlan {
    std::string path;  // "generators[1]"
    int64_t count = 0;
    GeneratorParams params;
};

// Appends the objects of `plan` to scene.objects with ids from `next_id` on
// (advancing it), using the scene's dimensions, world, seed and duration.
// Deterministic in (scene seed, generator_index).
void runGenerator(const GeneratorPlan& plan, size_t generator_index, Scene& scene, int& next_id);

// The rooms layout (scene_generators_rooms.cpp): appends its objects to
// scene.objects with ids from next_id on.
void generateRooms(const RoomsParams& params, SeededRandom& rng, Scene& scene, int& next_id);

// The plant layout (scene_generators_plant.cpp): appends plantObjectCount(params)
// objects to scene.objects with ids from next_id on.
void generatePlant(const PlantParams& params, SeededRandom& rng, Scene& scene, int& next_id);

}  // namespace gridcull
