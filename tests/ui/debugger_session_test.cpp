// The debugger's culling side (ui/debugger_session.h): scrubbing, algorithm
// switches and a frozen culling camera must give what running the frames in
// order gives; and the per-object states must name false culls.
#include "ui/debugger_session.h"

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"
#include "ui/object_states.h"

namespace gridcull {
namespace {

// A small oracle keeps the test fast; what is compared is consistency, not accuracy.
KnobValues fastOptions() {
    KnobValues knobs;
    knobs.set("oracle-res", 96);
    knobs.set("oracle-rays", 2048);
    return knobs;
}

TEST(DebuggerSession, ScrubbingBackGivesWhatRunningInOrderGives) {
    const Scene scene = defaultScene();
    DebuggerSession session(fastOptions());
    std::string error;
    ASSERT_TRUE(session.open(scene, "", "vfc", error)) << error;
    EXPECT_EQ(session.frame(), 0);
    session.seek(12);
    EXPECT_EQ(session.frame(), 12);
    session.seek(5);
    EXPECT_EQ(session.frame(), 5);
    const std::vector<int> after_scrub = session.result().pvs;

    DebuggerSession fresh(fastOptions());
    ASSERT_TRUE(fresh.open(scene, "", "vfc", error)) << error;
    for (int f = 1; f <= 5; ++f) ASSERT_TRUE(fresh.step());
    EXPECT_EQ(fresh.frame(), 5);
    EXPECT_EQ(after_scrub, fresh.result().pvs);
    EXPECT_FALSE(after_scrub.empty());
    EXPECT_EQ(session.history().pvs_size[5], float(after_scrub.size()));
    EXPECT_EQ(session.history().exact_visible[5], float(session.exactResult().pvs.size()));
}

TEST(DebuggerSession, SeekClampsAndStepStopsAtTheEnd) {
    const Scene scene = defaultScene();
    DebuggerSession session(fastOptions());
    std::string error;
    ASSERT_TRUE(session.open(scene, "", "vfc", error)) << error;
    session.seek(scene.frames + 50);
    EXPECT_EQ(session.frame(), scene.frames - 1);
    EXPECT_FALSE(session.step());
    EXPECT_EQ(session.frame(), scene.frames - 1);
    session.seek(-3);
    EXPECT_EQ(session.frame(), 0);
}

TEST(DebuggerSession, AllAlgorithmKeepsEverythingAndNeverFalseCulls) {
    const Scene scene = defaultScene();
    DebuggerSession session(fastOptions());
    std::string error;
    ASSERT_TRUE(session.open(scene, "", "vfc", error)) << error;
    session.seek(8);
    ASSERT_TRUE(session.selectAlgorithm("all", error)) << error;
    EXPECT_EQ(session.frame(), 8);
    EXPECT_EQ(session.result().pvs.size(), scene.objects.size());
    EXPECT_TRUE(session.falseCulled().empty());
    for (ObjectState state : session.states())
        EXPECT_TRUE(state == ObjectState::Visible || state == ObjectState::Hidden);
    EXPECT_FALSE(session.selectAlgorithm("no-such-culler", error));
    EXPECT_FALSE(error.empty());
    EXPECT_EQ(session.algo(), "all");
}

TEST(DebuggerSession, FrozenCameraStaysWhileTimeMoves) {
    const Scene scene = defaultScene();
    DebuggerSession session(fastOptions());
    std::string error;
    ASSERT_TRUE(session.open(scene, "", "vfc", error)) << error;
    session.seek(3);
    const Camera at3 = session.cullingCamera();
    session.setCullingCameraFrozen(true);
    session.seek(30);
    EXPECT_TRUE(session.cullingCameraFrozen());
    EXPECT_EQ(session.cullingCamera().position, at3.position);
    EXPECT_EQ(session.cullingCamera().target, at3.target);
    session.setCullingCameraFrozen(false);
    EXPECT_EQ(session.frame(), 30);
    EXPECT_EQ(session.cullingCamera().position, cameraAt(scene, scene.timeOfFrame(30)).position);
}

// A step back restores the latest checkpoint and replays at most an interval of
// frames (the selected culler alone but for the frame shown), and shows what
// running the frames in order shows: the same PVS, oracle and states. Every
// family with temporal state, on scenes where it keeps some.
TEST(DebuggerSession, StepsBackFromACheckpointAsIfRunInOrder) {
    struct Case {
        const char* algo;
        const char* scene;
    };
    for (const Case c :
         {Case{"rgvc", "default"}, Case{"rgvc", "scenes/hidden-movers-3d.json"},
          Case{"hzb-tbv", "scenes/hidden-movers-3d.json"}, Case{"bsp-oq", "scenes/bunnies-3d.json"},
          Case{"lazy-grid", "scenes/forest-3d.json"}}) {
        SCOPED_TRACE(std::string(c.algo) + " on " + c.scene);
        Scene scene = defaultScene();
        if (std::string(c.scene) != "default") {
            SceneLoadResult loaded =
                loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/" + c.scene);
            ASSERT_TRUE(loaded.scene);
            scene = std::move(*loaded.scene);
        }
        constexpr int kFrom = 23, kTo = 12;
        ASSERT_GT(scene.frames, kFrom);
        std::string error;
        DebuggerSession in_order(fastOptions());
        ASSERT_TRUE(in_order.open(scene, "", c.algo, error)) << error;
        std::vector<std::vector<int>> pvs(kFrom + 1), exact(kFrom + 1), culled(kFrom + 1);
        for (int f = 0; f <= kFrom; ++f) {
            if (f > 0) {
                ASSERT_TRUE(in_order.step());
            }
            EXPECT_EQ(in_order.lastReplayedFrames(), 1);
            pvs[size_t(f)] = in_order.result().pvs;
            exact[size_t(f)] = in_order.exactResult().pvs;
            culled[size_t(f)] = in_order.falseCulled();
        }
        ASSERT_TRUE(in_order.checkpoints().enabled());
        EXPECT_EQ(in_order.checkpoints().count(), kFrom / kDefaultCheckpointInterval + 1);

        DebuggerSession session(fastOptions());
        ASSERT_TRUE(session.open(scene, "", c.algo, error)) << error;
        session.seek(kFrom);
        for (int f = kFrom - 1; f >= kTo; --f) {
            session.seek(session.frame() - 1);
            ASSERT_EQ(session.frame(), f);
            EXPECT_GE(session.lastReplayedFrames(), 1);
            EXPECT_LE(session.lastReplayedFrames(), kDefaultCheckpointInterval);
            EXPECT_EQ(session.result().pvs, pvs[size_t(f)]) << "frame " << f;
            EXPECT_EQ(session.exactResult().pvs, exact[size_t(f)]) << "frame " << f;
            EXPECT_EQ(session.falseCulled(), culled[size_t(f)]) << "frame " << f;
            EXPECT_NE(session.debugSnapshot(), nullptr);
        }
        // A long jump back costs no more than a step, and forwards again goes on
        // from there.
        session.seek(2);
        EXPECT_LE(session.lastReplayedFrames(), kDefaultCheckpointInterval);
        EXPECT_EQ(session.result().pvs, pvs[2]);
        session.seek(kFrom);
        EXPECT_EQ(session.result().pvs, pvs[kFrom]);
        EXPECT_LE(session.lastReplayedFrames(), kDefaultCheckpointInterval);
    }
}

// A long seek runs on a worker while the session still shows where it was; once
// adopted it shows what running in order shows. A cancelled one leaves the
// session where it was, and a short one runs at once.
TEST(DebuggerSession, BackgroundSeeksAdoptOrCancelCleanly) {
    SceneLoadResult loaded =
        loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/hidden-movers-3d.json");
    ASSERT_TRUE(loaded.scene);
    const Scene& scene = *loaded.scene;
    constexpr int kTarget = 60;
    std::string error;
    DebuggerSession in_order(fastOptions());
    ASSERT_TRUE(in_order.open(scene, "", "hzb-tbv", error)) << error;
    for (int f = 1; f <= kTarget; ++f) ASSERT_TRUE(in_order.step());

    DebuggerSession session(fastOptions());
    ASSERT_TRUE(session.open(scene, "", "hzb-tbv", error)) << error;
    const std::vector<int> at0 = session.result().pvs;
    session.seekInBackground(kTarget);
    ASSERT_TRUE(session.seeking());
    EXPECT_EQ(session.seekTarget(), kTarget);
    EXPECT_EQ(session.frame(), 0);  // still showing frame 0
    EXPECT_EQ(session.result().pvs, at0);
    while (!session.pollSeek()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_FALSE(session.seeking());
    EXPECT_EQ(session.frame(), kTarget);
    EXPECT_EQ(session.lastReplayedFrames(), kTarget);
    EXPECT_EQ(session.result().pvs, in_order.result().pvs);
    EXPECT_EQ(session.exactResult().pvs, in_order.exactResult().pvs);
    EXPECT_EQ(session.history().pvs_size[kTarget / 2], in_order.history().pvs_size[kTarget / 2]);
    ASSERT_NE(session.debugSnapshot(), nullptr);
    // The worker left its checkpoints: a step back replays a few frames.
    session.seek(kTarget - 1);
    EXPECT_LE(session.lastReplayedFrames(), kDefaultCheckpointInterval);

    // Cancelled: still at kTarget - 1, and going on from there is unharmed.
    const std::vector<int> before = session.result().pvs;
    session.seekInBackground(scene.frames - 1);
    session.cancelSeek();
    EXPECT_FALSE(session.seeking());
    EXPECT_FALSE(session.pollSeek());
    EXPECT_EQ(session.frame(), kTarget - 1);
    EXPECT_EQ(session.result().pvs, before);
    ASSERT_TRUE(session.step());
    EXPECT_EQ(session.result().pvs, in_order.result().pvs);

    // Near a checkpoint: at once, no worker.
    session.seekInBackground(kTarget - 3);
    EXPECT_FALSE(session.seeking());
    EXPECT_EQ(session.frame(), kTarget - 3);
}

TEST(ObjectStates, ComparesPvsWithTheOracle) {
    Scene scene;
    for (int id : {4, 1, 3, 2, 5, 6}) {
        SceneObject object;
        object.id = id;
        object.radius = 1.0;
        scene.objects.push_back(object);
    }
    scene.finalize();
    std::vector<ObjectState> states;
    std::vector<int> false_culled;
    // 5 and 6 are the oracle's sub-sample objects: 5 culled, 6 kept.
    FrameResult exact;
    exact.pvs = {2, 3};
    exact.sub_sample_visible = {5};
    exact.sub_sample_undecided = {6};
    classifyObjects(scene, {1, 2, 6}, exact, states, false_culled);
    ASSERT_EQ(states.size(), 6u);
    EXPECT_EQ(states[size_t(scene.indexOf(1))], ObjectState::Hidden);
    EXPECT_EQ(states[size_t(scene.indexOf(2))], ObjectState::Visible);
    EXPECT_EQ(states[size_t(scene.indexOf(3))], ObjectState::FalseCulled);
    EXPECT_EQ(states[size_t(scene.indexOf(4))], ObjectState::Culled);
    EXPECT_EQ(states[size_t(scene.indexOf(5))], ObjectState::SubSample);
    EXPECT_EQ(states[size_t(scene.indexOf(6))], ObjectState::Hidden);
    EXPECT_EQ(false_culled, std::vector<int>{3});
    // Unknown ids are ignored rather than trusted.
    exact.pvs = {99};
    exact.sub_sample_visible = {98};
    exact.sub_sample_undecided.clear();
    classifyObjects(scene, {1, 99}, exact, states, false_culled);
    EXPECT_TRUE(false_culled.empty());
}

}  // namespace
}  // namespace gridcull
