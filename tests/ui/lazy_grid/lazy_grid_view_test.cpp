// The lazy occlusion grid in the window: the session's snapshot
// (ui/debugger_session.h), the panel's summaries (ui/lazy_grid/lazy_grid_view.h),
// the overlay's geometry as the debug-draw batch records it
// (ui/lazy_grid/lazy_grid_overlay.h), the family's view from the ui registry, and
// the panel itself drawn headless, with its cell-size slider driven by the
// mouse, on the forest scene.
#include <algorithm>
#include <cfloat>
#include <optional>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <imgui.h>

#include "culling/io/scene_loader.h"
#include "culling/lazy_grid/lazy_grid_options.h"
#include "culling/lazy_grid/lazy_grid_snapshot.h"
#include "culling/raster/id_depth_buffer.h"
#include "culling/registry/registry.h"
#include "tests/ui/headless_imgui.h"
#include "tests/ui/panel_test_helpers.h"
#include "ui/debugger_session.h"
#include "ui/debugger_ui.h"
#include "ui/lazy_grid/lazy_grid_overlay.h"
#include "ui/lazy_grid/lazy_grid_panel.h"
#include "ui/registry/family_views.h"

namespace gridcull {
namespace {

constexpr int kFrame = 20;
constexpr double kAreaTolerance = 1e-2;  // square view pixels, float vertices

Scene loadScene(const char* name) {
    SceneLoadResult loaded = loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/" + name);
    EXPECT_TRUE(loaded.scene) << name;
    return loaded.scene ? std::move(*loaded.scene) : Scene{};
}

// A small image keeps the test fast; the grid's logic does not depend on its size.
constexpr int kSmallImage = 160;
KnobValues smallImage() {
    KnobValues knobs;
    knobs.set("oracle-res", kSmallImage);
    return knobs;
}

const LazyGridSnapshot* lazyOf(const DebuggerSession& session) {
    const DebugSnapshot* s = session.debugSnapshot();
    return s ? s->as<LazyGridSnapshot>() : nullptr;
}

double area(const std::vector<DebugDrawBatch::Vertex>& fill) {
    double sum = 0.0;
    for (size_t k = 0; k + 2 < fill.size(); k += 3) {
        const glm::vec3 a = fill[k].position, b = fill[k + 1].position, c = fill[k + 2].position;
        sum += 0.5 * std::abs(double((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)));
    }
    return sum;
}

LazyGridViewState only(LazyGridLayer layer) {
    LazyGridViewState view;
    for (bool& on : view.show) on = false;
    view.show[int(layer)] = true;
    return view;
}

class LazyGridViewTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(session_.open(loadScene("forest-3d.json"), "", "lazy-grid", error)) << error;
        session_.seek(kFrame);
        snap_ = lazyOf(session_);
        ASSERT_NE(snap_, nullptr);
        frame_ = cullingImageFrame(session_.cullingCamera().aspect, 900, 720, snap_->width,
                                   snap_->height);
    }

    // The first object whose own box was found occluded after a pixel query.
    int occludedAfterQuery() const {
        for (int i = 0; i < int(session_.scene().objects.size()); ++i) {
            const LazyDecision d = describeLazyDecision(*snap_, i);
            if (d.test && d.own_box && d.test->in_frustum && d.test->occluded &&
                d.pixel_queries > 0)
                return i;
        }
        return -1;
    }

    // The overlay for `view` and object `focus`, in View space.
    const DebugDrawBatch::Layer& overlay(const LazyGridViewState& view, int focus,
                                         const LazyGridSnapshot* snap = nullptr) {
        batch_.clear();
        drawLazyGridOverlay(snap ? *snap : *snap_, view, focus, frame_, batch_, scratch_);
        EXPECT_TRUE(batch_.layer(DrawSpace::World).fill.empty());
        return batch_.layer(DrawSpace::View);
    }
    // Its line vertices of one width.
    std::vector<DebugDrawBatch::Vertex> lines(float width) const {
        for (const DebugDrawBatch::LineSet& set : batch_.layer(DrawSpace::View).lines)
            if (set.width == width) return set.vertices;
        return {};
    }

    DebuggerSession session_{smallImage()};
    const LazyGridSnapshot* snap_ = nullptr;
    ImageFrame frame_;
    DebugDrawBatch batch_;
    LazyGridOverlayScratch scratch_;
};

