// The hzb family's overlay presets (ui/hzb_tbv/hzb_tbv_view.h) through its view
// from the ui registry, on the hidden movers (TBVs of hidden dynamic objects):
// a new view starts with "occlusion only" (the Z-pyramid and the nodes it hid),
// each preset draws its part and nothing else, the toggles' flags override the
// preset only when given.
#include <memory>
#include <set>

#include <gtest/gtest.h>

#include "culling/hzb_tbv/hzb_tbv_snapshot.h"
#include "culling/io/scene_loader.h"
#include "tests/ui/overlay_swatches.h"
#include "ui/debugger_session.h"
#include "ui/hzb_tbv/hzb_tbv_view.h"
#include "ui/registry/family_views.h"

namespace gridcull {
namespace {

class HzbTbvPresetsTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        KnobValues knobs;
        knobs.set("oracle-res", 160);
        session_ = new DebuggerSession(knobs);
        SceneLoadResult loaded =
            loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/hidden-movers-3d.json");
        ASSERT_TRUE(loaded.scene);
        std::string error;
        ASSERT_TRUE(session_->open(std::move(*loaded.scene), "", "hzb-tbv", error)) << error;
        session_->seek(60);
    }
    static void TearDownTestSuite() {
        delete session_;
        session_ = nullptr;
    }

    void SetUp() override {
        snap_ = session_->debugSnapshot()->as<HzbTbvSnapshot>();
        ASSERT_NE(snap_, nullptr);
        view_ = findFamilyView("hzb")->make();
        context_.scene = &session_->scene();
        context_.snapshot = snap_;
        overlay_.width = 900;
        overlay_.height = 720;
    }

    // What the view draws: World-space swatches (nodes, TBVs), and whether the
    // Z-pyramid images (View space) are drawn.
    std::set<Swatch> drawn(bool& pyramid) {
        batch_.clear();
        view_->drawOverlay(context_, overlay_, batch_);
        pyramid = !batch_.layer(DrawSpace::View).fill.empty();
        return test::swatchesIn(batch_, DrawSpace::World);
    }
    int64_t nodes(HzbNodeOutcome o) const { return snap_->node_count[size_t(o)]; }
    Swatch outcome(HzbNodeOutcome o) const { return hzbNodeOutcomeSwatch(o); }
    // The outcomes' swatches that some node has.
    std::set<Swatch> outcomes() const {
        std::set<Swatch> out;
        for (int o = 0; o < kHzbNodeOutcomeCount; ++o)
            if (nodes(HzbNodeOutcome(o)) > 0) out.insert(outcome(HzbNodeOutcome(o)));
        return out;
    }
    std::set<Swatch> bands() const {
        std::set<Swatch> out;
        for (const HzbTbvObject& o : snap_->objects)
            if (o.has_tbv) out.insert(hzbTbvBandSwatch(hzbTbvBandOf(o)));
        return out;
    }

    static DebuggerSession* session_;
    const HzbTbvSnapshot* snap_ = nullptr;
    std::unique_ptr<FamilyView> view_;
    FamilyViewContext context_;
    OverlayView overlay_;
    DebugDrawBatch batch_;
};

DebuggerSession* HzbTbvPresetsTest::session_ = nullptr;

TEST_F(HzbTbvPresetsTest, EachPresetDrawsItsPart) {
    ASSERT_FALSE(bands().empty()) << "hidden movers with TBVs";
    ASSERT_GT(nodes(HzbNodeOutcome::ZCulled), 0);
    ASSERT_GT(nodes(HzbNodeOutcome::Entered), 0);
    EXPECT_EQ(view_->overlayPresets(), hzbTbvOverlayPresets());
    ASSERT_EQ(hzbTbvOverlayPresets().front(), OverlayPreset::Occlusion);
    const auto noneOf = [](const std::set<Swatch>& s, const std::set<Swatch>& off) {
        for (Swatch w : off)
            if (s.count(w)) return false;
        return true;
    };

    // A new view: occlusion only.
    bool pyramid = false;
    std::set<Swatch> s = drawn(pyramid);
    EXPECT_TRUE(pyramid);
    EXPECT_EQ(s, std::set<Swatch>{outcome(HzbNodeOutcome::ZCulled)}) << "the nodes it hid";

    view_->applyOverlayPreset(OverlayPreset::Traversal);
    s = drawn(pyramid);
    EXPECT_FALSE(pyramid);
    EXPECT_EQ(s, outcomes());

    view_->applyOverlayPreset(OverlayPreset::Tbvs);
    s = drawn(pyramid);
    EXPECT_FALSE(pyramid);
    EXPECT_EQ(s, bands());

    view_->applyOverlayPreset(OverlayPreset::All);
    s = drawn(pyramid);
    EXPECT_TRUE(pyramid);
    EXPECT_EQ(s.size(), outcomes().size() + bands().size());
    EXPECT_FALSE(noneOf(s, bands()));

    // A flag given overrides its toggle over the preset; one not given leaves it.
    KnobValues flags;
    flags.set("hzb-show-pyramid", 0);
    std::string error;
    ASSERT_TRUE(view_->applyFlags(flags, session_->scene(), error)) << error;
    s = drawn(pyramid);
    EXPECT_FALSE(pyramid);
    EXPECT_EQ(s.size(), outcomes().size() + bands().size())
        << "nodes and TBVs as the preset has them";
}

}  // namespace
}  // namespace gridcull
