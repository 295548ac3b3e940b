// Scenes for the extremes suite (extremes_*_test.cpp). The usual worlds are
// [0, 100]^3 in 10^3 voxels and [0, 100]^2 in 10 x 10 voxels (a voxel is 10
// units), so "on a voxel face" means a coordinate that is a multiple of 10.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull::test {

constexpr double kDt = 0.04;

inline Camera makeCamera(int dimensions, const glm::dvec3& position, const glm::dvec3& target,
                         double fov_deg, double aspect = 1.0, double near = 0.1,
                         double far = 1000.0) {
    Camera camera;
    camera.dimensions = dimensions;
    camera.position = position;
    camera.target = target;
    camera.up = dimensions == 2 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    camera.fov_deg = fov_deg;
    camera.aspect = aspect;
    camera.near = near;
    camera.far = far;
    return camera;
}

// Sets the scene's camera spec from `camera` (one key), so that reset() sizes
// buffers for it.
inline void adoptCamera(Scene& scene, const Camera& camera) {
    scene.camera.fov_deg = camera.fov_deg;
    scene.camera.aspect = camera.aspect;
    scene.camera.near = camera.near;
    scene.camera.far = camera.far;
    scene.camera.path = {CameraKey{0.0, camera.position, camera.target, camera.up}};
}

// Objects on a lattice of voxel corners, spacing two voxels: at (10 + 20 i,
// 10 + 20 j[, 10 + 20 k]) alternately a sphere of radius 3 centred on the
// corner (it straddles 4 or 8 voxels) and a box filling exactly the voxel whose
// min corner it is. Every fifth object moves (linear), so that stateful cullers
// have dynamic objects to track. Ids from 0 in lattice order.
inline Scene latticeScene(int dimensions) {
    Scene scene = dimensions == 3 ? scene3d() : scene2d();
    int id = 0;
    const int kz = dimensions == 3 ? 5 : 1;
    for (int k = 0; k < kz; ++k) {
        for (int j = 0; j < 5; ++j) {
            for (int i = 0; i < 5; ++i) {
                const glm::dvec3 p{10.0 + 20 * i, 10.0 + 20 * j,
                                   dimensions == 3 ? 10.0 + 20 * k : 0.0};
                if ((i + j + k) % 2 == 0) {
                    addSphere(scene, id, p, 3.0);
                } else {
                    const glm::dvec3 size =
                        dimensions == 3 ? glm::dvec3(10.0) : glm::dvec3(10, 10, 0);
                    addBox(scene, id, p, p + size);
                }
                if (id % 5 == 4) {
                    scene.objects.back().motion.kind = MotionKind::Linear;
                    scene.objects.back().motion.velocity =
                        dimensions == 3 ? glm::dvec3(7, -5, 3) : glm::dvec3(7, -5, 0);
                    scene.objects.back().motion.max_speed =
                        glm::length(scene.objects.back().motion.velocity);
                }
                ++id;
            }
        }
    }
    return scene;
}

// A seeded random scene over `world` (2D when world.min.z == world.max.z):
// spheres, boxes and thin walls (2D also polygons), sizes relative to the
// world, a third of them moving. Ids from 0.
inline void addRandomObjects(Scene& scene, SeededRandom& rng, int count) {
    const Aabb w = scene.grid.world;
    const glm::dvec3 e = w.extent();
    const double size = std::max(e.x, e.y) * 0.04;
    const bool flat = scene.dimensions == 2;
    auto point = [&]() {
        return glm::dvec3{rng.uniform(w.min.x, w.max.x), rng.uniform(w.min.y, w.max.y),
                          flat ? 0.0 : rng.uniform(w.min.z, w.max.z)};
    };
    int id = int(scene.objects.size());
    for (int n = 0; n < count; ++n, ++id) {
        const glm::dvec3 c = point();
        const double kind = rng.uniform();
        if (kind < 0.35) {
            addSphere(scene, id, c, rng.uniform(0.2, 1.5) * size);
        } else if (kind < 0.7 || !flat) {
            // Boxes, a third of them thin walls along one axis.
            glm::dvec3 half{rng.uniform(0.2, 1.5) * size, rng.uniform(0.2, 1.5) * size,
                            flat ? 0.0 : rng.uniform(0.2, 1.5) * size};
            if (rng.uniform() < 0.33) {
                const int axis = int(rng.below(flat ? 2 : 3));
                half[axis] = size * 0.05;
                half[(axis + 1) % (flat ? 2 : 3)] = size * 4.0;
            }
            addBox(scene, id, c - half, c + half);
        } else {
            // A star-shaped polygon: simple and counter-clockwise.
            const int corners = 3 + int(rng.below(6));
            std::vector<glm::dvec3> points;
            for (int k = 0; k < corners; ++k) {
                const double angle = (k + rng.uniform(0.0, 0.8)) * 6.283185307179586 / corners;
                const double radius = rng.uniform(0.3, 1.5) * size;
                points.push_back(c + glm::dvec3(std::cos(angle), std::sin(angle), 0) * radius);
            }
            addPolygon(scene, id, points);
        }
        if (rng.uniform() < 0.33) {
            Motion& m = scene.objects.back().motion;
            m.kind = MotionKind::Linear;
            m.velocity = glm::dvec3{rng.uniform(-1, 1), rng.uniform(-1, 1),
                                    flat ? 0.0 : rng.uniform(-1, 1)} *
                         size * 2.0;
            m.max_speed = glm::length(m.velocity);
        }
    }
}

// A wall across the view with one rectangular hole: the slab `lo`..`hi` on the
// `depth_axis` (z in 3D, y in 2D) covering [0, 100] on the other axes, minus
// the hole [hole_min, hole_max] (on the other axes; in 2D only x counts).
// Adds 4 boxes in 3D, 2 in 2D, ids from `first_id`.
inline void addWallWithHole(Scene& scene, int first_id, double lo, double hi,
                            const glm::dvec3& hole_min, const glm::dvec3& hole_max) {
    if (scene.dimensions == 2) {
        addBox(scene, first_id, {0, lo, 0}, {hole_min.x, hi, 0});
        addBox(scene, first_id + 1, {hole_max.x, lo, 0}, {100, hi, 0});
        return;
    }
    addBox(scene, first_id, {0, 0, lo}, {hole_min.x, 100, hi});
    addBox(scene, first_id + 1, {hole_max.x, 0, lo}, {100, 100, hi});
    addBox(scene, first_id + 2, {hole_min.x, 0, lo}, {hole_max.x, hole_min.y, hi});
    addBox(scene, first_id + 3, {hole_min.x, hole_max.y, lo}, {hole_max.x, 100, hi});
}

}  // namespace gridcull::test
