// Making the objects of checked generators (scene_generators.h describes the
// layouts). Ids come in generation order from next_id.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "culling/generators/scene_emitter.h"
#include "culling/generators/scene_generators.h"
#include "culling/scene/seeded_random.h"

namespace gridcull {

namespace {

using Emitter = SceneEmitter;

SceneObject makeSphere(const glm::dvec3& center, double radius) {
    SceneObject o;
    o.shape = ShapeKind::Sphere;
    o.center = center;
    o.radius = radius;
    return o;
}

SceneObject makeBox(const Aabb& box) {
    SceneObject o;
    o.shape = ShapeKind::Box;
    o.box = box;
    return o;
}

// A uniform position for a shape whose bounds are `low`..`high` relative to
// it, such that the bounds lie inside `region` on every axis where they fit,
// and centred in `region` on the axes where they do not.
glm::dvec3 placeInside(SeededRandom& rng, const Aabb& region, const glm::dvec3& low,
                       const glm::dvec3& high, int dimensions) {
    glm::dvec3 p{0.0};
    for (int axis = 0; axis < dimensions; ++axis) {
        const double lo = region.min[axis] - low[axis];
        const double hi = region.max[axis] - high[axis];
        p[axis] = lo <= hi ? rng.uniform(lo, hi) : region.center()[axis];
    }
    return p;
}

// A straight-line motion with speed uniform in [max_speed / 4, max_speed].
Motion linearMotion(SeededRandom& rng, int dimensions, double max_speed) {
    Motion m;
    m.kind = MotionKind::Linear;
    m.velocity = randomDirection(rng, dimensions) * (max_speed * rng.uniform(0.25, 1.0));
    m.max_speed = glm::length(m.velocity);
    return m;
}

void generateSphereCluster(const SphereClusterParams& p, SeededRandom& rng, Emitter& out) {
    const int dims = out.scene.dimensions;
    const int64_t dynamic = std::llround(double(p.count) * p.dynamic_fraction);
    for (int64_t i = 0; i < p.count; ++i) {
        const double radius = rng.uniform(p.radius_min, p.radius_max);
        const glm::dvec3 half{radius, radius, dims == 2 ? 0.0 : radius};
        SceneObject o = makeSphere(placeInside(rng, p.region, -half, half, dims), radius);
        if (i < dynamic) {
            const bool random = p.motion == ClusterMotion::Random ||
                                (p.motion == ClusterMotion::Mixed && rng.uniform() < 0.5);
            if (random) {
                o.motion.kind = MotionKind::Random;
                o.motion.max_speed = p.max_speed;  // the walk is built once ids are final
            } else {
                o.motion = linearMotion(rng, dims, p.max_speed);
            }
        }
        out.add(std::move(o));
    }
}

void generateCity(const CityParams& p, SeededRandom& rng, Emitter& out) {
    const Aabb& world = out.scene.grid.world;
    const double pitch = p.block_size + p.street_width;
    const double width_x = double(p.blocks_x) * pitch + p.street_width;
    const double width_z = double(p.blocks_z) * pitch + p.street_width;
    const double x0 = world.center().x - width_x * 0.5 + p.street_width;
    const double z0 = world.center().z - width_z * 0.5 + p.street_width;
    const double ground = world.min.y;
    for (int64_t j = 0; j < p.blocks_z; ++j) {
        for (int64_t i = 0; i < p.blocks_x; ++i) {
            const double x = x0 + double(i) * pitch, z = z0 + double(j) * pitch;
            const double height = rng.uniform(p.height_min, p.height_max);
            out.add(
                makeBox({{x, ground, z}, {x + p.block_size, ground + height, z + p.block_size}}));
        }
    }
}

void generateForest(const ForestParams& p, SeededRandom& rng, Emitter& out) {
    const Aabb& world = out.scene.grid.world;
    const double ground = world.min.y;
    const glm::dvec3 half{p.crown_radius, 0.0, p.crown_radius};
    for (int64_t i = 0; i < p.count; ++i) {
        glm::dvec3 at = placeInside(rng, world, -half, half, 3);
        const double height = rng.uniform(p.height_min, p.height_max);
        const double top = ground + height - p.crown_radius;
        out.add(makeBox({{at.x - p.trunk_radius, ground, at.z - p.trunk_radius},
                         {at.x + p.trunk_radius, top, at.z + p.trunk_radius}}));
        out.add(makeSphere({at.x, top, at.z}, p.crown_radius));
    }
}

void generateMeshCrowd(const MeshCrowdParams& p, SeededRandom& rng, Emitter& out) {
    const Aabb& world = out.scene.grid.world;
    for (int64_t i = 0; i < p.count; ++i) {
        const size_t level = size_t(rng.below(p.meshes.size()));
        SceneObject o;
        o.shape = ShapeKind::Mesh;
        o.mesh = p.meshes[level];
        o.center = placeInside(rng, world, o.mesh->bounds.min, o.mesh->bounds.max, 3);
        if (p.max_speed > 0.0) o.motion = linearMotion(rng, 3, p.max_speed);
        out.add(std::move(o));
    }
}

}  // namespace

void runGenerator(const GeneratorPlan& plan, size_t generator_index, Scene& scene, int& next_id) {
    // One stream per generator: adding a generator does not change the others.
    SeededRandom rng(scene.seed, 0x47454e0000000000ull + generator_index);
    Emitter out{scene, next_id};
    if (const auto* p = std::get_if<SphereClusterParams>(&plan.params)) {
        generateSphereCluster(*p, rng, out);
    } else if (const auto* p = std::get_if<CityParams>(&plan.params)) {
        generateCity(*p, rng, out);
    } else if (const auto* p = std::get_if<ForestParams>(&plan.params)) {
        generateForest(*p, rng, out);
    } else if (const auto* p = std::get_if<RoomsParams>(&plan.params)) {
        generateRooms(*p, rng, scene, next_id);
    } else if (const auto* p = std::get_if<MeshCrowdParams>(&plan.params)) {
        generateMeshCrowd(*p, rng, out);
    } else if (const auto* p = std::get_if<PlantParams>(&plan.params)) {
        generatePlant(*p, rng, scene, next_id);
    }
}

}  // namespace gridcull
