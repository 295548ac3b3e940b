// The hzb family in the window: the session's snapshot, the bands and picks of
// ui/hzb_tbv/hzb_tbv_view.h, the World-space overlay (TBVs and octree nodes,
// ui/hzb_tbv/hzb_tbv_overlay.h) and the Z-pyramid images (View space,
// ui/hzb_tbv/hzb_pyramid_images.h) as the debug-draw batch records them, and
// the family's view from the ui registry: its flags, redraws that allocate
// nothing, and the whole panel column drawn headless, on the rooms scene
// (Sudarsky & Gotsman's test scene).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <imgui.h>

#include "culling/hzb_tbv/hzb_tbv_snapshot.h"
#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"
#include "tests/ui/headless_imgui.h"
#include "tests/common/allocation_counter.h"
#include "tests/ui/panel_test_helpers.h"
#include "ui/debugger_session.h"
#include "ui/debugger_ui.h"
#include "ui/hzb_tbv/hzb_pyramid_images.h"
#include "ui/hzb_tbv/hzb_tbv_overlay.h"
#include "ui/hzb_tbv/hzb_tbv_view.h"
#include "ui/registry/family_views.h"

namespace gridcull {
namespace {

constexpr int kFrame = 60;
constexpr int kSmallImage = 160;  // level 0 160 x 90: every level is captured
constexpr int kViewWidth = 900, kViewHeight = 720;
constexpr size_t kBoxVertices = 24;  // 12 edges, 2 vertices each

Scene loadScene(const char* name) {
    SceneLoadResult loaded = loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/" + name);
    EXPECT_TRUE(loaded.scene) << name;
    return loaded.scene ? std::move(*loaded.scene) : Scene{};
}

KnobValues smallImage() {
    KnobValues knobs;
    knobs.set("oracle-res", kSmallImage);
    return knobs;
}

const HzbTbvSnapshot* hzbOf(const DebuggerSession& session) {
    const DebugSnapshot* s = session.debugSnapshot();
    return s ? s->as<HzbTbvSnapshot>() : nullptr;
}

HzbTbvViewState nothingShown() {
    HzbTbvViewState view;
    view.show_tbvs = false;
    for (bool& on : view.show_nodes) on = false;
    view.show_pyramid = false;
    return view;
}

bool sameColor(const glm::vec4& c, Swatch s) {
    const Rgb rgb = swatchColor(s);
    return std::abs(c.r - rgb.r) < 1e-6f && std::abs(c.g - rgb.g) < 1e-6f &&
           std::abs(c.b - rgb.b) < 1e-6f;
}

class HzbTbvViewTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(session_.open(loadScene("rooms-3d.json"), "", "hzb-tbv", error)) << error;
        session_.seek(kFrame);
        snap_ = hzbOf(session_);
        ASSERT_NE(snap_, nullptr);
    }

    const std::vector<DebugDrawBatch::Vertex>& lines(DrawSpace space, float width) const {
        static const std::vector<DebugDrawBatch::Vertex> none;
        for (const DebugDrawBatch::LineSet& set : batch_.layer(space).lines)
            if (set.width == width) return set.vertices;
        return none;
    }
    // The hidden objects (with a TBV), in snapshot order.
    std::vector<const HzbTbvObject*> withTbv() const {
        std::vector<const HzbTbvObject*> out;
        for (const HzbTbvObject& o : snap_->objects)
            if (o.has_tbv) out.push_back(&o);
        return out;
    }

    DebuggerSession session_{smallImage()};
    const HzbTbvSnapshot* snap_ = nullptr;
    DebugDrawBatch batch_;
};

TEST_F(HzbTbvViewTest, SessionExposesTheSnapshotOfHzbCullersOnly) {
    EXPECT_STREQ(session_.debugSnapshot()->kind().family, "hzb");
    EXPECT_TRUE(snap_->uses_tbvs);
    EXPECT_EQ(snap_->frame, kFrame + 1);
    EXPECT_FALSE(withTbv().empty()) << "the rooms scene hides chairs at frame 60";
    std::string error;
    for (const char* algo : {"hzb-tbvi", "hzb"}) {
        ASSERT_TRUE(session_.selectAlgorithm(algo, error)) << error;
        const HzbTbvSnapshot* s = hzbOf(session_);
        ASSERT_NE(s, nullptr) << algo;
        EXPECT_EQ(s->uses_tbvs, std::string(algo) != "hzb");
        EXPECT_EQ(s->mode == TbvUpdateMode::Implicit, std::string(algo) == "hzb-tbvi");
    }
    for (const char* algo : {"vfc", "lazy-grid"}) {
        ASSERT_TRUE(session_.selectAlgorithm(algo, error)) << error;
        EXPECT_EQ(hzbOf(session_), nullptr) << algo;
    }
}