TEST_F(LazyGridViewTest, SessionExposesTheSnapshotOfLazyCullersOnly) {
    const Camera& camera = session_.cullingCamera();
    int width = 0, height = 0;
    // The image follows the oracle's resolution when --lazy-res is not given.
    imageSizeForAspect(kSmallImage, camera.aspect, width, height);
    EXPECT_EQ(snap_->width, width);
    EXPECT_EQ(snap_->height, height);
    EXPECT_EQ(snap_->cell_size, LazyGridOptions{}.cell_size);
    EXPECT_EQ(snap_->cells.size(), size_t(snap_->cells_x) * size_t(snap_->cells_y));
    EXPECT_GT(snap_->counters.occlusion_tests, 0);
    EXPECT_STREQ(session_.debugSnapshot()->kind().family, "lazy-grid");

    std::string error;
    for (const char* algo : {"lazy-grid-z", "busy-grid"}) {
        ASSERT_TRUE(session_.selectAlgorithm(algo, error)) << error;
        const LazyGridSnapshot* s = lazyOf(session_);
        ASSERT_NE(s, nullptr) << algo;
        EXPECT_TRUE(s->valid);
        EXPECT_EQ(s->variant == LazyGridVariant::ZBuffer, std::string(algo) == "lazy-grid-z");
        EXPECT_EQ(s->update == LazyGridUpdate::Busy, std::string(algo) == "busy-grid");
    }
    for (const char* algo : {"vfc", "all", "exact"}) {
        ASSERT_TRUE(session_.selectAlgorithm(algo, error)) << error;
        EXPECT_EQ(session_.debugSnapshot(), nullptr) << algo;
    }
    // A 2D scene: the lazy grid does not run on it, and the session says why.
    DebuggerSession flat(smallImage());
    EXPECT_FALSE(flat.open(loadScene("walls-2d.json"), "", "lazy-grid", error));
    EXPECT_NE(error.find("lazy-grid runs on 3D scenes only, and this scene is 2D"),
              std::string::npos)
        << error;
}

TEST_F(LazyGridViewTest, NewCellSizeRerunsUpToTheSameFrame) {
    KnobValues options = session_.knobs();
    options.set("lazy-cell-size", 16);
    std::string error;
    ASSERT_TRUE(session_.setKnobs(options, error)) << error;
    EXPECT_EQ(session_.frame(), kFrame);
    EXPECT_EQ(session_.knobs().set_values().at("lazy-cell-size"), 16);
    const LazyGridSnapshot* s = lazyOf(session_);
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->cell_size, 16);
    EXPECT_EQ(s->cells_x, (s->width + 15) / 16);
    EXPECT_EQ(s->cells_y, (s->height + 15) / 16);

    DebuggerSession fresh(options);
    ASSERT_TRUE(fresh.open(loadScene("forest-3d.json"), "", "lazy-grid", error)) << error;
    fresh.seek(kFrame);
    EXPECT_EQ(session_.result().pvs, fresh.result().pvs);
    EXPECT_EQ(lazyOf(session_)->counters.pixel_queries, lazyOf(fresh)->counters.pixel_queries);
}

TEST_F(LazyGridViewTest, CountsAndDecisionsSumUpTheSnapshot) {
    const LazyCellCounts counts = countLazyCells(*snap_);
    int64_t total = 0;
    for (int64_t n : counts.count) total += n;
    EXPECT_EQ(total, int64_t(snap_->cells.size()));
    // The occlusion-buffer variant's cells are in its four classes only.
    EXPECT_EQ(counts.of(LazyCellClass::ZfarAtZmax) + counts.of(LazyCellClass::ZfarFinite), 0);
    EXPECT_GT(counts.of(LazyCellClass::Full) + counts.of(LazyCellClass::Outdated), 0);

    const int object = occludedAfterQuery();
    ASSERT_GE(object, 0) << "the forest has trees culled after a pixel query";
    const LazyDecision d = describeLazyDecision(*snap_, object);
    std::set<int32_t> internal, border;
    int queries = 0;
    for (int32_t k = d.test->first_touch; k < d.test->first_touch + d.test->touch_count; ++k) {
        const CellTouch& t = snap_->touches[size_t(k)];
        (t.role == CellRole::Internal ? internal : border).insert(t.cell);
        queries += t.kind == CellTouchKind::PixelQuery ? 1 : 0;
    }
    EXPECT_EQ(d.internal, int(internal.size()));
    EXPECT_EQ(d.border, int(border.size()));
    EXPECT_EQ(d.pixel_queries, queries);
    EXPECT_EQ(d.test->step, OcclusionStep::Occluded);

    // An object in the PVS was decided by its own box, found potentially visible.
    const Scene& scene = session_.scene();
    ASSERT_FALSE(session_.result().pvs.empty());
    const LazyDecision v = describeLazyDecision(*snap_, scene.indexOf(session_.result().pvs[0]));
    ASSERT_NE(v.test, nullptr);
    EXPECT_TRUE(v.own_box);
    EXPECT_FALSE(v.test->occluded);
}

