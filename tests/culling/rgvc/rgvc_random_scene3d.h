// Seeded random 3D scenes for the rgvc tests: walls and big boxes (occluders),
// spheres, boxes and meshes (closed cubes and tetrahedra, an open quad, now and
// then a closed mesh with a concave notch), static and moving (linear, random
// walk, keyframes that may leave the world), some sticking out of the grid or
// lying wholly outside it; cubic and stretched voxels; a camera path over 20
// frames of 0.1 s with viewpoints inside and outside the grid, on voxel faces,
// edges and corners, inside objects, now and then teleporting; fov from 10 to
// 150 degrees, any aspect, near from 0.01 to several voxels, far anywhere.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "culling/scene/random_walk.h"
#include "culling/scene/scene.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/rgvc/rgvc_random_scene.h"

namespace gridcull::test {

constexpr int kRgvc3dFrames = 20;
constexpr double kRgvc3dDt = 0.1;

// A closed L-shaped prism (a cube with a notch), so that interiors of
// non-convex meshes are exercised.
inline std::shared_ptr<TriangleMesh> notchedMesh(double h) {
    // Two boxes glued along a face would not be a single closed surface; this
    // is one: the L profile (x, y) extruded along z, 8 profile corners.
    const double a = h, b = 0.2 * h;
    const std::vector<glm::dvec2> profile = {{-a, -a}, {a, -a}, {a, b}, {b, b},
                                             {b, a},   {-a, a}};
    std::vector<glm::dvec3> v;
    for (const double z : {-a, a})
        for (const glm::dvec2& p : profile) v.push_back({p.x, p.y, z});
    const uint32_t n = uint32_t(profile.size());
    std::vector<uint32_t> idx;
    // Caps: a fan from corner 0 (the profile is star-shaped from (-a, -a)).
    for (uint32_t i = 1; i + 1 < n; ++i) {
        idx.insert(idx.end(), {0, i + 1, i});          // bottom, facing -z
        idx.insert(idx.end(), {n, n + i, n + i + 1});  // top, facing +z
    }
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t j = (i + 1) % n;
        idx.insert(idx.end(), {i, j, n + j});
        idx.insert(idx.end(), {i, n + j, n + i});
    }
    return finishMesh(v, idx, true);
}

inline glm::dvec3 rgvc3dPoint(SeededRandom& rng, const Aabb& box) {
    return {rng.uniform(box.min.x, box.max.x), rng.uniform(box.min.y, box.max.y),
            rng.uniform(box.min.z, box.max.z)};
}

// A point of the world, or on a voxel face, edge or corner, or outside the world.
inline glm::dvec3 rgvc3dViewpoint(SeededRandom& rng, const Scene& scene) {
    const Aabb& w = scene.grid.world;
    const glm::dvec3 d = scene.grid.voxelSize(), e = w.extent();
    const double kind = rng.uniform();
    glm::dvec3 p = rgvc3dPoint(rng, w);
    if (kind < 0.25) {
        p = rgvc3dPoint(rng, Aabb{w.min - 0.4 * e, w.max + 0.4 * e});
    } else if (kind < 0.55) {
        // Snap one, two or three coordinates onto grid planes.
        const int snap = 1 + int(rng.below(3));
        for (int k = 0; k < snap; ++k) {
            const int a = int(rng.below(3));
            const int i = int(rng.below(uint64_t(scene.grid.resolution[a]) + 1));
            p[a] = w.min[a] + i * d[a];
        }
    } else if (kind < 0.65 && !scene.objects.empty()) {
        p = scene.objects[rng.below(scene.objects.size())].bounds.center();
    }
    return p;
}

