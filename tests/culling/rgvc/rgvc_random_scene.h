// Seeded random 2D scenes for the rgvc tests: circles, boxes (some thin and
// long, like walls) and polygons (star-shaped, some concave), static and moving
// (linear, random walk, keyframes), some sticking out of the grid or lying
// wholly outside it; square and non-square voxels; a camera path over 20 frames
// of 0.1 s with viewpoints inside and outside the grid, on voxel faces and
// corners, now and then inside an object or teleporting; fov from 10 to 360
// degrees; far anywhere from inside the grid to beyond it.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "culling/scene/random_walk.h"
#include "culling/scene/scene.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull::test {

constexpr int kRgvcFrames = 20;
constexpr double kRgvcDt = 0.1;

// A point of the world box, or on a voxel face or corner of the scene's grid,
// or outside the world.
inline glm::dvec3 rgvcRandomViewpoint(SeededRandom& rng, const Scene& scene) {
    const Aabb& w = scene.grid.world;
    const glm::dvec3 d = scene.grid.voxelSize();
    const glm::dvec3 e = w.extent();
    const double kind = rng.uniform();
    glm::dvec3 p{rng.uniform(w.min.x, w.max.x), rng.uniform(w.min.y, w.max.y), 0.0};
    if (kind < 0.25) {
        // Outside the grid, up to 40% of its size away.
        p = {rng.uniform(w.min.x - 0.4 * e.x, w.max.x + 0.4 * e.x),
             rng.uniform(w.min.y - 0.4 * e.y, w.max.y + 0.4 * e.y), 0.0};
    } else if (kind < 0.55) {
        // On a voxel face (one coordinate on a grid line) or corner (both).
        const int i = int(rng.below(uint64_t(scene.grid.resolution.x) + 1));
        const int j = int(rng.below(uint64_t(scene.grid.resolution.y) + 1));
        const double gx = w.min.x + i * d.x, gy = w.min.y + j * d.y;
        const double sub = rng.uniform();
        if (sub < 0.4)
            p.x = gx;
        else if (sub < 0.8)
            p.y = gy;
        else
            p = {gx, gy, 0.0};
    } else if (kind < 0.6 && !scene.objects.empty()) {
        p = scene.objects[rng.below(scene.objects.size())].anchor;
    }
    return p;
}

// Thresholds on a uniform draw: below `still` the object stays, below `linear`
// it moves in a straight line, below `random` on a random walk, else on three
// keyframes.
struct RgvcMotionMix {
    double still, linear, random;
};

// Gives `o` a motion of the kind `draw` picks from `mix`, at up to `speed`.
inline void rgvcRandomMotion(SeededRandom& rng, SceneObject& o, int dimensions, uint64_t seed,
                             double draw, double speed, RgvcMotionMix mix) {
    if (draw < mix.still) return;
    if (draw < mix.linear) {
        o.motion.kind = MotionKind::Linear;
        o.motion.velocity = randomDirection(rng, dimensions) * speed;
        o.motion.max_speed = glm::length(o.motion.velocity);
    } else if (draw < mix.random) {
        o.motion.kind = MotionKind::Random;
        o.motion.max_speed = speed;
        buildRandomWalk(o.motion, dimensions, seed, o.id, 8, 0.3);
    } else {
        o.motion.kind = MotionKind::Keyframes;
        glm::dvec3 p = o.anchor;
        double best = 0.0;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 next = p + randomDirection(rng, dimensions) * (speed * 0.7);
            o.motion.keys.push_back(PositionKey{0.7 * k, p});
            if (k > 0)
                best = std::max(best, glm::length(p - o.motion.keys[size_t(k) - 1].position) / 0.7);
            p = next;
        }
        o.motion.max_speed = best;
    }
}

// Ends the camera path with a teleport to `to`, looking at `target`: two keys
// a hair apart in time, far apart in space; the path is rescaled so that the
// teleport falls inside `duration` seconds (the scene's frames).
inline void rgvcAppendTeleport(Scene& scene, const glm::dvec3& to, const glm::dvec3& target,
                               double duration) {
    CameraKey a = scene.camera.path.back(), b;
    a.t = scene.camera.path.back().t + 0.95;
    b.t = a.t + 1e-3;
    b.position = to;
    b.target = target;
    scene.camera.path.push_back(a);
    scene.camera.path.push_back(b);
    const double scale = (duration - 0.2) / scene.camera.path.back().t;
    for (CameraKey& key : scene.camera.path) key.t *= scale;
}

