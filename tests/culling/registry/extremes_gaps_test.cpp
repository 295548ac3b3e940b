// Extremes of scene geometry, every algorithm against
// the exact oracle (extremes_harness.h):
//  3. a wall with a gap one voxel wide (aligned to the voxels, and straddling two
//     of them) and one narrower than a voxel, at the centre, the edge and the
//     corner of the view, with an object seen only through the gap;
//  5. objects of 1e-4 voxel, objects spanning the whole grid (and beyond it),
//     sliver occluders 1e-4 voxel thick (facing the camera: they hide; edge-on:
//     they hide almost nothing, though they touch many voxels).
// Voxels are 10 units: world [0, 100]^d in 10^d voxels.
//
// The oracle samples pixel centres (rays in 2D): an object smaller than a pixel
// may fall between them and be missed by the oracle itself (exact_oracle.h,
// "Exactness"). The check is culler PVS >= oracle PVS, so that only makes the
// check weaker for those objects, never wrong; the rows print how many of the
// tiny objects the oracle saw.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/culling/registry/extremes_harness.h"
#include "tests/culling/registry/extremes_scenes.h"

namespace gridcull {
namespace {

using test::ExtremeCase;
using test::makeCamera;

struct Gap {
    const char* name;
    glm::dvec3 min, max;  // the hole, in the wall's plane (x, y in 3D; x in 2D)
};

// 3D: the camera at (50, 50, 5) looks down +z (fov 60, 16:9); the wall at
// z in [40, 42] covers the view (x in [14.1, 85.9], y in [29.8, 70.2] there).
// A small sphere (radius 0.3, two pixels) at z = 80 on the ray through the
// hole's centre at the wall's mid-depth (a slanted ray through a 2-unit-thick
// wall) is visible only through it; another at z = 80 behind the wall's
// middle-left is hidden.
TEST(ExtremesGeometry, GapsInAWall3d) {
    const Gap gaps[] = {
        {"one voxel aligned, centre", {50, 50, 0}, {60, 60, 0}},
        {"one voxel straddling, centre", {45, 45, 0}, {55, 55, 0}},
        {"0.3 voxel, centre", {48.5, 48.5, 0}, {51.5, 51.5, 0}},
        {"one voxel aligned, edge", {20, 50, 0}, {30, 60, 0}},
        {"one voxel straddling, edge", {15, 45, 0}, {25, 55, 0}},
        {"0.3 voxel, edge", {16.5, 48.5, 0}, {19.5, 51.5, 0}},
        {"one voxel aligned, corner", {20, 60, 0}, {30, 70, 0}},
        {"one voxel straddling, corner", {15, 55, 0}, {25, 65, 0}},
        {"0.3 voxel, corner", {16.5, 66.5, 0}, {19.5, 69.5, 0}},
        {"0.03 voxel, centre", {49.85, 49.85, 0}, {50.15, 50.15, 0}},
    };
    const glm::dvec3 eye{50, 50, 5};
    for (const Gap& gap : gaps) {
        Scene scene = test::scene3d();
        test::addWallWithHole(scene, 0, 40, 42, gap.min, gap.max);
        const glm::dvec3 hole = (gap.min + gap.max) * 0.5;
        const glm::dvec3 through = eye + (glm::dvec3(hole.x, hole.y, 41) - eye) * (75.0 / 36.0);
        test::addSphere(scene, 10, through, 0.3);
        test::addSphere(scene, 11, {35, 40, 80}, 2.0);
        // Behind the wall, a moving one that crosses the line of sight between
        // two frames (at x offsets -6, -2, 2, 6 from it at z = 50).
        const glm::dvec3 cross = eye + (through - eye) * (45.0 / 75.0);
        test::addSphere(scene, 12, cross - glm::dvec3(6, 0, 0), 1.0);
        scene.objects.back().motion.kind = MotionKind::Linear;
        scene.objects.back().motion.velocity = {40, 0, 0};
        scene.objects.back().motion.max_speed = 40;
        ExtremeCase c{std::string("3d gap ") + gap.name, scene, {}, {}};
        for (int f = 0; f < 4; ++f) {
            c.frames.push_back(
                {f * 0.1, makeCamera(3, eye, {50, 50, 100}, 60, 16.0 / 9.0), {10}, {11}});
        }
        test::adoptCamera(c.scene, c.frames.front().camera);
        c.scene.finalize();
        test::runExtremeCase(c);
    }
}

// 2D: the camera at (50, 5) looks along +y (fov 90); the wall at y in [40, 42]
// covers the wedge (x in [15, 85] there). 2D has no "corner of the view": the
// edge is tried on both sides, and with a 360-degree wedge.
TEST(ExtremesGeometry, GapsInAWall2d) {
    const Gap gaps[] = {
        {"one voxel aligned, centre", {50, 0, 0}, {60, 0, 0}},
        {"one voxel straddling, centre", {45, 0, 0}, {55, 0, 0}},
        {"0.3 voxel, centre", {48.5, 0, 0}, {51.5, 0, 0}},
        {"one voxel aligned, left edge", {20, 0, 0}, {30, 0, 0}},
        {"one voxel straddling, left edge", {16, 0, 0}, {26, 0, 0}},
        {"0.3 voxel, left edge", {18.5, 0, 0}, {21.5, 0, 0}},
        {"one voxel aligned, right edge", {70, 0, 0}, {80, 0, 0}},
        {"0.3 voxel, right edge", {81.5, 0, 0}, {84.5, 0, 0}},
        {"0.03 voxel, centre", {49.85, 0, 0}, {50.15, 0, 0}},
    };
    const glm::dvec3 eye{50, 5, 0};
    for (const double fov : {90.0, 360.0}) {
        for (const Gap& gap : gaps) {
            Scene scene = test::scene2d();
            test::addWallWithHole(scene, 0, 40, 42, gap.min, gap.max);
            const double hole = (gap.min.x + gap.max.x) * 0.5;
            const glm::dvec3 through = eye + (glm::dvec3(hole, 41, 0) - eye) * (75.0 / 36.0);
            test::addSphere(scene, 10, through, 0.3);
            test::addSphere(scene, 11, {35, 80, 0}, 2.0);
            const glm::dvec3 cross = eye + (through - eye) * (45.0 / 75.0);
            test::addSphere(scene, 12, cross - glm::dvec3(6, 0, 0), 1.0);
            scene.objects.back().motion.kind = MotionKind::Linear;
            scene.objects.back().motion.velocity = {40, 0, 0};
            scene.objects.back().motion.max_speed = 40;
            ExtremeCase c{std::string("2d gap ") + gap.name + " fov " + std::to_string(int(fov)),
                          scene,
                          {},
                          {}};
            for (int f = 0; f < 4; ++f)
                c.frames.push_back({f * 0.1, makeCamera(2, eye, {50, 100, 0}, fov), {10}, {11}});
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
    }
}

// Objects of 1e-4 voxel (1e-3 units across) on voxel corners, faces and centres,
// near the camera and far from it, some moving; plus a few normal objects.
TEST(ExtremesGeometry, ObjectsOfATenThousandthOfAVoxel) {
    for (const int dims : {2, 3}) {
        Scene scene = dims == 3 ? test::scene3d() : test::scene2d();
        const double z = dims == 3 ? 50.0 : 0.0;
        const double r = 0.5e-3;  // diameter 1e-4 voxel
        const glm::dvec3 spots[] = {{50, 50, z}, {40, 60, dims == 3 ? 60.0 : 0.0},
                                    {45, 60, z}, {55, 55, z},
                                    {50, 21, z}, {90, 90, dims == 3 ? 90.0 : 0.0}};
        int id = 0;
        for (const glm::dvec3& p : spots) {
            test::addSphere(scene, id++, p, r);
            const glm::dvec3 h = dims == 3 ? glm::dvec3(r) : glm::dvec3(r, r, 0);
            test::addBox(scene, id++, p + glm::dvec3(3, 0, 0) - h, p + glm::dvec3(3, 0, 0) + h);
        }
        scene.objects[2].motion.kind = MotionKind::Linear;
        scene.objects[2].motion.velocity = {0, 30, 0};
        scene.objects[2].motion.max_speed = 30;
        test::addBox(scene, 100, dims == 3 ? glm::dvec3(60, 30, 30) : glm::dvec3(60, 30, 0),
                     dims == 3 ? glm::dvec3(70, 70, 70) : glm::dvec3(70, 70, 0));
        const glm::dvec3 eye{50, 20, z};
        ExtremeCase c{
            std::string(dims == 3 ? "3d" : "2d") + " objects of 1e-4 voxel", scene, {}, {}};
        for (int f = 0; f < 4; ++f)
            c.frames.push_back(
                {f * 0.1, makeCamera(dims, eye, {50, 100, z}, dims == 3 ? 90 : 120), {}, {}});
        test::adoptCamera(c.scene, c.frames.front().camera);
        c.scene.finalize();
        test::runExtremeCase(c);
    }
}

TEST(ExtremesGeometry, ObjectsSpanningTheWholeGrid) {
    for (const int dims : {2, 3}) {
        const std::string d = dims == 3 ? "3d " : "2d ";
        const double z = dims == 3 ? 50.0 : 0.0;
        const glm::dvec3 lo = dims == 3 ? glm::dvec3(0) : glm::dvec3(0, 0, 0);
        const glm::dvec3 hi = dims == 3 ? glm::dvec3(100) : glm::dvec3(100, 100, 0);
        const glm::dvec3 pad = dims == 3 ? glm::dvec3(10) : glm::dvec3(10, 10, 0);
        {
            // The world box itself as an object, seen from outside: it hides an
            // object inside it and shows one in front of it.
            Scene scene = dims == 3 ? test::scene3d() : test::scene2d();
            test::addBox(scene, 0, lo, hi);
            test::addSphere(scene, 1, {50, 50, z}, 5);
            test::addSphere(scene, 2, {-20, 50, z}, 2);
            ExtremeCase c{d + "the world box as an object, from outside", scene, {}, {}};
            for (int f = 0; f < 2; ++f)
                c.frames.push_back(
                    {f * test::kDt, makeCamera(dims, {-50, 50, z}, {50, 50, z}, 60), {0, 2}, {1}});
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
        {
            // A box larger than the world, the camera inside it: only it is seen.
            Scene scene = dims == 3 ? test::scene3d() : test::scene2d();
            test::addBox(scene, 0, lo - pad, hi + pad);
            test::addSphere(scene, 1, {50, 80, z}, 5);
            ExtremeCase c{d + "a box larger than the world, camera inside", scene, {}, {}};
            for (int f = 0; f < 2; ++f)
                c.frames.push_back(
                    {f * test::kDt, makeCamera(dims, {50, 20, z}, {50, 80, z}, 60), {0}, {1}});
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
        {
            // A sphere around the whole grid seen from outside, and a slab as
            // wide as the grid (a floor in 3D, a wall in 2D) with objects on
            // both sides.
            Scene scene = dims == 3 ? test::scene3d() : test::scene2d();
            test::addBox(scene, 0, lo, dims == 3 ? glm::dvec3(100, 1, 100) : glm::dvec3(100, 1, 0));
            test::addSphere(scene, 1, {50, 20, z}, 3);
            test::addSphere(scene, 2, {50, -20, z}, 3);
            test::addSphere(scene, 3, {50, 50, z}, 75);
            ExtremeCase c{d + "a slab as wide as the grid and a sphere around it", scene, {}, {}};
            // 120 units from the sphere's centre: it fills the 60-degree view. In
            // 3D the slab's corners stick out of it (out of view, so not named).
            const glm::dvec3 from = dims == 3 ? glm::dvec3(50, 50, -70) : glm::dvec3(-70, 50, 0);
            const std::vector<int> hidden =
                dims == 3 ? std::vector<int>{1, 2} : std::vector<int>{0, 1, 2};
            c.frames.push_back({0.0, makeCamera(dims, from, {50, 50, z}, 60), {3}, hidden});
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
    }
}

// Occluders 1e-4 voxel thick: a wall facing the camera (it must hide what is
// behind it), on a voxel plane and inside a voxel; and a comb of edge-on slivers,
// on voxel planes and between them, which touch many voxels but hide nothing
// seen between them.
TEST(ExtremesGeometry, SliverOccluders) {
    const double thin = 1e-3;
    for (const int dims : {2, 3}) {
        const std::string d = dims == 3 ? "3d " : "2d ";
        const double z = dims == 3 ? 50.0 : 0.0;
        const glm::dvec3 eye{50, 5, z};
        const glm::dvec3 ahead{50, 100, z};
        for (const double plane : {40.0, 45.0}) {
            Scene scene = dims == 3 ? test::scene3d() : test::scene2d();
            test::addBox(scene, 0, {0, plane, dims == 3 ? 0.0 : 0.0},
                         {100, plane + thin, dims == 3 ? 100.0 : 0.0});
            test::addSphere(scene, 1, {50, 70, z}, 3);
            test::addSphere(scene, 2, {50, 30, z}, 3);
            ExtremeCase c{d + "sliver wall facing the camera at y " + std::to_string(int(plane)),
                          scene,
                          {},
                          {}};
            for (int f = 0; f < 2; ++f)
                c.frames.push_back({f * test::kDt, makeCamera(dims, eye, ahead, 90), {0, 2}, {1}});
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
        {
            Scene scene = dims == 3 ? test::scene3d() : test::scene2d();
            int id = 0;
            for (int k = 1; k < 20; ++k) {
                const double x = 5.0 * k;  // on voxel planes when k is even
                test::addBox(scene, id++, {x, 30, dims == 3 ? 0.0 : 0.0},
                             {x + thin, 60, dims == 3 ? 100.0 : 0.0});
            }
            test::addSphere(scene, 100, {52.5, 80, z}, 1.5);  // between two planks
            ExtremeCase c{d + "edge-on sliver comb", scene, {}, {}};
            for (int f = 0; f < 2; ++f)
                c.frames.push_back(
                    {f * test::kDt, makeCamera(dims, {52.5, 5, z}, {52.5, 100, z}, 60), {100}, {}});
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
    }
}

}  // namespace
}  // namespace gridcull
