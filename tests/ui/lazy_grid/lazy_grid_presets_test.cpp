// The lazy grid's overlay presets (ui/lazy_grid/lazy_grid_view.h) and the
// hovered cell's outline (ui/lazy_grid/lazy_grid_hovered_cell.h), through the
// family's view from the ui registry on the forest scene, looked at through the
// culling camera: a new view starts with "occlusion only" (the cells and the
// grid, no test), each preset draws its layers' colours and no others, and the
// image cell the pointer's ray goes through is outlined in white on its own
// rectangle; none when the pointer leaves the view.
#include <memory>
#include <set>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"
#include "culling/lazy_grid/lazy_grid_snapshot.h"
#include "tests/ui/overlay_swatches.h"
#include "ui/debugger_session.h"
#include "ui/lazy_grid/lazy_grid_hovered_cell.h"
#include "ui/lazy_grid/lazy_grid_overlay.h"
#include "ui/lazy_grid/lazy_grid_view.h"
#include "ui/registry/family_views.h"

namespace gridcull {
namespace {

constexpr int kFrame = 20;
constexpr int kViewWidth = 960;

bool has(const std::set<Swatch>& s, Swatch w) {
    return s.count(w) != 0;
}

class LazyGridPresetsTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        KnobValues knobs;
        knobs.set("oracle-res", 160);  // small and fast; the overlay does not depend on it
        session_ = new DebuggerSession(knobs);
        SceneLoadResult loaded =
            loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/forest-3d.json");
        ASSERT_TRUE(loaded.scene);
        std::string error;
        ASSERT_TRUE(session_->open(std::move(*loaded.scene), "", "lazy-grid", error)) << error;
        session_->seek(kFrame);
    }
    static void TearDownTestSuite() {
        delete session_;
        session_ = nullptr;
    }

    void SetUp() override {
        snap_ = session_->debugSnapshot()->as<LazyGridSnapshot>();
        ASSERT_NE(snap_, nullptr);
        view_ = findFamilyView("lazy-grid")->make();
        // The view through the culling camera, of its aspect: the image covers it.
        const Camera& camera = session_->cullingCamera();
        overlay_.width = kViewWidth;
        overlay_.height = int(kViewWidth / camera.aspect + 0.5);
        overlay_.through_culling_camera = true;
        overlay_.culling_aspect = camera.aspect;
        overlay_.view_projection = camera.projectionMatrix() * camera.viewMatrix();
        context_.scene = &session_->scene();
        context_.snapshot = snap_;
    }

    // An object whose deciding test read pixels: its test has every kind of mark.
    int testedObject() const {
        for (int i = 0; i < int(session_->scene().objects.size()); ++i) {
            const LazyDecision d = describeLazyDecision(*snap_, i);
            if (d.test && d.test->in_frustum && d.pixel_queries > 0 && !d.test->box.rect.empty())
                return i;
        }
        return -1;
    }

    std::set<Swatch> drawn() {
        batch_.clear();
        view_->drawOverlay(context_, overlay_, batch_);
        return test::swatchesIn(batch_);
    }

    // The pointer's ray through the centre of image cell (cx, cy), as the window
    // casts it (app/view_camera.h): from the eye through the view pixel.
    ViewPointer pointerAt(int cx, int cy) const {
        const Camera& camera = session_->cullingCamera();
        const ImageFrame frame = overlay_.cullingImage(snap_->width, snap_->height);
        const PixelRect cell = lazyCellPixels(*snap_, cx, cy);
        const glm::dvec2 v =
            frame.toView(0.5 * (cell.x0 + cell.x1 + 1), 0.5 * (cell.y0 + cell.y1 + 1));
        const glm::dvec4 far = glm::inverse(overlay_.view_projection) *
                               glm::dvec4(2.0 * v.x / overlay_.width - 1.0,
                                          1.0 - 2.0 * v.y / overlay_.height, 1.0, 1.0);
        ViewPointer pointer;
        pointer.over_view = true;
        pointer.origin = camera.position;
        pointer.direction = glm::normalize(glm::dvec3(far) / far.w - camera.position);
        return pointer;
    }

    static DebuggerSession* session_;
    const LazyGridSnapshot* snap_ = nullptr;
    std::unique_ptr<FamilyView> view_;
    OverlayView overlay_;
    FamilyViewContext context_;
    DebugDrawBatch batch_;
};

DebuggerSession* LazyGridPresetsTest::session_ = nullptr;