inline Scene rgvcRandomScene(uint64_t seed) {
    SeededRandom rng(seed);
    const double width = rng.uniform(40.0, 160.0);
    const double height = rng.uniform() < 0.3 ? width : rng.uniform(40.0, 160.0);
    const glm::dvec3 lo{rng.uniform(-50.0, 50.0), rng.uniform(-50.0, 50.0), 0.0};
    const int res_x = 4 + int(rng.below(61));
    // Square voxels most of the time, any shape now and then.
    const int res_y = rng.uniform() < 0.7 ? std::max(1, int(std::lround(res_x * height / width)))
                                          : 4 + int(rng.below(61));
    Scene scene = makeScene(2, Aabb{lo, lo + glm::dvec3(width, height, 0.0)}, {res_x, res_y, 1});
    scene.seed = seed;
    scene.frames = kRgvcFrames;
    scene.dt = kRgvcDt;
    const double size = std::min(width, height);
    const glm::dvec3 voxel = scene.grid.voxelSize();
    const int count = 1 + int(rng.below(40));
    for (int id = 0; id < count; ++id) {
        // Mostly inside the world; some straddle its edge or lie beyond it.
        const double margin = rng.uniform() < 0.15 ? 0.2 : 0.0;
        const glm::dvec3 c{rng.uniform(lo.x - margin * width, lo.x + (1 + margin) * width),
                           rng.uniform(lo.y - margin * height, lo.y + (1 + margin) * height), 0.0};
        const double kind = rng.uniform();
        if (kind < 0.35) {
            addSphere(scene, id, c, rng.uniform(0.1, 0.12 * size));
        } else if (kind < 0.55) {
            const glm::dvec3 half{rng.uniform(0.1, 0.1 * size), rng.uniform(0.1, 0.1 * size), 0.0};
            addBox(scene, id, c - half, c + half);
        } else if (kind < 0.7) {
            // A wall: long and one to three voxels thick.
            const double len = rng.uniform(0.1, 0.5) * size;
            const double thick = rng.uniform(0.5, 3.0) * std::max(voxel.x, voxel.y);
            const glm::dvec3 half = rng.uniform() < 0.5 ? glm::dvec3(len, thick, 0) * 0.5
                                                        : glm::dvec3(thick, len, 0) * 0.5;
            addBox(scene, id, c - half, c + half);
        } else {
            // A star-shaped polygon around c (concave with 5 or more corners).
            const int corners = 3 + int(rng.below(7));
            const double reach = rng.uniform(0.5, 0.12 * size);
            std::vector<glm::dvec3> points;
            for (int k = 0; k < corners; ++k) {
                const double angle = (k + rng.uniform(0.0, 0.8)) * 6.283185307179586 / corners;
                const double r = reach * rng.uniform(0.3, 1.0);
                points.push_back(c + glm::dvec3(std::cos(angle), std::sin(angle), 0) * r);
            }
            addPolygon(scene, id, points);
        }
        const double motion = rng.uniform();
        const double speed = rng.uniform(0.0, 0.4) * size;  // world units per second
        rgvcRandomMotion(rng, scene.objects.back(), 2, seed, motion, speed, {0.45, 0.75, 0.9});
    }
    scene.finalize();

    // The camera: fov from a list of awkward values or at random, far anything.
    static const double kFovs[] = {10, 30, 60, 90, 120, 179, 180, 181, 270, 359, 360};
    scene.camera.fov_deg = rng.uniform() < 0.5 ? kFovs[rng.below(11)] : rng.uniform(10.0, 360.0);
    const double diag = std::hypot(width, height);
    scene.camera.far = rng.uniform() < 0.6 ? 1000.0 : rng.uniform(0.1, 1.5) * diag;
    scene.camera.near = 0.1;
    const double duration = kRgvcFrames * kRgvcDt;
    const int keys = 1 + int(rng.below(3));
    for (int k = 0; k < keys; ++k) {
        CameraKey key;
        key.t = keys == 1 ? 0.0 : duration * k / (keys - 1);
        key.position = rgvcRandomViewpoint(rng, scene);
        key.target =
            glm::dvec3(rng.uniform(lo.x, lo.x + width), rng.uniform(lo.y, lo.y + height), 0);
        if (rng.uniform() < 0.1) key.target = key.position;  // no direction: looks along +x
        scene.camera.path.push_back(key);
    }
    if (rng.uniform() < 0.15) {
        const glm::dvec3 to = rgvcRandomViewpoint(rng, scene);
        const glm::dvec3 target(rng.uniform(lo.x, lo.x + width), rng.uniform(lo.y, lo.y + height),
                                0);
        rgvcAppendTeleport(scene, to, target, duration);
    }
    return scene;
}

}  // namespace gridcull::test
