// The 3D parts of rgvc checked against brute force: the cube-shell traversal
// (every frustum voxel of the grid visited once, in order of chess distance),
// the 2-of-3 existence test of cubical TBVs (exactly the box's surface), the
// occlusion (every voxel put in H is wholly hidden: rays from the eye to its
// corners and centre meet a solid beyond the near plane first), and the
// snapshot switch (capturing changes nothing culled).
#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "culling/rgvc/rgvc_culler.h"
#include "culling/rgvc/rgvc_tbv3d.h"
#include "culling/scene/ray_intersect.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/rgvc/rgvc_random_scene3d.h"

namespace gridcull {
namespace {

// The frustum's box: the apex and the four corners of the far plane.
Aabb frustumBox(const Camera& camera) {
    glm::dvec3 right, up, fwd;
    camera.basis(right, up, fwd);
    const double ty = std::tan(camera.fov_deg * 3.141592653589793 / 360.0), tx = ty * camera.aspect;
    Aabb box{camera.position, camera.position};
    for (const double sx : {-1.0, 1.0})
        for (const double sy : {-1.0, 1.0}) {
            const glm::dvec3 c = camera.position + (fwd + right * (sx * tx) + up * (sy * ty)) * camera.far;
            box.merge({c, c});
        }
    return box;
}

bool boxesMeet(const Aabb& a, const Aabb& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
           a.min.z <= b.max.z && b.min.z <= a.max.z;
}

// The frustum's plane test for a voxel, written out again: the camera's side
// and far planes (no near plane), some corner on the inner side of each.
bool voxelPassesPlanes(const RegularGrid& grid, const Camera& camera, const glm::ivec3& v) {
    const Aabb box = grid.voxelBounds(v);
    const std::array<glm::dvec4, 6> planes = camera.frustumPlanes();
    const double slack = 1e-9 * std::max({grid.voxelSize().x, grid.voxelSize().y,
                                          grid.voxelSize().z});
    for (int i = 0; i < 6; ++i) {
        if (i == 4) continue;  // near
        double best = -1e300;
        for (int c = 0; c < 8; ++c)
            best = std::max(best, glm::dot(glm::dvec3(planes[size_t(i)]), box.corner(c)) +
                                      planes[size_t(i)].w);
        if (best < -slack) return false;
    }
    return true;
}

TEST(Rgvc3dTraversal, VisitsEveryFrustumVoxelOnceInChessOrder) {
    int64_t checked = 0;
    for (const uint64_t seed : test::seedsToRun(700000, 60)) {
        test::withSeed(seed, [&] {
            // No objects: nothing occludes, so the traversal ends only at the
            // grid's or the frustum's end.
            Scene scene = test::rgvcRandomScene3d(seed);
            scene.objects.clear();
            scene.finalize();
            RgvcCuller rgvc;
            rgvc.setDebugCapture(true);
            rgvc.reset(scene);
            FrameResult out;
            for (int frame = 0; frame < 3; ++frame) {
                const double t = scene.timeOfFrame(frame * 7);
                const Camera camera = cameraAt(scene, t);
                rgvc.cull(scene, camera, t, out);
                const RgvcSnapshot& s = rgvc.snapshot();
                const glm::i64vec3 viewer{s.viewer_voxel.x, s.viewer_voxel.y, s.viewer_voxel_z};
                std::set<std::tuple<int, int, int>> seen;
                int32_t last = -1;
                for (const RgvcVisit& v : s.visits) {
                    const glm::i64vec3 d = glm::i64vec3(v.voxel.x, v.voxel.y, v.z) - viewer;
                    const int64_t chess =
                        std::max({std::llabs(d.x), std::llabs(d.y), std::llabs(d.z)});
                    ASSERT_EQ(chess, v.layer);
                    ASSERT_GE(v.layer, last);
                    last = v.layer;
                    ASSERT_TRUE(seen.insert({v.voxel.x, v.voxel.y, v.z}).second) << "twice";
                    ASSERT_FALSE(v.occluded);
                }
                // Every voxel that passes the plane test and meets the frustum's
                // box is visited; every visited voxel passes the plane test (the
                // culler may take voxels beside the box).
                const glm::ivec3 r = scene.grid.resolution;
                const Aabb hull = frustumBox(camera);
                for (int z = 0; z < r.z; ++z)
                    for (int y = 0; y < r.y; ++y)
                        for (int x = 0; x < r.x; ++x) {
                            const bool passes = voxelPassesPlanes(scene.grid, camera, {x, y, z});
                            const bool got = seen.count({x, y, z}) > 0;
                            if (got) {
                                ASSERT_TRUE(passes) << x << "," << y << "," << z;
                            }
                            const bool want =
                                passes && boxesMeet(scene.grid.voxelBounds({x, y, z}), hull);
                            if (!want) continue;
                            ASSERT_TRUE(got)
                                << "voxel " << x << "," << y << "," << z << " frame " << frame
                                << " viewer " << viewer.x << "," << viewer.y << "," << viewer.z
                                << " layers " << s.first_layer << ".." << s.last_layer
                                << " ended early " << s.terminated_early << " camera "
                                << camera.position.x << "," << camera.position.y << ","
                                << camera.position.z << " fov " << camera.fov_deg << " far "
                                << camera.far << " res " << r.x << "," << r.y << "," << r.z;
                            checked += want ? 1 : 0;
                        }
            }
        });
    }
    if (!test::singleSeedRun()) {
        EXPECT_GT(checked, 10000);
    }
}

TEST(Rgvc3dTbv, TwoOfThreeProjectionsFindExactlyTheBoxSurface) {
    SeededRandom rng(42);
    for (int trial = 0; trial < 300; ++trial) {
        RgvcVoxelBox box;
        for (int a = 0; a < 3; ++a) {
            box.lo[a] = int(rng.below(6));
            box.hi[a] = box.lo[a] + int(rng.below(6));
        }
        for (const bool filled : {false, true}) {
            std::set<std::tuple<int, int, int>> cells;  // (plane, a, b)
            forEachTbvProjectionCell(box, filled, [&](TbvPlane plane, int a, int b) {
                cells.insert({int(plane), a, b});
            });
            for (int z = -1; z <= 12; ++z)
                for (int y = -1; y <= 12; ++y)
                    for (int x = -1; x <= 12; ++x) {
                        const bool xy = cells.count({int(TbvPlane::Xy), x, y}) > 0;
                        const bool xz = cells.count({int(TbvPlane::Xz), x, z}) > 0;
                        const bool yz = cells.count({int(TbvPlane::Yz), y, z}) > 0;
                        const bool found = (xy || yz) && (xy || xz) && (yz || xz);
                        const bool want = filled ? box.contains({x, y, z})
                                                 : onTbvBoxSurface(box, {x, y, z});
                        ASSERT_EQ(found, want) << "trial " << trial << " filled " << filled
                                               << " voxel " << x << "," << y << "," << z;
                    }
        }
    }
}

// Does the segment from the eye to p meet a solid sphere or box at a depth of
// at least `near`, before p?
bool hiddenBySolid(const Scene& scene, double t, const Camera& camera, const glm::dvec3& p) {
    const glm::dvec3 dir = p - camera.position;
    const double depth = glm::dot(dir, camera.forward());
    if (!(depth > 0.0)) return false;
    const double s_near = camera.near / depth;
    // A hair before p: a solid that p lies on the surface of does not hide p.
    const double s_end = 1.0 - 1e-9;
    for (const SceneObject& o : scene.objects) {
        const glm::dvec3 shift = scene.displacementAt(o, t);
        double s0 = 0.0, s1 = 0.0;
        bool hit = false;
        if (o.shape == ShapeKind::Sphere)
            hit = lineSphere(camera.position, dir, o.center + shift, o.radius, s0, s1);
        else if (o.shape == ShapeKind::Box)
            hit = lineBox(camera.position, dir, o.box.translated(shift), s0, s1);
        if (hit && std::max(s0, s_near) < std::min(s1, s_end)) return true;
    }
    return false;
}

TEST(Rgvc3dOcclusion, EveryVoxelInHIsWhollyHidden) {
    int64_t occluded = 0;
    for (const uint64_t seed : test::seedsToRun(710000, 80)) {
        test::withSeed(seed, [&] {
            // Spheres and boxes only, so that the check's solids are exact.
            Scene scene = test::rgvcRandomScene3d(seed);
            scene.objects.erase(std::remove_if(scene.objects.begin(), scene.objects.end(),
                                               [](const SceneObject& o) {
                                                   return o.shape == ShapeKind::Mesh;
                                               }),
                                scene.objects.end());
            scene.finalize();
            RgvcCuller rgvc;
            rgvc.setDebugCapture(true);
            rgvc.reset(scene);
            FrameResult out;
            for (int frame = 0; frame < scene.frames; frame += 4) {
                const double t = scene.timeOfFrame(frame);
                const Camera camera = cameraAt(scene, t);
                rgvc.cull(scene, camera, t, out);
                const RgvcSnapshot& s = rgvc.snapshot();
                for (const RgvcVisit& v : s.visits) {
                    if (!v.occluded) continue;
                    ++occluded;
                    const Aabb box = s.grid.voxelBounds({v.voxel.x, v.voxel.y, v.z});
                    // The corners pulled in by a millionth, and the centre.
                    const glm::dvec3 in = 1e-6 * box.extent();
                    const Aabb inner{box.min + in, box.max - in};
                    for (int c = 0; c <= 8; ++c) {
                        const glm::dvec3 p = c < 8 ? inner.corner(c) : box.center();
                        ASSERT_TRUE(hiddenBySolid(scene, t, camera, p))
                            << "voxel " << v.voxel.x << "," << v.voxel.y << "," << v.z
                            << " in H at layer " << v.layer << ", frame " << frame
                            << ": its point " << c << " is not hidden";
                    }
                }
            }
        });
    }
    if (!test::singleSeedRun()) {
        EXPECT_GT(occluded, 1000);
    }
}

TEST(Rgvc3dCuller, CapturingASnapshotChangesNothingCulled) {
    for (const uint64_t seed : test::seedsToRun(720000, 40)) {
        test::withSeed(seed, [&] {
            const Scene scene = test::rgvcRandomScene3d(seed);
            RgvcCuller plain, captured;
            captured.setDebugCapture(true);
            plain.reset(scene);
            captured.reset(scene);
            FrameResult a, b;
            for (int frame = 0; frame < scene.frames; ++frame) {
                const double t = scene.timeOfFrame(frame);
                const Camera camera = cameraAt(scene, t);
                plain.cull(scene, camera, t, a);
                captured.cull(scene, camera, t, b);
                ASSERT_EQ(a.pvs, b.pvs) << "frame " << frame;
                ASSERT_EQ(a.stats.get(Counter::VoxelsVisited), b.stats.get(Counter::VoxelsVisited))
                    << "frame " << frame;
            }
        });
    }
}

}  // namespace
}  // namespace gridcull