TEST(HzbTbvBands, FractionOfTheValidityPeriodLeft) {
    HzbTbvObject o;
    o.has_tbv = true;
    o.created = 1.0;
    o.expiry = 4.0;
    const struct {
        double remaining;
        HzbTbvBand band;
    } cases[] = {{3.0, HzbTbvBand::Long},   {2.1, HzbTbvBand::Long},  {1.9, HzbTbvBand::Middle},
                 {1.0, HzbTbvBand::Middle}, {0.9, HzbTbvBand::Short}, {0.0, HzbTbvBand::Short}};
    for (const auto& c : cases) {
        o.remaining = c.remaining;
        EXPECT_EQ(hzbTbvBandOf(o), c.band) << c.remaining;
    }
    o.expiry = INFINITY;  // a still object's TBV never expires
    o.remaining = INFINITY;
    EXPECT_EQ(hzbTbvBandOf(o), HzbTbvBand::Long);
    // Each band its own colour, none an object state's or the camera's.
    for (int a = 0; a < kHzbTbvBandCount; ++a) {
        const Swatch s = hzbTbvBandSwatch(HzbTbvBand(a));
        for (Swatch taken :
             {Swatch::Blue, Swatch::SkyBlue, Swatch::Vermillion, Swatch::DimGrey, Swatch::Yellow})
            EXPECT_NE(s, taken);
        for (int b = 0; b < a; ++b) EXPECT_NE(s, hzbTbvBandSwatch(HzbTbvBand(b)));
        for (int k = 0; k < kHzbNodeOutcomeCount; ++k)
            EXPECT_NE(s, hzbNodeOutcomeSwatch(HzbNodeOutcome(k)));
    }
}

// Every TBV is one wire box on its bounds, in its band's colour; the focused
// object's is the heavy one.
TEST_F(HzbTbvViewTest, OverlayDrawsEachTbvOnItsBoundsByBand) {
    const std::vector<const HzbTbvObject*> tbvs = withTbv();
    ASSERT_GE(tbvs.size(), 2u);
    HzbTbvViewState view = nothingShown();
    view.show_tbvs = true;
    const HzbTbvObject& focus = *tbvs[1];
    const HzbOverlayCounts counts = drawHzbTbvOverlay(*snap_, view, focus.object_index, batch_);
    EXPECT_EQ(counts.tbvs, int(tbvs.size()));
    EXPECT_TRUE(batch_.layer(DrawSpace::View).lines.empty()) << "World space only";
    const std::vector<DebugDrawBatch::Vertex>& bold = lines(DrawSpace::World, kHzbTbvWidth);
    const std::vector<DebugDrawBatch::Vertex>& heavy = lines(DrawSpace::World, kHzbFocusedTbvWidth);
    ASSERT_EQ(bold.size(), kBoxVertices * (tbvs.size() - 1));
    ASSERT_EQ(heavy.size(), kBoxVertices);

    // Box k of the bold set is the k-th unfocused TBV: its corners are the bounds'.
    size_t k = 0;
    for (const HzbTbvObject* o : tbvs) {
        const std::vector<DebugDrawBatch::Vertex>& set = o == &focus ? heavy : bold;
        const size_t first = o == &focus ? 0 : kBoxVertices * k++;
        glm::vec3 lo(FLT_MAX), hi(-FLT_MAX);
        for (size_t v = first; v < first + kBoxVertices; ++v) {
            lo = glm::min(lo, set[v].position);
            hi = glm::max(hi, set[v].position);
            EXPECT_TRUE(sameColor(set[v].color, hzbTbvBandSwatch(hzbTbvBandOf(*o))))
                << "object " << o->object_id;
        }
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(lo[a], o->tbv.min[a], 1e-3) << "object " << o->object_id;
            EXPECT_NEAR(hi[a], o->tbv.max[a], 1e-3) << "object " << o->object_id;
        }
    }
    // Off: no TBV.
    batch_.clear();
    drawHzbTbvOverlay(*snap_, nothingShown(), focus.object_index, batch_);
    EXPECT_TRUE(batch_.empty());
}

