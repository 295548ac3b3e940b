// Two cullers side by side (app/debugger_panes.cpp): the compared one follows the
// shown frame forwards and back, the frozen camera and the knobs; the objects
// called different are exactly those in one PVS and not the other; a culler
// that does not run on the scene is refused; the view splits into two panes.
// Needs a GL context (xvfb-run in the tests).
#include <algorithm>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/debugger.h"
#include "app/gl_context.h"
#include "culling/io/scene_loader.h"
#include "run_command.h"

namespace gridcull {
namespace {

class DebuggerCompareTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(window_.create(64, 64, "gridcull test", false, error)) << error;
        options_.knobs.set("oracle-res", 96);
        SceneLoadResult loaded = loadSceneFile(test::sourcePath("scenes/hidden-movers-3d.json"));
        ASSERT_TRUE(loaded.scene);
        scene_ = std::move(*loaded.scene);
        options_.algo = "hzb-tbv";
        options_.compare = "vfc";
    }
    // Indices of the objects in exactly one of the two PVS (ids ascending).
    std::vector<int> symmetricDifference(Debugger& debugger) const {
        const std::vector<int>& a = debugger.session().result().pvs;
        const std::vector<int>& b = debugger.compareSession()->result().pvs;
        std::vector<int> ids;
        std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(),
                                      std::back_inserter(ids));
        std::vector<int> indices;
        for (int id : ids) indices.push_back(scene_.indexOf(id));
        std::sort(indices.begin(), indices.end());
        return indices;
    }
    void expectInStep(Debugger& debugger) {
        debugger.syncCompare(true);
        ASSERT_NE(debugger.compareSession(), nullptr);
        EXPECT_EQ(debugger.compareSession()->frame(), debugger.session().frame());
        EXPECT_EQ(debugger.differingObjects(), symmetricDifference(debugger));
    }

    GlWindow window_;
    ViewOptions options_;
    Scene scene_;
};

TEST_F(DebuggerCompareTest, TheComparedCullerFollowsTheFrameAndTheDifferenceIsExact) {
    Debugger debugger(options_);
    std::string error;
    ASSERT_TRUE(debugger.init(scene_, error)) << error;
    expectInStep(debugger);
    for (int k = 0; k < 30; ++k) debugger.stepForward();
    expectInStep(debugger);
    EXPECT_FALSE(debugger.differingObjects().empty()) << "hzb-tbv culls what vfc keeps";
    debugger.stepBack();
    expectInStep(debugger);
    UiActions seek;
    seek.playback.seek_frame = 5;
    debugger.apply(seek);
    while (debugger.session().seeking()) debugger.advancePlayback(0.0);
    expectInStep(debugger);
}

TEST_F(DebuggerCompareTest, TheFrozenCameraAndTheKnobsAreShared) {
    Debugger debugger(options_);
    std::string error;
    ASSERT_TRUE(debugger.init(scene_, error)) << error;
    for (int k = 0; k < 10; ++k) debugger.stepForward();
    debugger.toggleFreeze();
    for (int k = 0; k < 10; ++k) debugger.stepForward();
    expectInStep(debugger);
    const DebuggerSession& compared = *debugger.compareSession();
    EXPECT_TRUE(compared.cullingCameraFrozen());
    EXPECT_EQ(compared.frozenAt(), debugger.session().frozenAt());
    EXPECT_EQ(compared.cullingCamera().position, debugger.session().cullingCamera().position);

    UiActions knobs;
    knobs.knobs.apply = true;
    knobs.knobs.set = {{"oracle-res", 64}};
    debugger.apply(knobs);
    expectInStep(debugger);
    EXPECT_EQ(debugger.compareSession()->knobs().set_values().at("oracle-res"), 64.0);
}

TEST_F(DebuggerCompareTest, AComparedCullerMustRunOnTheSceneAndNoneEndsTheSplit) {
    Debugger debugger(options_);
    std::string error;
    ASSERT_TRUE(debugger.init(scene_, error)) << error;
    const WindowLayout layout = computeLayout(1280, 720, true);
    EXPECT_EQ(debugger.panes(layout).count, 2);
    EXPECT_TRUE(debugger.panes(layout).pane[1].compared);
    EXPECT_FALSE(debugger.setCompare("no-such-culler", error));
    EXPECT_NE(debugger.compareSession(), nullptr) << "a refused one keeps the current";
    ASSERT_TRUE(debugger.setCompare("", error));
    EXPECT_EQ(debugger.compareSession(), nullptr);
    EXPECT_EQ(debugger.panes(layout).count, 1);
    EXPECT_TRUE(debugger.differingObjects().empty());
}

}  // namespace
}  // namespace gridcull