inline Scene rgvcRandomScene3d(uint64_t seed) {
    SeededRandom rng(seed);
    const glm::dvec3 size{rng.uniform(40.0, 160.0), rng.uniform(30.0, 120.0),
                          rng.uniform(40.0, 160.0)};
    const glm::dvec3 lo{rng.uniform(-50.0, 50.0), rng.uniform(-50.0, 50.0),
                        rng.uniform(-50.0, 50.0)};
    glm::ivec3 res;
    const int base = 4 + int(rng.below(37));
    const double longest = std::max({size.x, size.y, size.z});
    for (int a = 0; a < 3; ++a)
        res[a] = rng.uniform() < 0.7 ? std::max(1, int(std::lround(base * size[a] / longest)))
                                     : 2 + int(rng.below(39));
    Scene scene = makeScene(3, Aabb{lo, lo + size}, res);
    scene.seed = seed;
    scene.frames = kRgvc3dFrames;
    scene.dt = kRgvc3dDt;
    const Aabb world = scene.grid.world;
    const Aabb wide{world.min - 0.2 * size, world.max + 0.2 * size};
    const double small = std::min({size.x, size.y, size.z});
    const glm::dvec3 voxel = scene.grid.voxelSize();
    int id = 0;
    // Walls: most thick enough to hold whole voxels (the occluders), some thinner
    // than a voxel (spanned but never opaque).
    const int walls = int(rng.below(8));
    for (int k = 0; k < walls; ++k) {
        const glm::dvec3 c = rgvc3dPoint(rng, world);
        glm::dvec3 half = 0.5 * size * glm::dvec3(rng.uniform(0.2, 0.8), rng.uniform(0.2, 0.8),
                                                  rng.uniform(0.2, 0.8));
        const double thick = rng.uniform() < 0.8 ? rng.uniform(1.2, 3.0) : rng.uniform(0.3, 1.0);
        half[int(rng.below(3))] = 0.5 * thick * std::max({voxel.x, voxel.y, voxel.z});
        addBox(scene, id++, c - half, c + half);
    }
    const int count = 1 + int(rng.below(40));
    for (int k = 0; k < count; ++k) {
        const glm::dvec3 c = rgvc3dPoint(rng, rng.uniform() < 0.15 ? wide : world);
        const double kind = rng.uniform();
        const double r = rng.uniform(0.05, 0.15) * small;
        if (kind < 0.4) {
            addSphere(scene, id++, c, r);
        } else if (kind < 0.75) {
            const glm::dvec3 half{rng.uniform(0.1, r), rng.uniform(0.1, r), rng.uniform(0.1, r)};
            addBox(scene, id++, c - half, c + half);
        } else {
            const double shape = rng.uniform();
            addMesh(scene, id++, c,
                    shape < 0.35  ? cubeMesh(r)
                    : shape < 0.6 ? tetrahedronMesh(r)
                    : shape < 0.8 ? notchedMesh(r)
                                  : quadMesh(r));
        }
        const double motion = rng.uniform();
        const double speed = rng.uniform(0.0, 0.3) * small;
        rgvcRandomMotion(rng, scene.objects.back(), 3, seed, motion, speed, {0.4, 0.7, 0.85});
    }
    scene.finalize();

    static const double kFovs[] = {10, 30, 60, 90, 120, 150};
    scene.camera.fov_deg = rng.uniform() < 0.5 ? kFovs[rng.below(6)] : rng.uniform(10.0, 150.0);
    scene.camera.aspect = rng.uniform(0.4, 2.5);
    scene.camera.near = rng.uniform() < 0.2 ? rng.uniform(0.5, 3.0) * voxel.x : 0.01 * voxel.x;
    scene.camera.far =
        rng.uniform() < 0.6 ? 1000.0 : rng.uniform(0.1, 1.5) * glm::length(size);
    const double duration = kRgvc3dFrames * kRgvc3dDt;
    const int keys = 1 + int(rng.below(3));
    for (int k = 0; k < keys; ++k) {
        CameraKey key;
        key.t = keys == 1 ? 0.0 : duration * k / (keys - 1);
        key.position = rgvc3dViewpoint(rng, scene);
        key.target = rgvc3dPoint(rng, world);
        if (rng.uniform() < 0.05) key.target = key.position;  // no direction
        if (rng.uniform() < 0.1) key.up = randomDirection(rng, 3);
        scene.camera.path.push_back(key);
    }
    if (rng.uniform() < 0.15) {
        const glm::dvec3 to = rgvc3dViewpoint(rng, scene);
        const glm::dvec3 target = rgvc3dPoint(rng, world);
        rgvcAppendTeleport(scene, to, target, duration);
    }
    return scene;
}

}  // namespace gridcull::test