// Nodes: one wire box per node whose outcome is shown, in the outcome's colour
// and width, at most kHzbMaxNodesDrawn.
TEST_F(HzbTbvViewTest, OverlayDrawsTheNodesOfTheOutcomesShown) {
    ASSERT_GT(snap_->node_count[size_t(HzbNodeOutcome::ZCulled)], 0);
    ASSERT_GT(snap_->node_count[size_t(HzbNodeOutcome::Entered)], 0);
    for (int k = 0; k < kHzbNodeOutcomeCount; ++k) {
        const auto outcome = HzbNodeOutcome(k);
        HzbTbvViewState view = nothingShown();
        view.show_nodes[k] = true;
        batch_.clear();
        const HzbOverlayCounts counts = drawHzbTbvOverlay(*snap_, view, -1, batch_);
        const size_t n = size_t(snap_->node_count[size_t(k)]);
        EXPECT_EQ(counts.nodes_drawn, int(n));
        const std::vector<DebugDrawBatch::Vertex>& set =
            lines(DrawSpace::World, hzbNodeOutcomeWidth(outcome));
        ASSERT_EQ(set.size(), kBoxVertices * n) << hzbNodeOutcomeName(outcome);
        size_t box = 0;
        for (const HzbNodeVisit& node : snap_->nodes) {
            if (node.outcome != outcome) continue;
            EXPECT_TRUE(sameColor(set[kBoxVertices * box].color, hzbNodeOutcomeSwatch(outcome)));
            EXPECT_NEAR(set[kBoxVertices * box].position.x, node.box.min.x, 1e-3);
            ++box;
        }
    }
    // The cap: a deep tree's 2000 visits draw the first kHzbMaxNodesDrawn.
    HzbTbvSnapshot deep;
    deep.valid = true;
    deep.nodes.assign(2000, HzbNodeVisit{});
    deep.node_count[size_t(HzbNodeOutcome::Entered)] = 2000;
    HzbTbvViewState view = nothingShown();
    view.show_nodes[int(HzbNodeOutcome::Entered)] = true;
    batch_.clear();
    const HzbOverlayCounts counts = drawHzbTbvOverlay(deep, view, -1, batch_);
    EXPECT_EQ(counts.nodes_shown, 2000);
    EXPECT_EQ(counts.nodes_drawn, kHzbMaxNodesDrawn);
    EXPECT_EQ(lines(DrawSpace::World, kHairline).size(), kBoxVertices * kHzbMaxNodesDrawn);
}

TEST_F(HzbTbvViewTest, PyramidLevelPickFollowsTheFlagOrTheAutoRule) {
    ASSERT_EQ(snap_->pyramid_width, kSmallImage);
    ASSERT_EQ(snap_->pyramid_levels.front().level, 0) << "160 x 90 is captured whole";
    HzbTbvViewState view;
    // Auto: the finest level at most 64 texels wide: 40 x 23, level 2.
    EXPECT_EQ(snap_->pyramid_levels[size_t(hzbFirstPyramidImage(*snap_, view))].level, 2);
    view.pyramid_level = 0;
    EXPECT_EQ(hzbFirstPyramidImage(*snap_, view), 0);
    view.pyramid_level = 99;
    EXPECT_EQ(hzbFirstPyramidImage(*snap_, view), int(snap_->pyramid_levels.size()) - 1);
    EXPECT_EQ(hzbFirstPyramidImage(HzbTbvSnapshot{}, view), -1);
}

