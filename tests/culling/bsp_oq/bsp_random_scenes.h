// Seeded random scenes for the BSP culling tests: what Kovalčík & Sochor's
// method works on, at a random size. A crowd of complex meshes (bumpy closed
// spheres and open wavy sheets of a few hundred triangles, so that each gets
// a BSP tree of its own at the tests' leaf threshold) moving in straight
// lines through each other and through static boxes (walls, pillars, crates:
// the industrial plant's clutter), some starting outside the world, some
// fast; spheres and small boxes without trees; a camera that flies among them
// with turns, now and then from inside an object or with a deep near plane;
// 30 frames of 0.1 s.
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>

#include "culling/scene/scene.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull::test {

constexpr int kBspFrames = 30;
constexpr double kBspDt = 0.1;
// The leaf threshold these scenes are meant for: their meshes have 96 to 800
// triangles, so trees of 2 to 5 levels.
constexpr int kBspTestLeafTriangles = 48;

// A closed sphere of `slices` x `stacks` quads with its radius varied by
// `bump`, radius about r, centred on the origin.
inline std::shared_ptr<TriangleMesh> bumpySphereMesh(SeededRandom& rng, double r, int slices,
                                                     int stacks, double bump) {
    std::vector<glm::dvec3> v;
    std::vector<uint32_t> idx;
    const double phase = rng.uniform(0.0, 6.28), waves = double(1 + rng.below(5));
    v.push_back({0, r, 0});
    for (int i = 1; i < stacks; ++i) {
        const double theta = M_PI * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2.0 * M_PI * j / slices;
            const double rr =
                r * (1.0 + bump * std::sin(waves * phi + phase) * std::sin(theta * 3));
            v.push_back({rr * std::sin(theta) * std::cos(phi), rr * std::cos(theta),
                         rr * std::sin(theta) * std::sin(phi)});
        }
    }
    v.push_back({0, -r, 0});
    const auto ring = [&](int i, int j) { return uint32_t(1 + (i - 1) * slices + (j % slices)); };
    for (int j = 0; j < slices; ++j) idx.insert(idx.end(), {0, ring(1, j + 1), ring(1, j)});
    for (int i = 1; i + 1 < stacks; ++i)
        for (int j = 0; j < slices; ++j)
            idx.insert(idx.end(), {ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i, j),
                                   ring(i + 1, j + 1), ring(i + 1, j)});
    const uint32_t bottom = uint32_t(v.size() - 1);
    for (int j = 0; j < slices; ++j)
        idx.insert(idx.end(), {bottom, ring(stacks - 1, j), ring(stacks - 1, j + 1)});
    return finishMesh(v, idx, true);
}

// An open sheet of n x n quads, side s, waving in y by up to `amp`.
inline std::shared_ptr<TriangleMesh> wavySheetMesh(SeededRandom& rng, double s, int n, double amp) {
    std::vector<glm::dvec3> v;
    std::vector<uint32_t> idx;
    const double k = rng.uniform(0.5, 3.0);
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const double x = s * (double(i) / n - 0.5), z = s * (double(j) / n - 0.5);
            v.push_back({x, amp * std::sin(k * x) * std::cos(k * z), z});
        }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const uint32_t a = uint32_t(i * (n + 1) + j), b = a + 1, c = a + uint32_t(n + 1),
                           d = c + 1;
            idx.insert(idx.end(), {a, b, d, a, d, c});
        }
    return finishMesh(v, idx, false);
}

inline Scene bspRandomScene(uint64_t seed) {
    SeededRandom rng(seed);
    const double side = rng.uniform(20.0, 80.0);
    Scene scene = makeScene(3, Aabb{{0, 0, 0}, {side, side * 0.5, side}}, {8, 4, 8});
    scene.seed = seed;
    scene.dt = kBspDt;
    scene.frames = kBspFrames;
    int id = 0;
    auto somewhere = [&](double margin) {
        return glm::dvec3{rng.uniform(-margin, side + margin), rng.uniform(0.0, side * 0.5),
                          rng.uniform(-margin, side + margin)};
    };

    // Static clutter: walls, pillars and crates.
    const int statics = int(rng.below(60));
    for (int k = 0; k < statics; ++k) {
        const glm::dvec3 c = somewhere(0.0);
        glm::dvec3 half{rng.uniform(0.2, 3.0), rng.uniform(0.2, 6.0), rng.uniform(0.2, 3.0)};
        if (rng.uniform() < 0.3) half[rng.uniform() < 0.5 ? 0 : 2] = rng.uniform(4.0, side * 0.4);
        addBox(scene, id++, c - half, c + half);
    }

    // The crowd: complex meshes (shared by a few copies, as the bunnies share
    // one), spheres and small boxes, moving or not.
    std::vector<std::shared_ptr<TriangleMesh>> meshes;
    const int kinds = 1 + int(rng.below(3));
    for (int k = 0; k < kinds; ++k) {
        const double size = rng.uniform(0.8, 5.0);
        if (rng.uniform() < 0.7)
            meshes.push_back(bumpySphereMesh(rng, size, 8 + int(rng.below(17)),
                                             6 + int(rng.below(12)), rng.uniform(0.0, 0.4)));
        else
            meshes.push_back(
                wavySheetMesh(rng, 2.0 * size, 4 + int(rng.below(14)), rng.uniform(0.0, size)));
    }
    const int crowd = 1 + int(rng.below(80));
    for (int k = 0; k < crowd; ++k) {
        const glm::dvec3 c = somewhere(side * 0.1);
        const double kind = rng.uniform();
        if (kind < 0.7)
            addMesh(scene, id++, c, meshes[size_t(rng.below(uint64_t(meshes.size())))]);
        else if (kind < 0.85)
            addSphere(scene, id++, c, rng.uniform(0.2, 2.5));
        else
            addBox(scene, id++, c - glm::dvec3(0.5), c + glm::dvec3(rng.uniform(0.5, 2.0)));
        if (rng.uniform() < 0.25) continue;  // static
        Motion& m = scene.objects.back().motion;
        const double speed = rng.uniform() < 0.1 ? rng.uniform(20.0, 60.0) : rng.uniform(0.0, 6.0);
        glm::dvec3 dir{rng.uniform(-1.0, 1.0), rng.uniform(-0.3, 0.3), rng.uniform(-1.0, 1.0)};
        if (glm::length(dir) < 1e-6) dir = {1, 0, 0};
        m.kind = MotionKind::Linear;
        m.velocity = glm::normalize(dir) * speed;
        m.max_speed = speed;
    }

    // The camera: among the objects or above them, turning.
    const double duration = kBspFrames * kBspDt;
    const double fov = rng.uniform(30.0, 110.0);
    const double near = rng.uniform() < 0.1 ? rng.uniform(0.5, 3.0) : 0.1;
    setCamera(scene, somewhere(side * 0.3), somewhere(0.0), fov, near,
              rng.uniform() < 0.2 ? rng.uniform(10.0, 40.0) : 500.0);
    scene.camera.aspect = rng.uniform(0.6, 2.2);
    const int keys = 1 + int(rng.below(4));
    for (int k = 1; k <= keys; ++k)
        scene.camera.path.push_back(
            CameraKey{duration * k / keys, somewhere(side * 0.3), somewhere(0.0), {0, 1, 0}});
    if (rng.uniform() < 0.08 && !scene.objects.empty()) {
        // Start inside an object.
        const SceneObject& host = scene.objects[size_t(rng.below(uint64_t(scene.objects.size())))];
        scene.camera.path.front().position = host.bounds.center();
    }
    scene.finalize();
    return scene;
}

}  // namespace gridcull::test
