// Seeded random scenes for the oracle's tests: 2D (odd seeds) and 3D (even),
// spheres, boxes, meshes and polygons, static and moving, cameras inside and
// outside the world, now and then inside an object or with a deep near plane.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull::test {

inline glm::dvec3 randomPoint(SeededRandom& rng, double lo, double hi, int dimensions) {
    return {rng.uniform(lo, hi), rng.uniform(lo, hi), dimensions == 2 ? 0.0 : rng.uniform(lo, hi)};
}

inline Scene oracleRandomScene(uint64_t seed) {
    SeededRandom rng(seed);
    const int dims = seed % 2 == 0 ? 3 : 2;
    const int res = 4 + int(rng.below(17));
    Scene scene = dims == 3 ? makeScene(3, Aabb{{0, 0, 0}, {100, 100, 100}}, {res, res, res})
                            : makeScene(2, Aabb{{0, 0, 0}, {100, 100, 0}}, {res, res, 1});
    const int count = 1 + int(rng.below(30));
    for (int id = 0; id < count; ++id) {
        const glm::dvec3 c = randomPoint(rng, 0, 100, dims);
        const double kind = rng.uniform();
        if (kind < 0.45) {
            addSphere(scene, id, c, rng.uniform(0.5, 8.0));
        } else if (kind < 0.8) {
            const glm::dvec3 half = randomPoint(rng, 0.25, 8.0, dims);
            addBox(scene, id, c - half, c + half);
        } else if (dims == 3) {
            const double size = rng.uniform(1.0, 10.0);
            const double shape = rng.uniform();
            addMesh(scene, id, c,
                          shape < 0.4   ? cubeMesh(size)
                          : shape < 0.8 ? tetrahedronMesh(size)
                                        : quadMesh(size));
        } else {
            // A star-shaped polygon around c: simple and counter-clockwise.
            const int corners = 3 + int(rng.below(6));
            std::vector<glm::dvec3> points;
            for (int k = 0; k < corners; ++k) {
                const double angle = (k + rng.uniform(0.0, 0.8)) * 2.0 * 3.14159265358979 / corners;
                const double radius = rng.uniform(1.0, 10.0);
                points.push_back(c + glm::dvec3(std::cos(angle), std::sin(angle), 0) * radius);
            }
            addPolygon(scene, id, points);
        }
        if (rng.uniform() < 0.3) {
            scene.objects.back().motion.kind = MotionKind::Linear;
            scene.objects.back().motion.velocity = randomPoint(rng, -10, 10, dims);
        }
    }
    // Cameras inside and outside the world, now and then inside an object or
    // with a near plane deep enough to cut into objects.
    glm::dvec3 eye = randomPoint(rng, -30, 130, dims);
    const double placement = rng.uniform();
    const SceneObject& near_object = scene.objects[rng.below(scene.objects.size())];
    if (placement < 0.2) {
        eye = near_object.anchor;
    } else if (placement < 0.4) {
        // Just outside the object's bounds, so that it crosses the eye plane.
        const glm::dvec3 reach = near_object.bounds.extent() * 0.5;
        eye = near_object.anchor + randomPoint(rng, -1, 1, dims) * reach * rng.uniform(1.0, 1.6);
    }
    const double near = rng.uniform() < 0.3 ? rng.uniform(1.0, 8.0) : rng.uniform(0.05, 1.0);
    const glm::dvec3 target = randomPoint(rng, 0, 100, dims);
    const double fov =
        dims == 3 ? rng.uniform(20, 120) : (rng.uniform() < 0.2 ? 360.0 : rng.uniform(20, 360));
    setCamera(scene, eye, target, fov, near, rng.uniform(20, 300));
    scene.camera.aspect = rng.uniform(0.5, 2.5);
    scene.finalize();
    return scene;
}

}  // namespace gridcull::test
