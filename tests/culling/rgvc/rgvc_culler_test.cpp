// rgvc as a whole on small hand-made scenes: what it supports, its matrices'
// memory, occlusion by a wall, the TBV life cycle (created, expired, revealed),
// a teleporting camera, objects outside the grid, TBVs reaching outside the
// grid, and the snapshot switch. Each scene is also checked against the exact
// oracle frame by frame.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/oracle/exact_oracle.h"
#include "culling/registry/registry.h"
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

// [0, 100]^2 in 100 x 100 voxels of 1 unit.
Scene floorScene() {
    Scene scene = test::makeScene(2, Aabb{{0, 0, 0}, {100, 100, 0}}, {100, 100, 1});
    scene.dt = 0.1;
    return scene;
}

TEST(RgvcCuller, RegistryOffersItForBothDimensions) {
    std::string why;
    EXPECT_TRUE(algorithmFits("rgvc", test::scene2d(), why)) << why;
    EXPECT_TRUE(algorithmFits("rgvc", test::scene3d(), why)) << why;
}

TEST(RgvcCuller, MatricesOnlyWhereTheSceneNeedsThem) {
    Scene still = floorScene();
    addBox(still, 0, {40, 10, 0}, {42, 90, 0});
    still.finalize();
    test::setCamera(still, {10, 50, 0}, {90, 50, 0}, 90);
    RgvcCuller rgvc;
    test::cullIds(rgvc, still);
    RgvcMatrixMemory m = rgvc.memory();
    EXPECT_EQ(m.occluder, size_t(100 * 2 * 8));  // 100 rows of two 64-bit words
    EXPECT_EQ(m.occlusion, m.occluder);
    EXPECT_EQ(m.static_occluder, m.occluder);
    EXPECT_GT(m.identifiers_static, size_t(0));
    EXPECT_EQ(m.identifiers_dynamic, size_t(0));
    EXPECT_EQ(m.tbv, size_t(0));

    Scene moving_only = floorScene();
    addSphere(moving_only, 0, {70, 50, 0}, 2);
    moving(moving_only, {1, 0, 0});
    moving_only.finalize();
    test::setCamera(moving_only, {10, 50, 0}, {90, 50, 0}, 90);
    test::cullIds(rgvc, moving_only);
    m = rgvc.memory();
    EXPECT_EQ(m.static_occluder, size_t(0));
    EXPECT_EQ(m.identifiers_static, size_t(0));
    EXPECT_GT(m.identifiers_dynamic, size_t(0));
}

TEST(RgvcCuller, AWallHidesWhatIsBehindIt) {
    Scene scene = floorScene();
    addBox(scene, 0, {40, 10, 0}, {42, 90, 0});  // the wall
    addSphere(scene, 1, {70, 50, 0}, 3);         // behind it
    addSphere(scene, 2, {70, 20, 0}, 3);         // behind it
    addSphere(scene, 3, {25, 60, 0}, 2);         // in front of it
    addSphere(scene, 4, {5, 50, 0}, 2);          // behind the camera
    scene.finalize();
    test::setCamera(scene, {10, 50, 0}, {90, 50, 0}, 90);
    RgvcCuller rgvc;
    EXPECT_EQ(test::cullIds(rgvc, scene), (std::vector<int>{0, 3}));
}

TEST(RgvcCuller, TbvIsCreatedExpiresAndIsRevealed) {
    Scene scene = floorScene();
    addBox(scene, 0, {40, 0, 0}, {42, 60, 0});  // a wall up to y = 60
    // Behind the wall, moving up at 15 units/s: hidden until it leaves the wall's
    // shadow (y = 68.75 at x = 70) after about 3.2 s.
    addSphere(scene, 1, {70, 20, 0}, 1);
    moving(scene, {0, 15, 0});
    scene.finalize();
    test::setCamera(scene, {10, 50, 0}, {90, 50, 0}, 90);
    RgvcOptions options;
    options.validity_s = 0.5;
    RgvcCuller rgvc(options);
    rgvc.setDebugCapture(true);
    const std::vector<FrameResult> frames = runChecked(scene, 40, rgvc);
    EXPECT_FALSE(has(frames[0].pvs, 1));                     // hidden from the start
    EXPECT_EQ(frames[0].stats.get(Counter::TbvCreated), 1);  // so it gets a TBV at once
    EXPECT_EQ(frames[1].stats.get(Counter::TbvCreated), 0);
    EXPECT_EQ(frames[1].stats.get(Counter::ObjectUpdates), 0);  // and is left alone
    int64_t expired = 0, revealed = 0;
    for (const FrameResult& f : frames) {
        expired += f.stats.get(Counter::TbvExpired);
        revealed += f.stats.get(Counter::TbvRevealed);
    }
    EXPECT_GE(expired, 1);
    EXPECT_GE(revealed, 1);
    EXPECT_TRUE(has(frames.back().pvs, 1));  // out in the open at y = 78.5
}