TEST_F(LazyGridViewTest, OverlayFillsEachCellInItsFrame) {
    const DebugDrawBatch::Layer& g = overlay(only(LazyGridLayer::Cells), -1);
    double filled = 0.0;
    for (int cy = 0; cy < snap_->cells_y; ++cy)
        for (int cx = 0; cx < snap_->cells_x; ++cx) {
            const LazyGridCell& cell = snap_->cells[size_t(cy * snap_->cells_x + cx)];
            if (lazyCellClassFillAlpha(lazyCellClassOf(cell, snap_->variant)) <= 0.0f) continue;
            const ViewRect r = lazyCellInView(frame_, *snap_, cx, cy);
            filled += (r.x1 - r.x0) * (r.y1 - r.y0);
        }
    EXPECT_NEAR(area(g.fill), filled, kAreaTolerance);
    EXPECT_EQ(lines(kBoldLine).size(), 8 * snap_->cells.size()) << "one outline per cell";
    for (const DebugDrawBatch::Vertex& v : g.fill) {
        EXPECT_GE(v.position.y, frame_.area.y0 - 1e-3) << "inside the image, not on the bars";
        EXPECT_LE(v.position.y, frame_.area.y1 + 1e-3);
    }

    EXPECT_TRUE(overlay(only(LazyGridLayer::GridLines), -1).fill.empty());
    EXPECT_EQ(lines(kHairline).size(), size_t(2 * (snap_->cells_x + 1 + snap_->cells_y + 1)));

    LazyGridSnapshot invalid;
    overlay(LazyGridViewState{}, 0, &invalid);
    EXPECT_TRUE(batch_.empty());
}

TEST_F(LazyGridViewTest, OverlayDetailsTheFocusedObjectsTest) {
    const int object = occludedAfterQuery();
    ASSERT_GE(object, 0);
    const LazyDecision d = describeLazyDecision(*snap_, object);

    // The rectangle: one outline on the test's pixels mapped into the frame.
    overlay(only(LazyGridLayer::ScreenRect), object);
    const std::vector<DebugDrawBatch::Vertex> rect = lines(kBoldLine);
    ASSERT_EQ(rect.size(), 8u);
    const PixelRect& p = d.test->box.rect;
    const ViewRect want = frame_.pixelsToView(p.x0, p.y0, p.x1, p.y1);
    float x0 = FLT_MAX, y0 = FLT_MAX, x1 = -FLT_MAX, y1 = -FLT_MAX;
    for (const DebugDrawBatch::Vertex& v : rect) {
        x0 = std::min(x0, v.position.x);
        y0 = std::min(y0, v.position.y);
        x1 = std::max(x1, v.position.x);
        y1 = std::max(y1, v.position.y);
    }
    EXPECT_NEAR(x0, want.x0, 1e-3);
    EXPECT_NEAR(y0, want.y0, 1e-3);
    EXPECT_NEAR(x1, want.x1, 1e-3);
    EXPECT_NEAR(y1, want.y1, 1e-3);

    // A cross (two segments) per cell whose pixels were read.
    overlay(only(LazyGridLayer::PixelQueries), object);
    EXPECT_EQ(lines(kBoldLine).size(), size_t(4 * d.pixel_queries));

    // Internal cells filled, border cells not (this test found no cell free).
    EXPECT_EQ(overlay(only(LazyGridLayer::Touched), object).fill.size(), size_t(6 * d.internal));
    EXPECT_FALSE(lines(kBoldLine).empty());

    // No focused object: nothing of a test.
    overlay(only(LazyGridLayer::Touched), -1);
    EXPECT_TRUE(batch_.empty());
}

class LazyGridPanelTest : public LazyGridViewTest {
protected:
    void SetUp() override {
        LazyGridViewTest::SetUp();
        test::createHeadlessImGui();
        names_ = algorithmNames(3);
        snapshot_ = test::snapshotOfSession(session_, names_, file_, errors_);
        snapshot_.algo_index =
            int(std::find(names_.begin(), names_.end(), "lazy-grid") - names_.begin());
        snapshot_.view_mode = ViewMode::CullingCamera;
        input_.scene = &session_.scene();
        input_.algo = "lazy-grid";
        input_.view_mode = ViewMode::CullingCamera;
        input_.focus_object = occludedAfterQuery();
        input_.focus_pinned = true;
    }
    void TearDown() override { ImGui::DestroyContext(); }