// The images: three levels at the bottom left, the z-buffer's aspect, one
// rectangle per drawn texel in grey by depth, each labelled with its size.
TEST_F(HzbTbvViewTest, PyramidImagesShowEachTexelByDepth) {
    HzbTbvViewState view = nothingShown();
    view.show_pyramid = true;
    view.pyramid_level = 1;
    HzbPyramidImage images[kHzbPyramidImages];
    const int count = layoutHzbPyramidImages(*snap_, view, kViewWidth, kViewHeight, images);
    ASSERT_EQ(count, kHzbPyramidImages);
    for (int k = 0; k < count; ++k) {
        const ViewRect& r = images[k].rect;
        EXPECT_EQ(snap_->pyramid_levels[size_t(images[k].index)].level, 1 + k);
        EXPECT_NEAR(r.x1 - r.x0, kHzbPyramidImageWidth, 1e-9);
        EXPECT_NEAR((r.y1 - r.y0) / (r.x1 - r.x0), 90.0 / 160.0, 1e-9);
        EXPECT_GE(r.x0, 0.0);
        EXPECT_LE(r.y1, double(kViewHeight));
        EXPECT_GT(r.y0, kViewHeight / 2.0) << "in the bottom half";
        if (k > 0) {
            EXPECT_GT(r.x0, images[k - 1].rect.x1) << "side by side";
        }
    }
    const HzbDepthRange range = hzbPyramidDepthRange(*snap_, images, count);
    ASSERT_TRUE(range.any);
    EXPECT_LT(range.near, range.far);
    EXPECT_FLOAT_EQ(hzbTexelGrey(float(range.near), range), 1.0f) << "near: light";
    EXPECT_FLOAT_EQ(hzbTexelGrey(float(range.far), range), kHzbFarGrey) << "far: dark";
    EXPECT_EQ(hzbTexelGrey(INFINITY, range), 0.0f) << "empty: black";

    EXPECT_EQ(drawHzbPyramidImages(*snap_, view, kViewWidth, kViewHeight, batch_), count);
    EXPECT_TRUE(batch_.layer(DrawSpace::World).fill.empty()) << "View space only";
    // A backing, then per image its black rectangle and one per non-empty texel.
    size_t rects = 1, texels_alpha_one = 0;
    for (int k = 0; k < count; ++k) {
        const HzbPyramidLevel& l = snap_->pyramid_levels[size_t(images[k].index)];
        ++rects;
        for (size_t i = 0; i < size_t(l.width * l.height); ++i) {
            const float grey = hzbTexelGrey(snap_->pyramid_texels[l.offset + i], range);
            rects += grey > 0.0f ? 1 : 0;
            texels_alpha_one += grey == 1.0f ? 1 : 0;
        }
    }
    const std::vector<DebugDrawBatch::Vertex>& fill = batch_.layer(DrawSpace::View).fill;
    EXPECT_EQ(fill.size(), 6 * rects);
    EXPECT_GT(texels_alpha_one, 0u);
    // Labels: the key and each level's number and size.
    std::vector<std::string> labels;
    for (const DebugDrawBatch::Label& label : batch_.layer(DrawSpace::View).labels)
        labels.push_back(batch_.labelText(label));
    ASSERT_EQ(labels.size(), size_t(count) + 1);
    EXPECT_NE(labels[0].find("near light, far dark, empty black"), std::string::npos);
    for (int k = 0; k < count; ++k) {
        const HzbPyramidLevel& l = snap_->pyramid_levels[size_t(images[k].index)];
        EXPECT_EQ(labels[size_t(k) + 1], "level " + std::to_string(l.level) + ": " +
                                             std::to_string(l.width) + " x " +
                                             std::to_string(l.height));
    }
    // Off: nothing.
    batch_.clear();
    EXPECT_EQ(drawHzbPyramidImages(*snap_, nothingShown(), kViewWidth, kViewHeight, batch_), 0);
    EXPECT_TRUE(batch_.empty());
}

// The window redraws the overlay every frame: once drawn, redrawing it (every
// node outcome, TBVs, a picked object, the finest captured pyramid levels)
// allocates nothing.
TEST_F(HzbTbvViewTest, RedrawingTheOverlayAllocatesNothing) {
    std::unique_ptr<FamilyView> view = familyViewOfAlgorithm("hzb-tbv")->make();
    KnobValues flags;
    flags.set("hzb-object", withTbv()[0]->object_id);
    flags.set("hzb-show-nodes", 7);
    flags.set("hzb-pyramid-level", 0);
    std::string error;
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    FamilyViewContext context;
    context.scene = &session_.scene();
    context.algo = "hzb-tbv";
    context.snapshot = snap_;
    OverlayView overlay;
    overlay.width = kViewWidth;
    overlay.height = kViewHeight;
    view->drawOverlay(context, overlay, batch_);
    ASSERT_FALSE(batch_.empty());
    test::startCounting();
    for (int k = 0; k < 2; ++k) {
        batch_.clear();
        view->drawOverlay(context, overlay, batch_);
    }
    test::stopCounting();
    EXPECT_EQ(test::allocationCount(), 0);
}