// A TBV made at a frame's end goes into T at the next frame's start; time
// going backwards resets the culler with such TBVs still waiting. The frames
// after the rewind must match a fresh run frame by frame.
TEST(RgvcCuller, TimeGoingBackwardsWithTbvsWaitingStartsAfresh) {
    Scene scene = floorScene();
    addBox(scene, 0, {40, 0, 0}, {42, 60, 0});
    addSphere(scene, 1, {70, 20, 0}, 1);  // behind the wall: its TBV waits at frame 0's end
    moving(scene, {0, 15, 0});
    scene.finalize();
    test::setCamera(scene, {10, 50, 0}, {90, 50, 0}, 90);
    RgvcOptions options;
    options.validity_s = 0.5;
    RgvcCuller fresh(options), rewound(options);
    const std::vector<FrameResult> want = runChecked(scene, 12, fresh);
    ASSERT_EQ(want[0].stats.get(Counter::TbvCreated), 1);
    FrameResult got;
    for (const int f : {0, 1, 2, 3, 4, 5, 1}) {  // rewinds from frames 5 and 1
        const double t = scene.timeOfFrame(f);
        rewound.cull(scene, cameraAt(scene, t), t, got);
    }
    for (int f = 0; f < 12; ++f) {
        const double t = scene.timeOfFrame(f);
        rewound.cull(scene, cameraAt(scene, t), t, got);
        EXPECT_EQ(got.pvs, want[size_t(f)].pvs) << "frame " << f;
        EXPECT_EQ(got.stats.get(Counter::TbvCreated),
                  want[size_t(f)].stats.get(Counter::TbvCreated))
            << "frame " << f;
    }
}

TEST(RgvcCuller, TeleportIntoABoundaryTbvRevealsIt) {
    Scene scene = floorScene();
    addSphere(scene, 0, {20, 80, 0}, 1);  // static, never in view
    addSphere(scene, 1, {60, 50, 0}, 1);
    moving(scene, {0.5, 0, 0});
    scene.finalize();
    // Frames 0-4 at (10, 50), the object beyond far; from frame 5 the camera
    // stands 3 units from it, inside its TBV's curve, looking at it. The curve's
    // voxels in the wedge lie beyond far, so only the teleport rule can find it.
    scene.camera.fov_deg = 60;
    scene.camera.far = 4;
    scene.camera.path = {CameraKey{0.0, {10, 50, 0}, {90, 50, 0}, {0, 1, 0}},
                         CameraKey{0.45, {10, 50, 0}, {90, 50, 0}, {0, 1, 0}},
                         CameraKey{0.46, {60.5, 53.5, 0}, {60.5, 0, 0}, {0, 1, 0}}};
    RgvcCuller rgvc;
    rgvc.setDebugCapture(true);
    const std::vector<FrameResult> frames = runChecked(scene, 8, rgvc);
    EXPECT_FALSE(has(frames[4].pvs, 1));
    EXPECT_EQ(frames[5].stats.get(Counter::TbvRevealed), 1);
    EXPECT_TRUE(has(frames[5].pvs, 1));
}

