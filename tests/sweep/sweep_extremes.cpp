#include "tests/sweep/sweep_extremes.h"

#include <algorithm>
#include <cmath>

#include "culling/scene/seeded_random.h"
#include "tests/culling/registry/extremes_scenes.h"

namespace gridcull::sweep {

namespace {

// A point anywhere in `box` (z = 0 in 2D).
glm::dvec3 pointIn(SeededRandom& rng, const Aabb& box, bool flat) {
    return {rng.uniform(box.min.x, box.max.x), rng.uniform(box.min.y, box.max.y),
            flat ? 0.0 : rng.uniform(box.min.z, box.max.z)};
}

// An eye for the camera: inside an object, on a box face's plane (grazing),
// far outside, or anywhere around the world.
glm::dvec3 eyeFor(SeededRandom& rng, const Scene& scene, glm::dvec3& target) {
    const Aabb& w = scene.grid.world;
    const bool flat = scene.dimensions == 2;
    const glm::dvec3 e = w.extent();
    const int axes = flat ? 2 : 3;
    const double kind = rng.uniform();
    target = pointIn(rng, w, flat);
    if (kind < 0.15 && !scene.objects.empty()) {
        return scene.objects[size_t(rng.below(scene.objects.size()))].bounds.center();
    }
    if (kind < 0.35) {
        for (const SceneObject& o : scene.objects) {
            if (o.shape != ShapeKind::Box || rng.uniform() < 0.5) continue;
            // On the plane of one face, looking along it across the box.
            const int axis = int(rng.below(uint64_t(axes)));
            glm::dvec3 eye = pointIn(rng, Aabb{o.box.min - e * 0.3, o.box.max + e * 0.3}, flat);
            eye[axis] = rng.uniform() < 0.5 ? o.box.min[axis] : o.box.max[axis];
            target = pointIn(rng, o.box, flat);
            target[axis] = eye[axis];
            return eye;
        }
    }
    if (kind < 0.5) {
        const double away = rng.uniform(2.0, 10.0);
        return w.center() + randomDirection(rng, scene.dimensions) * (away * glm::length(e));
    }
    return pointIn(rng, Aabb{w.min - e * 0.3, w.max + e * 0.3}, flat);
}

}  // namespace

Scene extremesScene(uint64_t seed, int dimensions) {
    SeededRandom rng(seed);
    const bool flat = dimensions == 2;
    const double side = 100.0 * std::pow(10.0, rng.uniform(-3.0, 3.0));
    glm::dvec3 lo{0.0};
    if (rng.uniform() < 0.3) lo = pointIn(rng, Aabb{glm::dvec3(-1e6), glm::dvec3(1e6)}, flat);
    const glm::dvec3 size =
        flat ? glm::dvec3(side, side * rng.uniform(0.3, 1.0), 0.0)
             : glm::dvec3(side, side * rng.uniform(0.3, 1.0), side * rng.uniform(0.3, 1.0));
    glm::ivec3 res{2 + int(rng.below(flat ? 63 : 23)), 2 + int(rng.below(flat ? 63 : 23)),
                   flat ? 1 : 2 + int(rng.below(23))};
    Scene scene = test::makeScene(dimensions, Aabb{lo, lo + size}, res);
    scene.seed = seed;
    scene.frames = 20;
    scene.dt = 0.1;
    test::addRandomObjects(scene, rng, 5 + int(rng.below(50)));
    const Aabb w = scene.grid.world;
    const glm::dvec3 voxel = scene.grid.voxelSize();
    const double v = std::max(voxel.x, voxel.y);
    int id = int(scene.objects.size());
    // Specks of a ten-thousandth of a voxel, slivers, and boxes over the world.
    for (int k = int(rng.below(6)); k > 0; --k)
        test::addSphere(scene, id++, pointIn(rng, w, flat), v * 1e-4);
    for (int k = int(rng.below(3)); k > 0; --k) {
        const glm::dvec3 c = pointIn(rng, w, flat);
        glm::dvec3 half = flat ? glm::dvec3(v, v, 0) : glm::dvec3(v);
        half[int(rng.below(flat ? 2 : 3))] = v * 1e-3;
        test::addBox(scene, id++, c - half, c + half);
    }
    if (rng.uniform() < 0.15) {
        const glm::dvec3 grow = size * rng.uniform(0.05, 0.5);
        test::addBox(scene, id++, w.min - grow, w.max + grow);
    }
    scene.finalize();

    static const double kFovs3d[] = {1, 30, 60, 90, 120, 150, 169};
    static const double kFovs2d[] = {1, 45, 90, 180, 270, 359, 360};
    const bool listed = rng.uniform() < 0.5;
    scene.camera.fov_deg = flat ? (listed ? kFovs2d[rng.below(7)] : rng.uniform(1.0, 360.0))
                                : (listed ? kFovs3d[rng.below(7)] : rng.uniform(1.0, 169.0));
    scene.camera.aspect = rng.uniform(0.2, 5.0);
    scene.camera.near = rng.uniform() < 0.3 ? v * 1e-4 : v * rng.uniform(0.01, 2.0);
    scene.camera.far =
        rng.uniform() < 0.5 ? 1e7 : scene.camera.near + side * rng.uniform(0.05, 3.0);
    const double duration = scene.frames * scene.dt;
    const int keys = 1 + int(rng.below(3));
    for (int k = 0; k < keys; ++k) {
        CameraKey key;
        key.t = keys == 1 ? 0.0 : duration * k / (keys - 1);
        key.position = eyeFor(rng, scene, key.target);
        key.up = flat ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
        if (!flat && rng.uniform() < 0.2) key.up = randomDirection(rng, 3);
        scene.camera.path.push_back(key);
    }
    return scene;
}

}  // namespace gridcull::sweep
