// The window offers only what fits the scene (app/debugger.h): its culler list is
// the registry's algorithms for the scene's dimension, a window asked for one
// that does not run on the scene refuses naming the dimension, and opening a
// scene the selected culler does not run on switches to one that does, with a
// note the scene panel shows. The family's view follows the selected culler.
// Needs a GL context (the test run provides an X display, under xvfb-run).
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "app/debugger.h"
#include "app/gl_api.h"
#include "app/gl_context.h"
#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"
#include "run_command.h"

namespace gridcull {
namespace {

Scene load(const char* name) {
    SceneLoadResult loaded = loadSceneFile(test::sourcePath(std::string("scenes/") + name));
    EXPECT_TRUE(loaded.scene) << name;
    return loaded.scene ? std::move(*loaded.scene) : Scene{};
}

bool offers(const Debugger& debugger, const std::string& name) {
    const std::vector<std::string>& names = debugger.offeredAlgorithms();
    return std::find(names.begin(), names.end(), name) != names.end();
}

void select(Debugger& debugger, const std::string& name);

class DebuggerTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(window_.create(64, 64, "gridcull test", false, error)) << error;
        options_.knobs.set("oracle-res", 96);
        options_.knobs.set("oracle-rays", 2048);
    }
    GlWindow window_;
    ViewOptions options_;
};