class HzbTbvPanelTest : public HzbTbvViewTest {
protected:
    void SetUp() override {
        HzbTbvViewTest::SetUp();
        test::createHeadlessImGui();
        names_ = algorithmNames(3);
        snapshot_ = test::snapshotOfSession(session_, names_, file_, errors_);
        snapshot_.algo_index =
            int(std::find(names_.begin(), names_.end(), "hzb-tbv") - names_.begin());
        context_.scene = &session_.scene();
        context_.algo = "hzb-tbv";
        context_.snapshot = snap_;
    }
    void TearDown() override { ImGui::DestroyContext(); }

    std::vector<std::string> names_;
    const std::string file_;
    const std::vector<std::string> errors_;
    FrameSnapshot snapshot_;
    FamilyViewContext context_;
};

// The family's view from the ui registry, with an object picked by its flag:
// the column draws headless and asks for nothing, the hzb panel a sizeable
// part of it; the flags choose what the overlay draws.
TEST_F(HzbTbvPanelTest, ColumnDrawsHeadlessAndFlagsChooseTheOverlay) {
    const FamilyViewEntry* entry = familyViewOfAlgorithm("hzb-tbvi");
    ASSERT_NE(entry, nullptr);
    EXPECT_EQ(entry->family, "hzb");
    for (const char* flag :
         {"hzb-show-tbvs", "hzb-show-nodes", "hzb-show-pyramid", "hzb-pyramid-level", "hzb-object"})
        EXPECT_EQ(familyViewOfFlag(flag), entry) << flag;

    const HzbTbvObject& picked = *withTbv()[0];
    std::unique_ptr<FamilyView> view = entry->make();
    KnobValues flags;
    flags.set("hzb-object", picked.object_id);
    std::string error;
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    EXPECT_EQ(view->focusedObject(context_), picked.object_index) << "the picked one";
    context_.hovered_object = 0;
    EXPECT_EQ(view->focusedObject(context_), 0) << "the one under the pointer first";
    context_.hovered_object = -1;
    EXPECT_GT(test::familyPanelVertices(snapshot_, view.get(), context_), 1000);

    OverlayView overlay;
    overlay.width = kViewWidth;
    overlay.height = kViewHeight;
    // The first preset, occlusion only: the Z-pyramid images and no TBVs; the
    // TBVs preset brings the picked object's.
    view->drawOverlay(context_, overlay, batch_);
    EXPECT_TRUE(lines(DrawSpace::World, kHzbFocusedTbvWidth).empty()) << "no TBVs";
    EXPECT_FALSE(batch_.layer(DrawSpace::View).fill.empty()) << "the Z-pyramid images";
    view->applyOverlayPreset(OverlayPreset::Tbvs);
    batch_.clear();
    view->drawOverlay(context_, overlay, batch_);
    EXPECT_EQ(lines(DrawSpace::World, kHzbFocusedTbvWidth).size(), kBoxVertices)
        << "the picked object's TBV";

    flags.set("hzb-show-tbvs", 0);
    flags.set("hzb-show-nodes", 0);
    flags.set("hzb-show-pyramid", 0);
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    batch_.clear();
    view->drawOverlay(context_, overlay, batch_);
    EXPECT_TRUE(batch_.empty()) << "everything off";

    // --hzb-show-nodes 2: Z-culled nodes only.
    flags.set("hzb-show-nodes", 2);
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    batch_.clear();
    view->drawOverlay(context_, overlay, batch_);
    EXPECT_EQ(lines(DrawSpace::World, hzbNodeOutcomeWidth(HzbNodeOutcome::ZCulled)).size(),
              kBoxVertices * size_t(snap_->node_count[size_t(HzbNodeOutcome::ZCulled)]));
    EXPECT_TRUE(lines(DrawSpace::World, kHairline).empty()) << "no entered, no frustum-culled";

    // Another snapshot kind, or none: nothing.
    context_.snapshot = nullptr;
    batch_.clear();
    view->drawOverlay(context_, overlay, batch_);
    EXPECT_TRUE(batch_.empty());

    flags.set("hzb-object", 999999);
    EXPECT_FALSE(view->applyFlags(flags, session_.scene(), error));
    EXPECT_NE(error.find("--hzb-object 999999"), std::string::npos) << error;
}

}  // namespace
}  // namespace gridcull