TEST_F(LazyGridPresetsTest, ANewViewShowsTheCellsNotTheTest) {
    const std::vector<OverlayPreset> presets = view_->overlayPresets();
    EXPECT_EQ(presets, (std::vector<OverlayPreset>{OverlayPreset::Occlusion,
                                                   OverlayPreset::Traversal, OverlayPreset::All}))
        << "no TBVs: the lazy grid has none";
    context_.hovered_object = testedObject();
    ASSERT_GE(context_.hovered_object, 0);
    const std::set<Swatch> fresh = drawn();
    EXPECT_TRUE(has(fresh, lazyGridLayerSwatch(LazyGridLayer::GridLines)));
    const LazyCellCounts counts = countLazyCells(*snap_);
    for (int c = 0; c < kLazyCellClassCount; ++c) {
        if (counts.count[c] > 0) {
            EXPECT_TRUE(has(fresh, lazyCellClassSwatch(LazyCellClass(c))))
                << lazyCellClassName(LazyCellClass(c));
        }
    }
    for (Swatch off : {lazyGridLayerSwatch(LazyGridLayer::Touched),
                       lazyGridLayerSwatch(LazyGridLayer::ScreenRect)})
        EXPECT_FALSE(has(fresh, off)) << swatchName(off);
}

TEST_F(LazyGridPresetsTest, EachPresetDrawsItsLayersColours) {
    context_.hovered_object = testedObject();
    ASSERT_GE(context_.hovered_object, 0);
    view_->applyOverlayPreset(OverlayPreset::Traversal);
    std::set<Swatch> s = drawn();
    for (LazyGridLayer on :
         {LazyGridLayer::GridLines, LazyGridLayer::Touched, LazyGridLayer::ScreenRect})
        EXPECT_TRUE(has(s, lazyGridLayerSwatch(on))) << lazyGridLayerName(on);
    // No cell classes but the free one (a touched cell found free is drawn so).
    for (LazyCellClass off :
         {LazyCellClass::PartiallyFree, LazyCellClass::Full, LazyCellClass::Outdated})
        EXPECT_FALSE(has(s, lazyCellClassSwatch(off))) << lazyCellClassName(off);

    view_->applyOverlayPreset(OverlayPreset::All);
    s = drawn();
    for (int l = 0; l < kLazyGridLayerCount; ++l) {
        if (LazyGridLayer(l) != LazyGridLayer::Cells) {  // keyed by class, not by this swatch
            EXPECT_TRUE(has(s, lazyGridLayerSwatch(LazyGridLayer(l))))
                << lazyGridLayerName(LazyGridLayer(l));
        }
    }
    const LazyCellCounts counts = countLazyCells(*snap_);
    for (int c = 0; c < kLazyCellClassCount; ++c) {
        if (counts.count[c] > 0) {
            EXPECT_TRUE(has(s, lazyCellClassSwatch(LazyCellClass(c))))
                << lazyCellClassName(LazyCellClass(c));
        }
    }

    view_->applyOverlayPreset(OverlayPreset::Occlusion);
    s = drawn();
    EXPECT_FALSE(has(s, lazyGridLayerSwatch(LazyGridLayer::ScreenRect)));
    EXPECT_FALSE(has(s, lazyGridLayerSwatch(LazyGridLayer::Touched)));
}

TEST_F(LazyGridPresetsTest, TheCellUnderThePointerIsOutlined) {
    const ImageFrame frame = overlay_.cullingImage(snap_->width, snap_->height);
    for (const glm::ivec2 cell : {glm::ivec2(0, 0), glm::ivec2(snap_->cells_x / 2, 1),
                                  glm::ivec2(snap_->cells_x - 1, snap_->cells_y - 1)}) {
        view_->pointer(context_, pointerAt(cell.x, cell.y));
        drawn();
        const std::vector<DebugDrawBatch::Vertex> outline =
            test::linesOf(batch_, DrawSpace::View, kLazyHoverPaint.swatch, kLazyHoverWidth);
        ASSERT_EQ(outline.size(), 8u) << "four sides, cell " << cell.x << ", " << cell.y;
        const ViewRect want = lazyCellInView(frame, *snap_, cell.x, cell.y);
        const glm::vec4 b = test::boundsXY(outline);
        EXPECT_NEAR(b.x, want.x0, 1e-3);
        EXPECT_NEAR(b.y, want.y0, 1e-3);
        EXPECT_NEAR(b.z, want.x1, 1e-3);
        EXPECT_NEAR(b.w, want.y1, 1e-3);
    }
    // Off the view, or not through the culling camera: no outline. From
    // outside the camera the cells are held up in its frustum (World space),
    // where the pointer names no cell: nothing in View space at all.
    view_->pointer(context_, ViewPointer{});
    drawn();
    EXPECT_TRUE(
        test::linesOf(batch_, DrawSpace::View, kLazyHoverPaint.swatch, kLazyHoverWidth).empty());
    view_->pointer(context_, pointerAt(1, 1));
    overlay_.through_culling_camera = false;
    overlay_.culling_camera = session_->cullingCamera();
    drawn();
    EXPECT_TRUE(batch_.layer(DrawSpace::View).fill.empty());
    EXPECT_TRUE(test::linesOf(batch_, DrawSpace::View, kLazyHoverPaint.swatch, kLazyHoverWidth)
                    .empty());
    EXPECT_FALSE(batch_.layer(DrawSpace::World).fill.empty()) << "the cells in the frustum";
}

}  // namespace
}  // namespace gridcull
