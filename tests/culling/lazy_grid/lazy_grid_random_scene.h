// Seeded random 3D scenes for the lazy occlusion grid's differential and
// traversal tests: occluders (walls, large boxes) in front of crowds of small
// spheres, boxes and meshes, some moving, and a camera path through or around
// them, so that much is hidden and the grid's states matter. Now and then the
// camera starts inside an object or with a near plane that cuts into one.
#pragma once
#include <cstdint>

#include <glm/geometric.hpp>

#include "culling/scene/scene.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull::test {

inline glm::dvec3 randomPoint3(SeededRandom& rng, double lo, double hi) {
    return {rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
}

inline Scene lazyGridRandomScene(uint64_t seed) {
    SeededRandom rng(seed);
    Scene scene = scene3d();
    scene.seed = seed;
    scene.dt = 0.1;
    int id = 0;
    // Occluders: walls across the view and big boxes.
    const int walls = 1 + int(rng.below(6));
    for (int w = 0; w < walls; ++w) {
        const glm::dvec3 c = randomPoint3(rng, 10, 90);
        glm::dvec3 half = randomPoint3(rng, 5.0, 35.0);
        half[int(rng.below(3))] = rng.uniform(0.2, 2.0);  // thin along one axis
        addBox(scene, id++, c - half, c + half);
    }
    // The crowd.
    const int count = 5 + int(rng.below(100));
    for (int k = 0; k < count; ++k) {
        const glm::dvec3 c = randomPoint3(rng, 0, 100);
        const double kind = rng.uniform();
        if (kind < 0.45) {
            addSphere(scene, id++, c, rng.uniform(0.3, 4.0));
        } else if (kind < 0.85) {
            const glm::dvec3 half = randomPoint3(rng, 0.2, 4.0);
            addBox(scene, id++, c - half, c + half);
        } else {
            const double size = rng.uniform(0.5, 6.0);
            const double shape = rng.uniform();
            addMesh(scene, id++, c,
                    shape < 0.4   ? cubeMesh(size)
                    : shape < 0.8 ? tetrahedronMesh(size)
                                  : quadMesh(size));
        }
        if (rng.uniform() < 0.35) {
            scene.objects.back().motion.kind = MotionKind::Linear;
            scene.objects.back().motion.velocity = randomPoint3(rng, -15, 15);
            scene.objects.back().motion.max_speed =
                glm::length(scene.objects.back().motion.velocity);
        }
    }
    // The camera path: two keys, inside or outside the world.
    const glm::dvec3 from = randomPoint3(rng, -20, 120);
    const glm::dvec3 to = from + randomPoint3(rng, -40, 40);
    const double fov = rng.uniform(20.0, 120.0);
    const double near = rng.uniform() < 0.15 ? rng.uniform(1.0, 8.0) : 0.1;
    setCamera(scene, from, randomPoint3(rng, 20, 80), fov, near, rng.uniform(60.0, 300.0));
    scene.camera.aspect = rng.uniform(0.5, 2.5);
    scene.camera.path.push_back(CameraKey{2.0, to, randomPoint3(rng, 20, 80), {0, 1, 0}});
    if (rng.uniform() < 0.1) {
        // Start inside an object.
        const SceneObject& host = scene.objects[size_t(rng.below(uint64_t(scene.objects.size())))];
        scene.camera.path.front().position = host.bounds.center();
    }
    scene.frames = 20;
    scene.finalize();
    return scene;
}

}  // namespace gridcull::test