TEST(RgvcCuller, ObjectsOutsideTheGridAreKeptWhenInTheFrustum) {
    Scene scene = floorScene();
    addSphere(scene, 0, {106, 50, 0}, 3);  // wholly outside, ahead
    addSphere(scene, 1, {99, 40, 0}, 3);   // straddling the edge, ahead
    addSphere(scene, 2, {-6, 50, 0}, 3);   // wholly outside, behind the camera
    addSphere(scene, 3, {80, 120, 0}, 2);  // wholly outside, moving, ahead
    moving(scene, {0, -1, 0});
    scene.finalize();
    test::setCamera(scene, {20, 50, 0}, {90, 50, 0}, 120);
    RgvcCuller rgvc;
    const std::vector<FrameResult> frames = runChecked(scene, 5, rgvc);
    EXPECT_TRUE(has(frames[0].pvs, 0));
    EXPECT_TRUE(has(frames[0].pvs, 1));
    EXPECT_FALSE(has(frames[0].pvs, 2));
    EXPECT_TRUE(has(frames[4].pvs, 3));
}

// Looking at a full-height wall for 1 s, then turning away, then a viewpoint
// beyond the wall: the mover behind it is hidden, then in view again.
void lookAwayAndBeyond(Scene& scene) {
    scene.camera.fov_deg = 90;
    scene.camera.path = {CameraKey{0.0, {10, 50, 0}, {90, 50, 0}, {0, 1, 0}},
                         CameraKey{1.0, {10, 50, 0}, {90, 50, 0}, {0, 1, 0}},
                         CameraKey{1.01, {60, 50, 0}, {60, 0, 0}, {0, 1, 0}},
                         CameraKey{1.5, {60, 50, 0}, {60, 0, 0}, {0, 1, 0}},
                         CameraKey{1.51, {60, 50, 0}, {100, 50, 0}, {0, 1, 0}}};
}

TEST(RgvcCuller, TbvOfAnObjectThatCanLeaveTheGridIsKeptOutOfT) {
    Scene scene = floorScene();
    addBox(scene, 0, {40, 0, 0}, {42, 100, 0});  // a full-height wall
    addSphere(scene, 1, {96, 50, 0}, 1);         // behind it, near the grid's edge
    // Keyframes may leave the world: this one goes 20 units past its edge.
    SceneObject& mover = scene.objects.back();
    mover.motion.kind = MotionKind::Keyframes;
    mover.motion.keys = {{0.0, {96, 50, 0}}, {2.0, {120, 50, 0}}};
    mover.motion.max_speed = 12.0;
    scene.finalize();
    lookAwayAndBeyond(scene);
    RgvcCuller rgvc;
    rgvc.setDebugCapture(true);
    ExactOracle exact;
    rgvc.reset(scene);
    exact.reset(scene);
    bool saw_edge_tbv = false;
    FrameResult got, want;
    for (int f = 0; f < 20; ++f) {
        const double t = scene.timeOfFrame(f);
        const Camera camera = cameraAt(scene, t);
        rgvc.cull(scene, camera, t, got);
        exact.cull(scene, camera, t, want);
        EXPECT_TRUE(test::isSubset(want.pvs, got.pvs)) << "frame " << f;
        for (const RgvcTbvView& tbv : rgvc.snapshot().tbv_list) {
            EXPECT_TRUE(tbv.edge);
            saw_edge_tbv = true;
            // An edge TBV is never written into T.
            for (int y = 0; y < 100; ++y)
                for (int x = 0; x < 100; ++x)
                    ASSERT_FALSE(rgvc.snapshot().tbvs->contains(x, y, tbv.object_index));
        }
    }
    EXPECT_TRUE(saw_edge_tbv);
}

TEST(RgvcCuller, TbvOfAnObjectThatStaysInTheGridIsCutToItAndNotRevealedEveryFrame) {
    Scene scene = floorScene();
    addBox(scene, 0, {40, 0, 0}, {42, 100, 0});  // a full-height wall
    addSphere(scene, 1, {96, 50, 0}, 1);         // behind it, near the grid's edge
    moving(scene, {0, 3, 0});                    // linear motion folds back at the world's walls
    scene.finalize();
    lookAwayAndBeyond(scene);
    // A TBV valid for an hour: its disc would cover the whole grid and beyond.
    RgvcOptions options;
    options.validity_s = 3600.0;
    RgvcCuller rgvc(options);
    rgvc.setDebugCapture(true);
    const std::vector<FrameResult> frames = runChecked(scene, 20, rgvc);
    // Frames 1 to 9 look at the wall. The first TBVs, shortened only to leave
    // the viewer outside, reach in front of the wall and are seen; each reveal
    // halves the next period until the TBV stays behind the wall.
    int64_t revealed = 0;
    for (int f = 1; f < 10; ++f) revealed += frames[size_t(f)].stats.get(Counter::TbvRevealed);
    EXPECT_GE(revealed, 1);
    EXPECT_LE(revealed, 3);
    for (int f = 5; f < 10; ++f) {  // then neither revealed nor renewed
        EXPECT_EQ(frames[size_t(f)].stats.get(Counter::TbvRevealed), 0) << "frame " << f;
        EXPECT_EQ(frames[size_t(f)].stats.get(Counter::TbvCreated), 0) << "frame " << f;
    }
    EXPECT_TRUE(has(frames.back().pvs, 1));  // seen again from beyond the wall
}

