// Extremes of the camera, every algorithm against the
// exact oracle (extremes_harness.h):
//  1. the camera exactly on voxel corners, edges and faces (of inner voxels and of
//     the world box), looking exactly along +-X, +-Y, +-Z, with frustum planes
//     through voxel corners (fov 90, aspect 1) and, in 2D, wedge edges along the
//     grid lines (fov 180);
//  2. the camera inside an object, inside an opaque voxel, inside a block of
//     opaque voxels, and outside the grid looking in and looking away, with
//     objects lying wholly outside the grid;
//  8. a teleporting camera and a 180-degree turn between two frames, with moving
//     objects, so that stateful cullers must not keep last frame's answer;
// and seeded random scenes snapped to the voxel lattice (GRIDCULL_SEED).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/culling/registry/extremes_harness.h"
#include "tests/culling/registry/extremes_scenes.h"

namespace gridcull {
namespace {

using test::ExtremeCase;
using test::ExtremeFrame;
using test::makeCamera;

const glm::dvec3 kAxes[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

// One case per viewpoint: the six (2D: four) axis directions as consecutive
// frames, a 90- or 180-degree turn each frame.
ExtremeCase axisSweep(const std::string& name, int dimensions, const glm::dvec3& eye,
                      double fov_deg) {
    ExtremeCase c{name, test::latticeScene(dimensions), {}, {}};
    const int directions = dimensions == 3 ? 6 : 4;
    for (int d = 0; d < directions; ++d) {
        const Camera camera = makeCamera(dimensions, eye, eye + kAxes[d] * 30.0, fov_deg);
        c.frames.push_back({d * test::kDt, camera, {}, {}});
    }
    test::adoptCamera(c.scene, c.frames.front().camera);
    c.scene.finalize();
    return c;
}

TEST(ExtremesCamera, OnVoxelCornersEdgesAndFacesLookingAlongTheAxes3d) {
    // Lattice boxes fill the voxels [10 + 20i, 20 + 20i] per axis where i + j + k
    // is odd; spheres of radius 3 sit on (10 + 20i, ...) where it is even. So
    // (40, 40, 40) is a corner of the box [30, 40]^3 (the camera on an opaque
    // voxel's corner: the oracle counts it inside the box), (20, 40, 40) a
    // corner that no box touches (one of its eight voxels holds a sphere's rim).
    // "Empty voxel" below means no box in it.
    const struct {
        const char* name;
        glm::dvec3 eye;
    } points[] = {
        {"3d corner of an empty voxel", {20, 40, 40}},
        {"3d corner of an opaque voxel", {40, 40, 40}},
        {"3d edge of an empty voxel", {20, 40, 45}},
        {"3d face of an empty voxel", {20, 45, 45}},
        {"3d centre of a voxel", {45, 45, 45}},
        {"3d corner of the world", {0, 0, 0}},
        {"3d edge of the world", {0, 0, 45}},
        {"3d face of the world", {100, 45, 45}},
    };
    for (const auto& p : points) {
        test::runExtremeCase(axisSweep(std::string(p.name) + " fov 90", 3, p.eye, 90.0));
    }
    // A narrow frustum whose planes lie close to the grid lines.
    test::runExtremeCase(axisSweep("3d corner of an empty voxel fov 1", 3, {20, 40, 40}, 1.0));
}

TEST(ExtremesCamera, OnVoxelCornersAndFacesLookingAlongTheAxes2d) {
    const struct {
        const char* name;
        glm::dvec3 eye;
    } points[] = {
        // Lattice as in 3D: no box touches (40, 40) (a sphere's rim does), (30,
        // 20) is a corner of the box [30, 40] x [10, 20].
        {"2d corner of an empty voxel", {40, 40, 0}}, {"2d corner of an opaque voxel", {30, 20, 0}},
        {"2d face of an empty voxel", {40, 45, 0}},   {"2d corner of the world", {0, 0, 0}},
        {"2d face of the world", {100, 45, 0}},
    };
    for (const auto& p : points) {
        for (const double fov : {90.0, 180.0, 360.0}) {
            test::runExtremeCase(
                axisSweep(std::string(p.name) + " fov " + std::to_string(int(fov)), 2, p.eye, fov));
        }
    }
}

// The camera inside things. The oracle sees only the object it is in.
TEST(ExtremesCamera, InsideAnObject) {
    for (const int dims : {2, 3}) {
        const std::string d = dims == 3 ? "3d " : "2d ";
        const glm::dvec3 centre = dims == 3 ? glm::dvec3(45, 45, 45) : glm::dvec3(45, 45, 0);
        const glm::dvec3 ahead = dims == 3 ? glm::dvec3(45, 45, 90) : glm::dvec3(45, 90, 0);
        struct Inside {
            std::string name;
            Scene scene;
        };
        std::vector<Inside> cases;
        {
            Scene s = test::latticeScene(dims);
            test::addSphere(s, 1000, centre, 2.0);
            cases.push_back({d + "inside a sphere", s});
        }
        {
            // A box filling exactly the voxel [40, 50]^3: an opaque voxel.
            Scene s = test::latticeScene(dims);
            const glm::dvec3 lo = dims == 3 ? glm::dvec3(40) : glm::dvec3(40, 40, 0);
            const glm::dvec3 hi = dims == 3 ? glm::dvec3(50) : glm::dvec3(50, 50, 0);
            test::addBox(s, 1000, lo, hi);
            cases.push_back({d + "inside an opaque voxel", s});
        }
        {
            // A block of 3^d opaque voxels around the camera's voxel.
            Scene s = test::scene3d();
            if (dims == 2) s = test::scene2d();
            const glm::dvec3 lo = dims == 3 ? glm::dvec3(30) : glm::dvec3(30, 30, 0);
            const glm::dvec3 hi = dims == 3 ? glm::dvec3(60) : glm::dvec3(60, 60, 0);
            test::addBox(s, 1000, lo, hi);
            test::addSphere(s, 1001, ahead, 3.0);
            cases.push_back({d + "inside a block of opaque voxels", s});
        }
        if (dims == 3) {
            Scene s = test::latticeScene(3);
            test::addMesh(s, 1000, centre, test::cubeMesh(4.0));
            cases.push_back({d + "inside a closed mesh", s});
        } else {
            Scene s = test::latticeScene(2);
            test::addPolygon(s, 1000, {{41, 41, 0}, {49, 42, 0}, {46, 49, 0}, {42, 47, 0}});
            cases.push_back({d + "inside a polygon", s});
        }
        for (Inside& inside : cases) {
            std::vector<int> hidden;
            for (const SceneObject& o : inside.scene.objects)
                if (o.id != 1000) hidden.push_back(o.id);
            ExtremeCase c{inside.name, inside.scene, {}, {}};
            // Looking ahead, then turned about, then along the diagonal.
            const glm::dvec3 targets[] = {ahead, centre * 2.0 - ahead,
                                          centre + glm::dvec3(1, 1, dims == 3 ? 1 : 0)};
            for (int f = 0; f < 3; ++f) {
                const Camera camera = makeCamera(dims, centre, targets[f], dims == 3 ? 60 : 120);
                c.frames.push_back({f * test::kDt, camera, {1000}, hidden});
            }
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
    }
}

TEST(ExtremesCamera, OutsideTheGridLookingInAndAway) {
    for (const int dims : {2, 3}) {
        const std::string d = dims == 3 ? "3d " : "2d ";
        Scene scene = test::latticeScene(dims);
        const double z = dims == 3 ? 45.0 : 0.0;
        // Wholly outside the grid: one between the camera and the grid, one
        // behind the camera.
        test::addSphere(scene, 1000, {-20, 45, z}, 2.0);
        test::addSphere(scene, 1001, {-90, 45, z}, 2.0);
        // Sticking out of the grid through its -x face.
        test::addBox(scene, 1002, {-5, 50, dims == 3 ? 50.0 : 0.0},
                     {5, 56, dims == 3 ? 56.0 : 0.0});
        std::vector<int> grid_ids;
        for (int id = 0; id < int(scene.objects.size()) - 3; ++id) grid_ids.push_back(id);
        const glm::dvec3 eye{-50, 45, z};
        const double fov = dims == 3 ? 60 : 90;
        {
            ExtremeCase c{d + "outside the grid looking in", scene, {}, {}};
            for (int f = 0; f < 3; ++f) {
                // Creeping towards the grid.
                const glm::dvec3 at = eye + glm::dvec3(f * 5.0, 0, 0);
                c.frames.push_back({f * test::kDt,
                                    makeCamera(dims, at, at + glm::dvec3(1, 0, 0), fov),
                                    {1000},
                                    {1001}});
            }
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
        {
            ExtremeCase c{d + "outside the grid looking away", scene, {}, {}};
            std::vector<int> hide = grid_ids;
            hide.push_back(1000);
            hide.push_back(1002);
            for (int f = 0; f < 3; ++f) {
                c.frames.push_back({f * test::kDt,
                                    makeCamera(dims, eye, eye - glm::dvec3(1, 0, 0), fov),
                                    {1001},
                                    hide});
            }
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
        {
            // Far outside, looking in along a diagonal with a far plane to match.
            ExtremeCase c{d + "far outside the grid looking in", scene, {}, {}};
            const glm::dvec3 far_eye =
                dims == 3 ? glm::dvec3(-1e5, -1e5, -1e5) : glm::dvec3(-1e5, -1e5, 0);
            const glm::dvec3 middle = dims == 3 ? glm::dvec3(50) : glm::dvec3(50, 50, 0);
            c.frames.push_back(
                {0.0,
                 makeCamera(dims, far_eye, middle, dims == 3 ? 1.0 : 2.0, 1.0, 0.1, 1e6),
                 {},
                 {}});
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
    }
}

// Item 8: the camera jumps across the grid, turns about in one frame, and jumps
// out of and back into the grid, while objects move.
TEST(ExtremesCamera, TeleportAndHalfTurnInOneFrame) {
    for (const int dims : {2, 3}) {
        const std::string d = dims == 3 ? "3d " : "2d ";
        Scene scene = dims == 3 ? test::scene3d() : test::scene2d();
        SeededRandom rng(5);
        test::addRandomObjects(scene, rng, 60);
        const double z = dims == 3 ? 50.0 : 0.0;
        const glm::dvec3 a{5, 50, z}, b{95, 50, z}, outside{-40, 50, z};
        const glm::dvec3 east{1, 0, 0};
        struct Key {
            glm::dvec3 eye, direction;
        };
        const Key keys[] = {
            {a, east},       {a, east},  {a, east},  // settle
            {b, -east},      {b, -east},             // teleport across the grid
            {b, east},       {b, east},              // half turn in one frame
            {outside, east},                         // out of the grid
            {a, -east},      {b, -east},             // back in, and across again
            {b, east},                               // and about again
        };
        for (const double fov : {dims == 3 ? 60.0 : 90.0, dims == 3 ? 120.0 : 360.0}) {
            ExtremeCase c{
                d + "teleport and half turn fov " + std::to_string(int(fov)), scene, {}, {}};
            int f = 0;
            for (const Key& k : keys) {
                c.frames.push_back({f * test::kDt,
                                    makeCamera(dims, k.eye, k.eye + k.direction * 10.0, fov),
                                    {},
                                    {}});
                ++f;
            }
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
    }
}

// Seeded random scenes whose every coordinate lies on the half-voxel lattice
// (so that object faces, voxel faces, the camera and the view directions
// coincide as often as possible), a few frames of axis-aligned and diagonal
// views from lattice points.
Scene snappedScene(uint64_t seed, std::vector<ExtremeFrame>& frames) {
    SeededRandom rng(seed);
    const int dims = seed % 2 == 0 ? 2 : 3;
    Scene scene = dims == 3 ? test::scene3d() : test::scene2d();
    auto snap = [&](double lo, double hi) { return 5.0 * std::floor(rng.uniform(lo, hi) / 5.0); };
    auto point = [&]() {
        return glm::dvec3{snap(-10, 110), snap(-10, 110), dims == 3 ? snap(-10, 110) : 0.0};
    };
    const int count = 5 + int(rng.below(40));
    for (int id = 0; id < count; ++id) {
        const glm::dvec3 p = point();
        if (rng.uniform() < 0.4) {
            test::addSphere(scene, id, p, 5.0 * (1 + int(rng.below(3))));
        } else {
            glm::dvec3 q =
                p + glm::dvec3{5.0 * (1 + int(rng.below(6))), 5.0 * (1 + int(rng.below(6))),
                               dims == 3 ? 5.0 * (1 + int(rng.below(6))) : 0.0};
            test::addBox(scene, id, p, q);
        }
    }
    const double fovs3[] = {30, 60, 90, 120};
    const double fovs2[] = {45, 90, 180, 270, 360};
    const double fov = dims == 3 ? fovs3[rng.below(4)] : fovs2[rng.below(5)];
    for (int f = 0; f < 5; ++f) {
        const glm::dvec3 eye = point();
        glm::dvec3 dir = kAxes[rng.below(dims == 3 ? 6 : 4)];
        if (rng.uniform() < 0.3) dir = dir + kAxes[rng.below(dims == 3 ? 6 : 4)];
        if (glm::length(dir) == 0.0) dir = kAxes[0];
        frames.push_back({f * test::kDt, makeCamera(dims, eye, eye + dir * 20.0, fov), {}, {}});
    }
    test::adoptCamera(scene, frames.front().camera);
    scene.finalize();
    return scene;
}

TEST(ExtremesCamera, RandomScenesSnappedToTheVoxelLattice) {
    for (const uint64_t seed : test::seedsToRun(0, 40)) {
        ExtremeCase c{"snapped seed " + std::to_string(seed), {}, {}, {}};
        c.scene = snappedScene(seed, c.frames);
        test::withSeed(seed, [&] { test::runExtremeCase(c); });
    }
}

}  // namespace
}  // namespace gridcull
