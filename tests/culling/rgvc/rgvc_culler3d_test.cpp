// rgvc in 3D on small hand-made scenes, each checked against the exact oracle
// frame by frame: a wall hides what is behind it (and nothing that peeks over
// it), the cubical TBV's life cycle (created, expired and renewed, revealed), a
// teleport into a TBV, an object that can leave the grid (its TBV kept out of
// T), the viewer inside an opaque object, and each matrix allocated only when
// the scene needs it.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "culling/oracle/exact_oracle.h"
#include "culling/rgvc/rgvc_culler.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/rgvc/rgvc_checked_run.h"

namespace gridcull {
namespace {

using test::addBox;
using test::addSphere;
using test::has;
using test::moving;
using test::runChecked;

// [0, 100]^3 in 50^3 voxels of 2 units, frames of 0.1 s.
Scene roomScene() {
    Scene scene = test::makeScene(3, Aabb{{0, 0, 0}, {100, 100, 100}}, {50, 50, 50});
    scene.dt = 0.1;
    return scene;
}

int64_t total(const std::vector<FrameResult>& frames, Counter c) {
    int64_t n = 0;
    for (const FrameResult& f : frames) n += f.stats.get(c);
    return n;
}

TEST(RgvcCuller3d, AWallHidesWhatIsBehindItAndNothingThatPeeksOver) {
    Scene scene = roomScene();
    addBox(scene, 0, {0, 0, 40}, {100, 50, 44});  // a wall across the room, 50 high
    addSphere(scene, 1, {50, 20, 70}, 3);         // behind it, low
    addSphere(scene, 2, {50, 66, 70}, 3);         // behind it, seen over its top
    addSphere(scene, 3, {45, 45, 20}, 3);         // in front of it
    scene.finalize();
    test::setCamera(scene, {50, 45, 5}, {50, 45, 90}, 60);
    RgvcCuller rgvc;
    const std::vector<FrameResult> frames = runChecked(scene, 3, rgvc);
    for (const FrameResult& f : frames) {
        EXPECT_FALSE(has(f.pvs, 1));
        EXPECT_TRUE(has(f.pvs, 2));
        EXPECT_TRUE(has(f.pvs, 3));
    }
}

TEST(RgvcCuller3d, CubicalTbvIsCreatedRenewedAndRevealed) {
    Scene scene = roomScene();
    addBox(scene, 0, {0, 0, 40}, {100, 60, 44});  // a wall 60 high
    // Behind it, rising at 10 units/s: over the wall's top as the camera sees
    // it (y = 71.4) after about 5.1 s.
    addSphere(scene, 1, {50, 20, 70}, 2);
    moving(scene, {0, 10, 0});
    scene.finalize();
    test::setCamera(scene, {50, 45, 5}, {50, 45, 90}, 60);
    RgvcOptions options;
    options.validity_s = 0.5;
    options.adaptive_validity = 0;
    RgvcCuller rgvc(options);
    const std::vector<FrameResult> frames = runChecked(scene, 60, rgvc);
    EXPECT_FALSE(has(frames[0].pvs, 1));
    EXPECT_EQ(frames[0].stats.get(Counter::TbvCreated), 1);  // at the end of the frame
    EXPECT_EQ(frames[1].stats.get(Counter::TbvCreated), 0);
    EXPECT_EQ(frames[1].stats.get(Counter::ObjectUpdates), 0);  // left alone while hidden
    EXPECT_GE(total(frames, Counter::TbvExpired), 1);
    EXPECT_GE(total(frames, Counter::TbvRevealed), 1);
    EXPECT_TRUE(has(frames.back().pvs, 1));  // over the wall at y = 79
}

TEST(RgvcCuller3d, TeleportIntoACubicalTbvRevealsIt) {
    Scene scene = roomScene();
    addSphere(scene, 0, {60, 50, 50}, 1);
    moving(scene, {0.5, 0, 0});
    scene.finalize();
    // Frames 0-4 far from it with a short far plane; from frame 5 the camera
    // stands 3 units from it, inside its TBV's box, with far = 4: the box's
    // surface in view lies beyond far, so only the teleport rule finds it.
    scene.camera.fov_deg = 60;
    scene.camera.far = 4;
    scene.camera.path = {CameraKey{0.0, {10, 50, 50}, {90, 50, 50}, {0, 1, 0}},
                         CameraKey{0.45, {10, 50, 50}, {90, 50, 50}, {0, 1, 0}},
                         CameraKey{0.46, {60.5, 53.5, 50}, {60.5, 0, 50}, {0, 0, 1}}};
    RgvcOptions options;
    options.validity_s = 5.0;
    RgvcCuller rgvc(options);
    const std::vector<FrameResult> frames = runChecked(scene, 8, rgvc);
    EXPECT_FALSE(has(frames[4].pvs, 0));
    EXPECT_EQ(frames[5].stats.get(Counter::TbvRevealed), 1);
    EXPECT_TRUE(has(frames[5].pvs, 0));
}

TEST(RgvcCuller3d, TbvOfAnObjectThatCanLeaveTheGridIsKeptOutOfT) {
    Scene scene = roomScene();
    addBox(scene, 0, {0, 0, 40}, {100, 100, 44});  // a wall across the whole room
    addSphere(scene, 1, {50, 50, 90}, 2);          // behind it, near the grid's back
    SceneObject& mover = scene.objects.back();
    // Still for 5 s, then out through the back of the grid.
    mover.motion.kind = MotionKind::Keyframes;
    mover.motion.keys = {{0.0, {50, 50, 90}}, {5.0, {50, 50, 90}}, {7.0, {50, 50, 130}}};
    mover.motion.max_speed = 20.0;
    scene.finalize();
    test::setCamera(scene, {50, 50, 5}, {50, 50, 90}, 60);
    // A long validity: the TBV's box reaches past the grid's back.
    RgvcOptions options;
    options.validity_s = 5.0;
    options.adaptive_validity = 0;
    RgvcCuller rgvc(options);
    rgvc.setDebugCapture(true);
    ExactOracle exact;
    rgvc.reset(scene);
    exact.reset(scene);
    bool saw_edge = false;
    for (int f = 0; f < 10; ++f) {
        const double t = scene.timeOfFrame(f);
        const Camera camera = cameraAt(scene, t);
        FrameResult got, want;
        rgvc.cull(scene, camera, t, got);
        exact.cull(scene, camera, t, want);
        EXPECT_TRUE(test::isSubset(want.pvs, got.pvs)) << "frame " << f;
        const RgvcSnapshot& s = rgvc.snapshot();
        // Its box reaches into the frustum beyond the grid, so it is made and
        // revealed before the traversal, frame after frame.
        for (const RgvcRevealView& r : s.reveals)
            if (r.tbv.object_index == 1) {
                EXPECT_EQ(r.layer, -1);
                saw_edge = saw_edge || r.tbv.edge;
            }
        for (const RgvcTbvView& tbv : s.tbv_list) {
            EXPECT_TRUE(tbv.edge);
            saw_edge = true;
            for (int y = 0; y < 50; ++y)
                for (int x = 0; x < 50; ++x)
                    ASSERT_FALSE(s.tbvs->contains(x, y, tbv.object_index));
        }
    }
    EXPECT_TRUE(saw_edge);
}

TEST(RgvcCuller3d, ViewerInsideAnOpaqueObjectSeesOnlyIt) {
    Scene scene = roomScene();
    addSphere(scene, 0, {50, 50, 50}, 20);  // the camera is inside it
    addSphere(scene, 1, {50, 50, 90}, 3);   // beyond its far side
    scene.finalize();
    test::setCamera(scene, {50, 50, 45}, {50, 50, 90}, 60);
    RgvcCuller rgvc;
    const std::vector<FrameResult> frames = runChecked(scene, 2, rgvc);
    EXPECT_TRUE(has(frames[0].pvs, 0));
    EXPECT_FALSE(has(frames[0].pvs, 1));
}

TEST(RgvcCuller3d, MatricesOnlyWhereTheSceneNeedsThem) {
    Scene still = roomScene();
    addBox(still, 0, {0, 0, 40}, {100, 60, 44});
    still.finalize();
    test::setCamera(still, {50, 20, 5}, {50, 20, 90}, 60);
    RgvcCuller rgvc;
    test::cullIds(rgvc, still);
    RgvcMatrixMemory m = rgvc.memory();
    EXPECT_EQ(m.occluder, size_t(50 * 50 * 8));  // 2500 rows of one 64-bit word
    EXPECT_EQ(m.static_occluder, m.occluder);
    EXPECT_EQ(m.tbv, size_t(0));  // no dynamic objects: no T
    EXPECT_EQ(m.identifiers_dynamic, size_t(0));
    EXPECT_GT(m.direction_map, size_t(0));

    Scene moving_only = roomScene();
    addSphere(moving_only, 0, {50, 50, 70}, 2);
    moving(moving_only, {1, 0, 0});
    moving_only.finalize();
    test::setCamera(moving_only, {50, 50, 5}, {50, 50, 90}, 60);
    test::cullIds(rgvc, moving_only);
    m = rgvc.memory();
    EXPECT_EQ(m.static_occluder, size_t(0));  // no static objects: no Os
    EXPECT_EQ(m.identifiers_static, size_t(0));
}

}  // namespace
}  // namespace gridcull