TEST(RgvcCuller, ViewpointsMillionsOfVoxelsAwayStayConservative) {
    // [0, 1]^2 in 100 x 100 voxels of 0.01: a viewpoint 5e6 units away is 5e8
    // voxels away (rings of 4e9 voxels), one 1e7 away is where voxelOf clamps.
    Scene scene = test::makeScene(2, Aabb{{0, 0, 0}, {1, 1, 0}}, {100, 100, 1});
    addBox(scene, 0, {0.4, 0.2, 0}, {0.42, 0.8, 0});
    addSphere(scene, 1, {0.7, 0.5, 0}, 0.05);
    addSphere(scene, 2, {0.2, 0.5, 0}, 0.05);
    scene.finalize();
    for (const double distance : {5e6, 1e7, 1e9}) {
        test::setCamera(scene, {-distance, 0.5, 0}, {0, 0.5, 0}, 10, 0.1, 2e9);
        RgvcCuller rgvc;
        ExactOracle exact;
        const std::vector<int> got = test::cullIds(rgvc, scene);
        EXPECT_TRUE(test::isSubset(test::cullIds(exact, scene), got)) << "distance " << distance;
        EXPECT_TRUE(has(got, 0) && has(got, 2)) << "distance " << distance;
    }
}

TEST(RgvcCuller, ViewerInsideAnObjectSeesIt) {
    Scene scene = floorScene();
    addBox(scene, 0, {10, 10, 0}, {30, 30, 0});
    addSphere(scene, 1, {60, 20, 0}, 3);
    scene.finalize();
    test::setCamera(scene, {20, 20, 0}, {90, 20, 0}, 90);
    RgvcCuller rgvc;
    EXPECT_TRUE(has(test::cullIds(rgvc, scene), 0));
}

TEST(RgvcCuller, SnapshotOnlyWhenAsked) {
    Scene scene = floorScene();
    addBox(scene, 0, {40, 10, 0}, {42, 90, 0});
    addSphere(scene, 1, {70, 50, 0}, 3);
    moving(scene, {1, 0, 0});
    scene.finalize();
    test::setCamera(scene, {10, 50, 0}, {90, 50, 0}, 90);
    RgvcCuller rgvc;
    test::cullIds(rgvc, scene);
    EXPECT_FALSE(rgvc.snapshot().valid);
    EXPECT_TRUE(rgvc.snapshot().visits.empty());
    EXPECT_GT(rgvc.snapshot().memory.total(), size_t(0));
    rgvc.setDebugCapture(true);
    test::cullIds(rgvc, scene);
    const RgvcSnapshot& snap = rgvc.snapshot();
    ASSERT_TRUE(snap.valid);
    EXPECT_FALSE(snap.visits.empty());
    EXPECT_FALSE(snap.seeds.empty());
    EXPECT_FALSE(snap.occluders.empty());
    EXPECT_TRUE(snap.terminated_early);  // the wall fills the view from layer 30 on
    EXPECT_EQ(snap.viewer_voxel, glm::i64vec2(10, 50));
    EXPECT_TRUE(snap.occluder->get(41, 50));
    EXPECT_TRUE(snap.static_occluder->get(41, 50));
    EXPECT_TRUE(snap.occlusion->get(80, 50));
    EXPECT_TRUE(snap.identifiers_static->contains(40, 50, 0));
    EXPECT_EQ(snap.memory.total(), rgvc.memory().total());
}

}  // namespace
}  // namespace gridcull
