// The `plant` generator, an addition of ours standing in for Kovalcik &
// Sochor's UNC power plant: a dense static industrial site of tanks, platforms,
// pipes, valves and pipe racks whose sizes spread over more than two orders of
// magnitude (layout and sizes in scene_generators.h, "plant"). Deterministic
// from the random stream it is given; makes exactly plantObjectCount objects.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "culling/generators/scene_emitter.h"
#include "culling/generators/scene_generators.h"
#include "culling/scene/seeded_random.h"

namespace gridcull {

namespace {

using PlantEmitter = SceneEmitter;

// A box of square section `width` around the segment from `from` to `to`,
// which differ on one axis only.
Aabb pipeBox(const glm::dvec3& from, const glm::dvec3& to, double width) {
    Aabb box;
    for (int axis = 0; axis < 3; ++axis) {
        box.min[axis] = std::min(from[axis], to[axis]);
        box.max[axis] = std::max(from[axis], to[axis]);
        if (box.min[axis] == box.max[axis]) {
            box.min[axis] -= 0.5 * width;
            box.max[axis] += 0.5 * width;
        }
    }
    return box;
}

// Valve cubes are this many pipe widths wide.
constexpr double kValveWidths = 2.5;

// A pipe from `from` to `to` and its valves: cubes centred on its axis at
// uniform points kept half a valve off its ends (its middle if it is shorter).
void addPipe(const glm::dvec3& from, const glm::dvec3& to, double width, int64_t valves,
             SeededRandom& rng, PlantEmitter& out) {
    out.addBox(pipeBox(from, to, width));
    const double half = 0.5 * kValveWidths * width;
    const double length = glm::length(to - from);
    for (int64_t v = 0; v < valves; ++v) {
        const double s = length > 2.0 * half ? rng.uniform(half, length - half) : 0.5 * length;
        const glm::dvec3 at = from + (to - from) * (s / length);
        out.addBox({at - glm::dvec3(half), at + glm::dvec3(half)});
    }
}

void addTanks(const PlantParams& p, double ux, double uz, double ground, SeededRandom& rng,
              PlantEmitter& out) {
    if (p.tanks_per_unit == 0) return;
    const int64_t cols = int64_t(std::ceil(std::sqrt(double(p.tanks_per_unit))));
    const int64_t rows = (p.tanks_per_unit + cols - 1) / cols;
    const double cell_x = p.unit_size / double(cols);
    const double cell_z = 0.5 * p.unit_size / double(rows);
    const double cell = std::min(cell_x, cell_z);
    for (int64_t k = 0; k < p.tanks_per_unit; ++k) {
        const double cx = ux + (double(k % cols) + 0.5) * cell_x;
        const double cz = uz + (double(k / cols) + 0.5) * cell_z;
        const double height = rng.uniform(p.tank_height_min, p.tank_height_max);
        const bool sphere = rng.below(3) == 0;
        const double size = rng.uniform();
        if (sphere) {
            const double r = std::min(cell * (0.3 + 0.1 * size), 0.5 * height);
            out.addSphere({cx, ground + r, cz}, r);
        } else {
            const double half = 0.5 * cell * (0.4 + 0.4 * size);
            out.addBox({{cx - half, ground, cz - half}, {cx + half, ground + height, cz + half}});
        }
    }
}

void addPlatforms(const PlantParams& p, double ux, double uz, double ground, SeededRandom& rng,
                  PlantEmitter& out) {
    const double s = p.unit_size;
    for (int64_t k = 0; k < p.platforms_per_unit; ++k) {
        const double wx = s * rng.uniform(0.25, 0.5), wz = s * rng.uniform(0.15, 0.35);
        const double x = rng.uniform(ux, ux + s - wx);
        const double z = rng.uniform(uz + 0.5 * s, uz + s - wz);
        const double y = ground + p.tank_height_min * rng.uniform(0.2, 0.8);
        out.addBox({{x, y, z}, {x + wx, y + p.pipe_width_max, z + wz}});
        const double leg = p.pipe_width_min;
        for (int corner = 0; corner < 4; ++corner) {
            const double lx = corner & 1 ? x + wx - leg : x;
            const double lz = corner & 2 ? z + wz - leg : z;
            out.addBox({{lx, ground, lz}, {lx + leg, y, lz + leg}});
        }
    }
}

void addUnitPipes(const PlantParams& p, double ux, double uz, double ground, SeededRandom& rng,
                  PlantEmitter& out) {
    const double s = p.unit_size;
    const double margin = 0.5 * kValveWidths * p.pipe_width_max;
    for (int64_t k = 0; k < p.pipes_per_unit; ++k) {
        const double width = rng.uniform(p.pipe_width_min, p.pipe_width_max);
        const int axis = int(rng.below(3));
        const double level = ground + p.tank_height_min * double(1 + rng.below(4)) / 5.0;
        glm::dvec3 from{rng.uniform(ux + margin, ux + s - margin), level,
                        rng.uniform(uz + margin, uz + s - margin)};
        glm::dvec3 to = from;
        if (axis == 1) {
            from.y = ground;
        } else {
            const double length = s * rng.uniform(0.3, 1.0);
            const double start = rng.uniform(0.0, s - length);
            from[axis] = (axis == 0 ? ux : uz) + start;
            to[axis] = from[axis] + length;
        }
        addPipe(from, to, width, p.valves_per_pipe, rng, out);
    }
}

}  // namespace

int64_t plantObjectCount(const PlantParams& p) {
    const int64_t per_unit =
        p.tanks_per_unit + p.pipes_per_unit * (1 + p.valves_per_pipe) + 5 * p.platforms_per_unit;
    return p.units_x * p.units_z * per_unit + p.rack_pipes * (p.units_x - 1 + p.units_z - 1);
}

void generatePlant(const PlantParams& p, SeededRandom& rng, Scene& scene, int& next_id) {
    PlantEmitter out{scene, next_id};
    const Aabb& world = scene.grid.world;
    const double pitch = p.unit_size + p.aisle_width;
    const double width_x = double(p.units_x) * pitch + p.aisle_width;
    const double width_z = double(p.units_z) * pitch + p.aisle_width;
    const double site_x = world.center().x - 0.5 * width_x;
    const double site_z = world.center().z - 0.5 * width_z;
    const double ground = world.min.y;
    for (int64_t j = 0; j < p.units_z; ++j) {
        for (int64_t i = 0; i < p.units_x; ++i) {
            const double ux = site_x + p.aisle_width + double(i) * pitch;
            const double uz = site_z + p.aisle_width + double(j) * pitch;
            addTanks(p, ux, uz, ground, rng, out);
            addPlatforms(p, ux, uz, ground, rng, out);
            addUnitPipes(p, ux, uz, ground, rng, out);
        }
    }
    // Racks over the inner aisles, the whole site long: along z between unit
    // columns, then along x between unit rows.
    const double rack_y = ground + 0.85 * p.tank_height_min;
    for (int axis : {0, 2}) {
        const int64_t aisles = (axis == 0 ? p.units_x : p.units_z) - 1;
        const double site_lo = axis == 0 ? site_x : site_z;
        const double other_lo = axis == 0 ? site_z : site_x;
        const double other_hi = other_lo + (axis == 0 ? width_z : width_x);
        for (int64_t a = 0; a < aisles; ++a) {
            const double aisle_lo = site_lo + p.aisle_width + double(a) * pitch + p.unit_size;
            for (int64_t k = 0; k < p.rack_pipes; ++k) {
                const double width = rng.uniform(p.pipe_width_min, p.pipe_width_max);
                const double across =
                    aisle_lo + (double(k) + 0.5) * p.aisle_width / double(p.rack_pipes);
                glm::dvec3 from{0.0, rack_y, 0.0};
                from[axis] = across;
                glm::dvec3 to = from;
                const int along = axis == 0 ? 2 : 0;
                from[along] = other_lo;
                to[along] = other_hi;
                out.addBox(pipeBox(from, to, width));
            }
        }
    }
}

}  // namespace gridcull
