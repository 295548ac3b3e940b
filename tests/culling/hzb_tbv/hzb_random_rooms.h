// Seeded random room scenes for the octree + hierarchical z-buffer tests: the
// paper's test scene (the `rooms` generator: rooms joined by doors, a table per
// room, chairs circling it on keyframed loops) at a random size, plus movers
// of every other kind (linear and random-walk spheres, boxes and meshes, some
// crossing walls, some leaving the world, some fast), and a camera that walks
// through the rooms at eye height or looks down from above the walls, now and
// then from inside an object or with a deep near plane; 30 frames of 0.1 s.
#pragma once
#include <cstdint>

#include <glm/geometric.hpp>

#include "culling/generators/scene_generators.h"
#include "culling/scene/random_walk.h"
#include "culling/scene/scene.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull::test {

constexpr int kHzbRoomFrames = 30;
constexpr double kHzbRoomDt = 0.1;

inline Scene hzbRandomRooms(uint64_t seed) {
    SeededRandom rng(seed);
    Scene scene = makeScene(3, Aabb{{0, 0, 0}, {100, 40, 100}}, {10, 4, 10});
    scene.seed = seed;
    scene.dt = kHzbRoomDt;
    scene.frames = kHzbRoomFrames;
    const double duration = kHzbRoomFrames * kHzbRoomDt;
    RoomsParams rooms;
    rooms.rooms_x = 1 + int64_t(rng.below(4));
    rooms.rooms_z = 1 + int64_t(rng.below(4));
    rooms.room_size = rng.uniform(8.0, 24.0);
    rooms.wall_thickness = rng.uniform(0.1, 1.0);
    rooms.door_width = rng.uniform(0.5, 0.6 * rooms.room_size);
    rooms.chairs_per_room = int64_t(rng.below(7));
    rooms.chair_speed = rng.uniform(0.2, 6.0);
    int id = 0;
    generateRooms(rooms, rng, scene, id);

    // Other movers, anywhere in the world and beyond it.
    const int movers = int(rng.below(40));
    for (int k = 0; k < movers; ++k) {
        const glm::dvec3 c{rng.uniform(-10.0, 110.0), rng.uniform(0.0, 12.0),
                           rng.uniform(-10.0, 110.0)};
        const double kind = rng.uniform();
        if (kind < 0.5) {
            addSphere(scene, id++, c, rng.uniform(0.2, 2.5));
        } else if (kind < 0.85) {
            const glm::dvec3 half{rng.uniform(0.2, 2.0), rng.uniform(0.2, 2.0),
                                  rng.uniform(0.2, 2.0)};
            addBox(scene, id++, c - half, c + half);
        } else {
            const double size = rng.uniform(0.4, 2.5);
            addMesh(scene, id++, c, rng.uniform() < 0.6 ? cubeMesh(size) : tetrahedronMesh(size));
        }
        Motion& m = scene.objects.back().motion;
        const double speed = rng.uniform() < 0.1 ? rng.uniform(20.0, 60.0) : rng.uniform(0.0, 6.0);
        if (rng.uniform() < 0.6) {
            m.kind = MotionKind::Linear;
            glm::dvec3 dir{rng.uniform(-1.0, 1.0), rng.uniform(-0.2, 0.2), rng.uniform(-1.0, 1.0)};
            if (glm::length(dir) < 1e-6) dir = {1, 0, 0};
            m.velocity = glm::normalize(dir) * speed;
            m.max_speed = speed;
        } else {
            m.kind = MotionKind::Random;
            m.max_speed = speed;
            buildRandomWalk(m, 3, seed, scene.objects.back().id, 8, duration / 8.0);
        }
    }

    // The camera: at eye height among the rooms (or above the walls), turning.
    const double span = double(std::max(rooms.rooms_x, rooms.rooms_z)) * rooms.room_size;
    const glm::dvec3 centre{50.0, 0.0, 50.0};
    auto spot = [&](double height) {
        return glm::dvec3{centre.x + rng.uniform(-0.6, 0.6) * span, height,
                          centre.z + rng.uniform(-0.6, 0.6) * span};
    };
    const double eye = rng.uniform() < 0.25 ? rng.uniform(0.4, 2.0) * rooms.room_size
                                            : rng.uniform(0.5, 0.25 * rooms.room_size);
    const double fov = rng.uniform(30.0, 110.0);
    const double near = rng.uniform() < 0.1 ? rng.uniform(0.5, 3.0) : 0.1;
    setCamera(scene, spot(eye), spot(0.0), fov, near,
              rng.uniform() < 0.2 ? rng.uniform(10.0, 40.0) : 500.0);
    scene.camera.aspect = rng.uniform(0.6, 2.2);
    const int keys = 1 + int(rng.below(4));
    for (int k = 1; k <= keys; ++k)
        scene.camera.path.push_back(
            CameraKey{duration * k / keys, spot(eye), spot(rng.uniform(0.0, eye)), {0, 1, 0}});
    if (rng.uniform() < 0.08 && !scene.objects.empty()) {
        // Start inside an object.
        const SceneObject& host = scene.objects[size_t(rng.below(uint64_t(scene.objects.size())))];
        scene.camera.path.front().position = host.bounds.center();
    }
    scene.finalize();
    return scene;
}

}  // namespace gridcull::test