    // One frame of the lazy panel alone in a window at the top left.
    FamilyAction panelFrame(ImVec2 mouse, bool down) {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(kPanelWidth, 1200);
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = mouse;
        io.MouseDown[0] = down;
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 1200));
        ImGui::Begin("lazy", nullptr, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove);
        FamilyAction action;
        drawLazyGridPanel(*snap_, input_, view_, state_, action);
        ImGui::End();
        ImGui::Render();
        return action;
    }

    bool everyLayerShown() const {
        for (bool on : view_.show)
            if (!on) return false;
        return true;
    }

    static constexpr float kPanelWidth = float(kPanelColumnWidth);
    std::vector<std::string> names_;
    const std::string file_;
    const std::vector<std::string> errors_;
    FrameSnapshot snapshot_;
    LazyGridPanelInput input_;
    LazyGridViewState view_;
    LazyGridPanelState state_;
};

// The whole column headless (no GL) with the lazy grid family's view from the
// ui registry, an object picked by its flag: with the mouse away it asks for
// nothing, and the lazy grid panel is a sizeable part of it.
TEST_F(LazyGridPanelTest, ColumnDrawsHeadlessAndAsksForNothing) {
    ASSERT_GE(input_.focus_object, 0);
    std::unique_ptr<FamilyView> view = familyViewOfAlgorithm("lazy-grid")->make();
    KnobValues flags;
    flags.set("lazy-object", session_.scene().objects[size_t(input_.focus_object)].id);
    std::string error;
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    FamilyViewContext context;
    context.scene = &session_.scene();
    context.algo = "lazy-grid";
    context.snapshot = snap_;
    context.view_mode = ViewMode::CullingCamera;
    EXPECT_EQ(view->focusedObject(context), input_.focus_object) << "the picked one is outlined";
    // The lazy grid panel is a sizeable part of the column.
    EXPECT_GT(test::familyPanelVertices(snapshot_, view.get(), context), 1000);

    // A flag naming no object of the scene is refused, naming the flag.
    flags.set("lazy-object", 999999);
    EXPECT_FALSE(view->applyFlags(flags, session_.scene(), error));
    EXPECT_NE(error.find("--lazy-object 999999"), std::string::npos) << error;
}

// A click at the right end of the cell-size slider asks, once let go, for the
// largest cell size; applied to the session it re-runs with that size.
// The picked object's test is told as a sentence; the paper's name of the step
// (internalCellIsFreeWithoutPixelquery, ...) only in a tooltip.
TEST_F(LazyGridPanelTest, TheDecisionIsASentenceNotAnIdentifier) {
    ASSERT_GE(input_.focus_object, 0);
    std::string text;
    for (int frame = 0; frame < 2; ++frame) {
        ImGui::GetIO().DisplaySize = ImVec2(kPanelWidth, 1200);
        ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 1200));
        ImGui::Begin("lazy", nullptr, ImGuiWindowFlags_NoTitleBar);
        ImGui::LogToClipboard();
        FamilyAction action;
        drawLazyGridPanel(*snap_, input_, view_, state_, action);
        ImGui::LogFinish();
        text = ImGui::GetClipboardText() ? ImGui::GetClipboardText() : "";
        ImGui::End();
        ImGui::Render();
    }
    EXPECT_EQ(text.find("Pixelquery"), std::string::npos) << text;
    EXPECT_EQ(text.find("step:"), std::string::npos) << text;
    EXPECT_TRUE(text.find("occluded and culled") != std::string::npos ||
                text.find("potentially visible and") != std::string::npos)
        << text;
}

TEST_F(LazyGridPanelTest, CellSizeSliderAsksForANewCellSize) {
    const ImVec2 away(-FLT_MAX, -FLT_MAX);
    panelFrame(away, false);
    panelFrame(away, false);
    // Press and release down the panel's right edge until the slider answers;
    // the rows above it are text (and the header, which the scan starts below).
    std::optional<double> asked;
    const float x = kPanelWidth - 14.0f;
    for (float y = 40.0f; y < 400.0f && !asked; y += 3.0f) {
        const FamilyAction press = panelFrame(ImVec2(x, y), true);
        EXPECT_TRUE(press.knobs.empty()) << "only when let go";
        const FamilyAction release = panelFrame(ImVec2(x, y), false);
        ASSERT_TRUE(everyLayerShown()) << "hit a layer toggle first at y " << y;
        if (!release.knobs.empty()) {
            EXPECT_EQ(release.knobs[0].first, "lazy-cell-size");
            asked = release.knobs[0].second;
        }
    }
    ASSERT_TRUE(asked.has_value()) << "no slider found";
    EXPECT_EQ(*asked, 1 << kLazyCellSizeMaxLog2);

    KnobValues knobs = session_.knobs();
    knobs.set("lazy-cell-size", *asked);
    std::string error;
    ASSERT_TRUE(session_.setKnobs(knobs, error)) << error;
    ASSERT_NE(lazyOf(session_), nullptr);
    EXPECT_EQ(lazyOf(session_)->cell_size, *asked);
    EXPECT_EQ(session_.frame(), kFrame);
}

}  // namespace
}  // namespace gridcull
