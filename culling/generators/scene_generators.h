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
//   high, standing on world.min.y. Each room has a table (a box of side
//   0.3 * room_size at its centre, 0.075 * room_size high) and chairs_per_room
//   chairs (boxes of side 0.05 * room_size, 0.1 * room_size high) that circle
//   the table at chair_speed on a square loop, as keyframe motion; the loop is
//   precomputed for the scene's duration (at most kMaxChairKeys keys each,
//   fewer when there are many chairs) and the chair stops at its end.
// - mesh_crowd (3D): `count` copies of the mesh in `file` at scales quantised
//   to kMeshCrowdScaleLevels levels evenly spread over `scale` (so copies share
//   kMeshCrowdScaleLevels meshes at most), placed like sphere_cluster, each in
//   linear motion with a speed uniform in [max_speed / 4, max_speed].
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
};

struct MeshCrowdParams {
    int64_t count = 0;
    double scale_min = 1.0, scale_max = 1.0;
    double max_speed = 0.0;
    // One mesh per scale level, loaded while reading so a bad file is reported early.
    std::vector<std::shared_ptr<const TriangleMesh>> meshes;
    std::vector<double> scales;
};

using GeneratorParams =
    std::variant<SphereClusterParams, CityParams, ForestParams, RoomsParams, MeshCrowdParams>;

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

}  // namespace gridcull
