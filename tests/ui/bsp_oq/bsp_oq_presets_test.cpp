// The bsp family's overlay presets (ui/bsp_oq/bsp_oq_view.h) through its view
// from the ui registry, looked at through the culling camera: a new view starts
// with "occlusion only" (the query rectangles and the states a query decided,
// which --bsp-show-nodes's default names), "traversal" shows every node the
// traversal reached and no rectangles, "all" every node and the rectangles;
// the flags override the preset only when given.
#include <memory>
#include <set>

#include <gtest/gtest.h>

#include "culling/bsp_oq/bsp_oq_snapshot.h"
#include "culling/io/scene_loader.h"
#include "tests/ui/overlay_swatches.h"
#include "ui/bsp_oq/bsp_oq_view.h"
#include "ui/debugger_session.h"
#include "ui/registry/family_views.h"

namespace gridcull {
namespace {

class BspOqPresetsTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        KnobValues knobs;
        knobs.set("oracle-res", 160);
        session_ = new DebuggerSession(knobs);
        SceneLoadResult loaded =
            loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/hidden-movers-3d.json");
        ASSERT_TRUE(loaded.scene);
        std::string error;
        ASSERT_TRUE(session_->open(std::move(*loaded.scene), "", "bsp-oq", error)) << error;
        session_->seek(30);
    }
    static void TearDownTestSuite() {
        delete session_;
        session_ = nullptr;
    }

    void SetUp() override {
        snap_ = session_->debugSnapshot()->as<BspOqSnapshot>();
        ASSERT_NE(snap_, nullptr);
        view_ = findFamilyView("bsp")->make();
        context_.scene = &session_->scene();
        context_.snapshot = snap_;
        const Camera& camera = session_->cullingCamera();
        overlay_.width = 960;
        overlay_.height = int(960 / camera.aspect);
        overlay_.through_culling_camera = true;
        overlay_.culling_aspect = camera.aspect;
    }

    // The node states drawn (World space: by their swatches), and whether any
    // query rectangle is (View space).
    std::set<Swatch> drawn(bool& queries) {
        batch_.clear();
        view_->drawOverlay(context_, overlay_, batch_);
        queries = false;  // a cleared batch keeps its (empty) line sets
        for (const DebugDrawBatch::LineSet& set : batch_.layer(DrawSpace::View).lines)
            queries = queries || !set.vertices.empty();
        return test::swatchesIn(batch_, DrawSpace::World);
    }
    // The swatches of the states in `mask` that some scene node is in.
    std::set<Swatch> statesIn(int mask) const {
        std::set<Swatch> out;
        for (const BspNodeRecord& n : snap_->scene_nodes)
            if ((mask >> int(n.state)) & 1) out.insert(bspNodeStateSwatch(n.state));
        return out;
    }

    static DebuggerSession* session_;
    const BspOqSnapshot* snap_ = nullptr;
    std::unique_ptr<FamilyView> view_;
    FamilyViewContext context_;
    OverlayView overlay_;
    DebugDrawBatch batch_;
};

DebuggerSession* BspOqPresetsTest::session_ = nullptr;

constexpr int kEvery = (1 << kBspNodeStateCount) - 1;
constexpr int kNotReached = 1 << int(BspNodeState::NotReached);

TEST_F(BspOqPresetsTest, EachPresetDrawsItsStatesAndRectangles) {
    ASSERT_FALSE(snap_->queries.empty());
    EXPECT_EQ(view_->overlayPresets(), (std::vector<OverlayPreset>{OverlayPreset::Occlusion,
                                                                   OverlayPreset::Traversal,
                                                                   OverlayPreset::All}))
        << "no TBVs: the family has none";
    const int occlusion = bspNodeMask(BspOqViewState{});
    EXPECT_EQ(occlusion, 8 | 16 | 32 | 64 | 128) << "--bsp-show-nodes's documented default";
    ASSERT_NE(statesIn(occlusion), statesIn(kEvery & ~kNotReached)) << "nodes only traversal shows";
    ASSERT_NE(statesIn(kEvery & ~kNotReached), statesIn(kEvery)) << "nodes not reached";

    bool queries = false;
    std::set<Swatch> s = drawn(queries);
    EXPECT_TRUE(queries);
    EXPECT_EQ(s, statesIn(occlusion));

    view_->applyOverlayPreset(OverlayPreset::Traversal);
    s = drawn(queries);
    EXPECT_FALSE(queries);
    EXPECT_EQ(s, statesIn(kEvery & ~kNotReached));

    view_->applyOverlayPreset(OverlayPreset::All);
    s = drawn(queries);
    EXPECT_TRUE(queries);
    EXPECT_EQ(s, statesIn(kEvery));

    // A flag given overrides its toggle over the preset; one not given leaves it.
    KnobValues flags;
    flags.set("bsp-show-queries", 0);
    std::string error;
    ASSERT_TRUE(view_->applyFlags(flags, session_->scene(), error)) << error;
    s = drawn(queries);
    EXPECT_FALSE(queries);
    EXPECT_EQ(s, statesIn(kEvery)) << "the nodes as the preset has them";
}

}  // namespace
}  // namespace gridcull