TEST_F(DebuggerTest, OffersOnlyTheAlgorithmsOfTheScenesDimension) {
    options_.algo = "lazy-grid";
    Debugger debugger(options_);
    std::string error;
    ASSERT_TRUE(debugger.init(load("forest-3d.json"), error)) << error;
    EXPECT_TRUE(offers(debugger, "lazy-grid"));
    EXPECT_TRUE(offers(debugger, "rgvc"));  // runs on 2D and 3D scenes
    ASSERT_NE(debugger.session().debugSnapshot(), nullptr);
    EXPECT_STREQ(debugger.session().debugSnapshot()->kind().family, "lazy-grid");
    debugger.drawScene(computeLayout(640, 360, false), 360);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

    // A 2D scene: the lazy grid does not run there, so the window switches to
    // the culler it opens with.
    debugger.openSceneFile(test::sourcePath("scenes/walls-2d.json"));
    EXPECT_EQ(debugger.session().scene().dimensions, 2);
    EXPECT_EQ(debugger.session().algo(), defaultAlgorithm());
    EXPECT_NE(debugger.note().find("lazy-grid runs on 3D scenes only, and this scene is 2D"),
              std::string::npos)
        << debugger.note();
    EXPECT_NE(debugger.note().find(std::string("switched to ") + defaultAlgorithm()),
              std::string::npos)
        << debugger.note();
    EXPECT_TRUE(offers(debugger, "rgvc"));
    EXPECT_FALSE(offers(debugger, "lazy-grid"));

    // Picking a culler from the list clears the note; picking rgvc brings its
    // view and snapshot.
    select(debugger, "vfc");
    EXPECT_TRUE(debugger.note().empty());
    EXPECT_EQ(debugger.session().debugSnapshot(), nullptr);
    select(debugger, "rgvc");
    EXPECT_TRUE(debugger.note().empty());
    ASSERT_NE(debugger.session().debugSnapshot(), nullptr);
    EXPECT_STREQ(debugger.session().debugSnapshot()->kind().family, "rgvc");
    debugger.drawScene(computeLayout(640, 360, false), 360);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// `gridcull` alone opens the built-in default scene with regular-grid
// culling, its panel and overlay (the 3D voxel boxes) drawn.
TEST_F(DebuggerTest, TheDefaultSceneOpensWithRgvc) {
    EXPECT_EQ(ViewOptions{}.algo, "rgvc");
    Debugger debugger(options_);
    std::string error;
    ASSERT_TRUE(debugger.init(defaultScene(), error)) << error;
    EXPECT_EQ(debugger.session().algo(), "rgvc");
    ASSERT_NE(debugger.session().debugSnapshot(), nullptr);
    EXPECT_STREQ(debugger.session().debugSnapshot()->kind().family, "rgvc");
    debugger.drawScene(computeLayout(640, 360, false), 360);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

void select(Debugger& debugger, const std::string& name) {
    UiActions actions;
    const std::vector<std::string>& names = debugger.offeredAlgorithms();
    actions.algorithm.select_algo =
        int(std::find(names.begin(), names.end(), name) - names.begin());
    debugger.apply(actions);
    ASSERT_EQ(debugger.session().algo(), name);
}

// A family's view keeps its state (here the object --lazy-object picked) when
// another culler is selected and this one again; the flag's pick belongs to the
// scene it named an object of, so another scene starts without it.
TEST_F(DebuggerTest, FamilyViewStateSurvivesSwitchingAndFlagsStayWithTheirScene) {
    options_.algo = "lazy-grid";
    const Scene forest = load("forest-3d.json");
    options_.view_flags.set("lazy-object", 2300);
    Debugger debugger(options_);
    std::string error;
    ASSERT_TRUE(debugger.init(forest, error)) << error;
    const int picked = forest.indexOf(2300);
    ASSERT_GE(picked, 0);
    EXPECT_EQ(debugger.outlinedObject(), picked);
    select(debugger, "vfc");
    EXPECT_EQ(debugger.outlinedObject(), -1) << "vfc's family has no view: nothing under the mouse";
    select(debugger, "lazy-grid-z");  // the same family: the same view
    EXPECT_EQ(debugger.outlinedObject(), picked);
    debugger.openSceneFile(test::sourcePath("scenes/city-3d.json"));
    EXPECT_EQ(debugger.session().algo(), "lazy-grid-z");
    EXPECT_EQ(debugger.outlinedObject(), -1) << "a pick of the old scene is forgotten";
    select(debugger, "vfc");
    select(debugger, "lazy-grid");
    EXPECT_EQ(debugger.outlinedObject(), -1) << "the flag is not applied to another scene";
}

TEST_F(DebuggerTest, RefusesAnAlgorithmThatDoesNotRunOnTheScene) {
    options_.algo = "lazy-grid";
    Debugger debugger(options_);
    std::string error;
    EXPECT_FALSE(debugger.init(load("walls-2d.json"), error));
    EXPECT_NE(error.find("lazy-grid runs on 3D scenes only, and this scene is 2D"),
              std::string::npos)
        << error;
}

// The knobs panel's Apply: the cullers are re-made with the knobs set and the
// ones returned to auto, re-run to the current frame, and the cost recorded; a
// value out of range is shown as an error and changes nothing.
TEST_F(DebuggerTest, KnobsPanelAppliesKnobsAndRecordsTheirCost) {
    options_.algo = "lazy-grid";
    options_.knobs.set("lazy-res", 64);
    Debugger debugger(options_);
    std::string error;
    ASSERT_TRUE(debugger.init(load("forest-3d.json"), error)) << error;
    debugger.session().seek(5);
    EXPECT_FALSE(debugger.snapshot().knob_cost.valid);

    UiActions actions;
    actions.knobs.apply = true;
    actions.knobs.set = {{"lazy-cell-size", 8.0}, {"oracle-rays", 4096.0}};
    actions.knobs.unset = {"lazy-res"};  // back to auto: the oracle's resolution
    debugger.apply(actions);
    const KnobValues& knobs = debugger.session().knobs();
    EXPECT_EQ(knobs.get(*findKnob("lazy-cell-size")), 8.0);
    EXPECT_FALSE(knobs.has("lazy-res"));
    EXPECT_EQ(debugger.session().frame(), 5);
    const FrameSnapshot shown = debugger.snapshot();
    EXPECT_EQ(shown.knobs, &knobs);
    ASSERT_TRUE(shown.knob_cost.valid);
    EXPECT_EQ(shown.knob_cost.frames, 6);
    EXPECT_GT(shown.knob_cost.pvs_ratio_after, 0.0);
    EXPECT_TRUE(shown.scene_errors->empty());

    actions.knobs.set = {{"oracle-res", 1.0}};  // below its range, 16 to 8192
    actions.knobs.unset.clear();
    debugger.apply(actions);
    EXPECT_EQ(debugger.session().knobs().get(*findKnob("oracle-res")),
              options_.knobs.get(*findKnob("oracle-res")));
    ASSERT_FALSE(debugger.snapshot().scene_errors->empty());
    EXPECT_NE(debugger.snapshot().scene_errors->front().find("oracle-res"), std::string::npos);
}

// The scene picker lists the files opened, most recent first, then the other
// scene files beside the current one, each once; picking one opens it.
TEST_F(DebuggerTest, ScenePickerListsRecentFilesThenTheScenesBesideThem) {
    Debugger debugger(options_);
    std::string error;
    ASSERT_TRUE(debugger.init(load("walls-2d.json"), error)) << error;
    FrameSnapshot shown = debugger.snapshot();
    ASSERT_NE(shown.scene_choices, nullptr);
    EXPECT_EQ(shown.recent_scene_count, 1);
    const std::vector<std::string> first = *shown.scene_choices;
    ASSERT_GE(first.size(), 10u);  // scenes/ holds more than ten scene files
    EXPECT_EQ(first.front(), test::sourcePath("scenes/walls-2d.json"));
    auto count = [&](const std::vector<std::string>& list, const std::string& name) {
        return std::count_if(list.begin(), list.end(), [&](const std::string& f) {
            return f.size() >= name.size() &&
                   f.compare(f.size() - name.size(), name.size(), name) == 0;
        });
    };
    EXPECT_EQ(count(first, "/walls-2d.json"), 1);
    EXPECT_EQ(count(first, "/default.json"), 1);

    UiActions pick;
    pick.scene.open = true;
    pick.scene.path = test::sourcePath("scenes/rooms-2d.json");
    debugger.apply(pick);
    shown = debugger.snapshot();
    EXPECT_EQ(*shown.scene_file, pick.scene.path);
    EXPECT_EQ(shown.recent_scene_count, 2);
    EXPECT_EQ((*shown.scene_choices)[0], pick.scene.path);
    EXPECT_EQ((*shown.scene_choices)[1], test::sourcePath("scenes/walls-2d.json"));
    EXPECT_EQ(shown.scene_choices->size(), first.size());
}

// The command line refuses the same combinations before any window opens.
TEST(WindowCommands, RefuseAnAlgorithmOfTheOtherDimensionNamingIt) {
    const std::string flat = "'" + test::sourcePath("scenes/walls-2d.json") + "'";
    for (const std::string& args :
         {"shot " + flat + " --frame 0 --algo lazy-grid --out '" + test::scratchDir() + "/n.png'",
          "view " + flat + " --algo lazy-grid", "cull " + flat + " --algo busy-grid",
          "bench " + flat + " --algo vfc,lazy-grid-z",
          "view " + flat + " --algo busy-grid-tight"}) {
        const test::CommandResult r = test::runGridcull(args);
        EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
        EXPECT_NE(r.err.find(" scenes only, and this scene is "), std::string::npos) << r.err;
    }
}

}  // namespace
}  // namespace gridcull
