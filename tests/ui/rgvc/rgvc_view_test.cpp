// The rgvc view's mapping from the culler's snapshot to what the window shows:
// the voxel description of the panel (ui/rgvc/rgvc_view.h), the overlay's
// geometry as the debug-draw batch records it (ui/rgvc/rgvc_overlay.h), and the
// family's view from the ui registry, on the Figure 1 scene run through the
// debugger session.
#include <cfloat>
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <imgui.h>

#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"
#include "tests/ui/headless_imgui.h"
#include "tests/ui/panel_test_helpers.h"
#include "ui/debugger_session.h"
#include "ui/debugger_ui.h"
#include "ui/registry/family_views.h"
#include "ui/rgvc/rgvc_overlay.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {
namespace {

constexpr int kFrame = 30;

class RgvcViewTest : public ::testing::Test {
protected:
    void SetUp() override {
        SceneLoadResult loaded =
            loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/figure1-2d.json");
        ASSERT_TRUE(loaded.scene);
        std::string error;
        ASSERT_TRUE(session_.open(std::move(*loaded.scene), "", "rgvc", error)) << error;
        session_.seek(kFrame);
        ASSERT_NE(session_.debugSnapshot(), nullptr);
        snap_ = session_.debugSnapshot()->as<RgvcSnapshot>();
        ASSERT_NE(snap_, nullptr);
        ASSERT_FALSE(snap_->visits.empty());
    }

    // Total area of the triangles in `fill` (world units squared).
    static double area(const std::vector<DebugDrawBatch::Vertex>& fill) {
        double sum = 0.0;
        for (size_t k = 0; k + 2 < fill.size(); k += 3) {
            const glm::vec3 a = fill[k].position, b = fill[k + 1].position,
                            c = fill[k + 2].position;
            sum += 0.5 * std::abs(double((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)));
        }
        return sum;
    }

    double voxelArea() const {
        const glm::dvec3 d = snap_->grid.voxelSize();
        return d.x * d.y;
    }

    // The World-space triangles the overlay emits for `view`.
    const std::vector<DebugDrawBatch::Vertex>& fillOf(const RgvcViewState& view) {
        batch_.clear();
        drawRgvcOverlay(*snap_, view, batch_, scratch_);
        EXPECT_TRUE(batch_.layer(DrawSpace::View).fill.empty());
        return batch_.layer(DrawSpace::World).fill;
    }

    glm::dvec3 voxelCentre(glm::ivec2 v) const {
        const RegularGrid& grid = session_.scene().grid;
        const glm::dvec3 size = grid.voxelSize();
        return {grid.world.min.x + (v.x + 0.5) * size.x, grid.world.min.y + (v.y + 0.5) * size.y,
                0.0};
    }

    // Lines of the heaviest width the overlay emits (the picked occluder's, the seed's).
    size_t heavyLines(FamilyView& view, const FamilyViewContext& context) {
        batch_.clear();
        view.drawOverlay(context, OverlayView{}, batch_);
        size_t n = 0;
        for (const DebugDrawBatch::LineSet& set : batch_.layer(DrawSpace::World).lines)
            if (set.width == kHeavyLine) n += set.vertices.size();
        return n;
    }

    static RgvcViewState only(RgvcLayer layer) {
        RgvcViewState view;
        for (bool& on : view.show) on = false;
        view.show[int(layer)] = true;
        return view;
    }

    DebuggerSession session_{KnobValues{}};
    const RgvcSnapshot* snap_ = nullptr;
    DebugDrawBatch batch_;
    std::vector<uint8_t> scratch_;
};

TEST_F(RgvcViewTest, VoxelDescriptionMatchesTheSnapshot) {
    RgvcVoxelInfo info;
    const Scene& scene = session_.scene();
    for (size_t k = 0; k < snap_->visits.size(); k += 37) {
        const RgvcVisit& visit = snap_->visits[k];
        describeRgvcVoxel(*snap_, scene, visit.voxel, info);
        ASSERT_TRUE(info.valid);
        // The traversal visits each voxel once, so the first visit found is this one.
        EXPECT_EQ(info.visit_order, int64_t(k));
        EXPECT_EQ(info.layer, visit.layer);
        EXPECT_EQ(info.visited_occluded, visit.occluded);
        EXPECT_EQ(info.o, snap_->occluder->get(visit.voxel.x, visit.voxel.y));
        EXPECT_EQ(info.h, snap_->occlusion->get(visit.voxel.x, visit.voxel.y));
        const int listed = snap_->identifiers_static->listLength(visit.voxel.x, visit.voxel.y) +
                           snap_->identifiers_dynamic->listLength(visit.voxel.x, visit.voxel.y);
        EXPECT_EQ(int(info.ids_i.size()), listed);
        for (int id : info.ids_i) EXPECT_GE(scene.indexOf(id), 0) << "I holds ids, not indices";
    }
    describeRgvcVoxel(*snap_, scene, {-1, 3}, info);
    EXPECT_FALSE(info.valid);
}

TEST_F(RgvcViewTest, SessionGivesNoSnapshotForOtherCullers) {
    std::string error;
    ASSERT_TRUE(session_.selectAlgorithm("vfc", error)) << error;
    EXPECT_EQ(session_.debugSnapshot(), nullptr);
}

TEST_F(RgvcViewTest, MatrixRunsCoverExactlyTheirVoxels) {
    EXPECT_NEAR(area(fillOf(only(RgvcLayer::Occluder))),
                double(snap_->occluder->count()) * voxelArea(), 1e-3);
    EXPECT_GT(snap_->occlusion->count(), 0);
    EXPECT_NEAR(area(fillOf(only(RgvcLayer::Occlusion))),
                double(snap_->occlusion->count()) * voxelArea(), 1e-3);
}

TEST_F(RgvcViewTest, LayerStepShowsVisitsUpToTheLayer) {
    ASSERT_GT(snap_->last_layer, snap_->first_layer + 3);
    RgvcViewState view = only(RgvcLayer::Visited);
    view.show[int(RgvcLayer::CurrentLayer)] = false;
    view.layer = snap_->first_layer + 3;
    int64_t before = 0, current = 0;
    for (const RgvcVisit& v : snap_->visits) {
        before += v.layer < view.layer ? 1 : 0;
        current += v.layer == view.layer ? 1 : 0;
    }
    EXPECT_NEAR(area(fillOf(view)), double(before) * voxelArea(), 1e-3);
    // -1 (every layer): the current layer is the last one.
    int64_t last = 0;
    for (const RgvcVisit& v : snap_->visits) last += v.layer == snap_->last_layer ? 1 : 0;
    EXPECT_NEAR(area(fillOf(only(RgvcLayer::CurrentLayer))), double(last) * voxelArea(), 1e-3);
    view = only(RgvcLayer::CurrentLayer);
    view.layer = snap_->first_layer + 3;
    EXPECT_NEAR(area(fillOf(view)), double(current) * voxelArea(), 1e-3);
    EXPECT_EQ(rgvcShownLayer(*snap_, snap_->last_layer + 100), snap_->last_layer);
}

TEST_F(RgvcViewTest, PickedOccluderDrawsItsStepsAndPolygon) {
    ASSERT_FALSE(snap_->occluders.empty());
    RgvcViewState view = only(RgvcLayer::Polygon);
    view.occluder = int(snap_->occluders.size()) - 1;
    const RgvcOccluderView& picked = snap_->occluders.back();
    EXPECT_EQ(fillOf(view).empty(), picked.polygon_count == 0);
    // A click on its initial voxel picks it (or an earlier occluder starting there).
    const int clicked = rgvcOccluderAt(*snap_, picked.occluder.initial);
    ASSERT_GE(clicked, 0);
    EXPECT_EQ(snap_->occluders[size_t(clicked)].occluder.initial, picked.occluder.initial);
    EXPECT_EQ(rgvcOccluderAt(*snap_, {-5, -5}), -1);
    view.occluder = int(snap_->occluders.size());  // out of range: nothing, no crash
    EXPECT_TRUE(fillOf(view).empty());
}

// With --rgvc-extension 1 a staircase occluder (two Ls) draws all its steps,
// step 3 included, numbered in the paper's order, and every one of its
// polygons (up to four) as a convex fan out from the outline.
TEST_F(RgvcViewTest, PickedStaircaseDrawsItsFourStepsAndEveryPolygon) {
    SceneLoadResult loaded =
        loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/figure1-2d.json");
    ASSERT_TRUE(loaded.scene);
    KnobValues knobs;
    knobs.set("rgvc-extension", 1);
    DebuggerSession session{knobs};
    std::string error;
    ASSERT_TRUE(session.open(std::move(*loaded.scene), "", "rgvc", error)) << error;
    // The first frame with a staircase that has more than two polygons, else any staircase.
    int index = -1;
    for (int frame = 0; frame < session.scene().frames && index < 0; frame += 5) {
        session.seek(frame);
        snap_ = session.debugSnapshot()->as<RgvcSnapshot>();
        ASSERT_NE(snap_, nullptr);
        for (size_t k = 0; k < snap_->occluders.size(); ++k) {
            const RgvcOccluderView& o = snap_->occluders[k];
            if (!o.occluder.isStaircase()) continue;
            if (index < 0 || o.polygon_count > 2) index = int(k);
            if (o.polygon_count > 2) break;
        }
    }
    ASSERT_GE(index, 0) << "no staircase occluder in figure1-2d";
    const RgvcOccluderView& picked = snap_->occluders[size_t(index)];
    const RgvcExtendedOccluder& occ = picked.occluder;
    ASSERT_TRUE(occ.steps[2].run && occ.steps[2].count > 0);
    ASSERT_GT(picked.polygon_count, 2);  // more than an L's

    // The steps: the initial voxel and every step's voxels, each once, are the
    // staircase's voxels; each step that added voxels is numbered.
    RgvcViewState view = only(RgvcLayer::PickedOccluder);
    view.occluder = index;
    EXPECT_NEAR(area(fillOf(view)), double(occ.voxelCount()) * voxelArea(), 1e-3);
    std::string labels;
    for (const DebugDrawBatch::Label& label : batch_.layer(DrawSpace::World).labels)
        labels += batch_.labelText(label);
    std::string expected;
    for (size_t i = 0; i < occ.steps.size(); ++i)
        if (occ.steps[i].run && occ.steps[i].count > 0) expected += char('1' + i);
    EXPECT_EQ(labels, expected);
    EXPECT_NE(labels.find('3'), std::string::npos);
    // A click on a voxel of the second L (the end of step 4, or of step 3) picks
    // an occluder that covers it.
    const RgvcExtensionStep& last = occ.steps[occ.steps[3].count > 0 ? 3 : 2];
    const glm::ivec2 far_voxel = last.from + last.direction * last.count;
    const int clicked = rgvcOccluderAt(*snap_, far_voxel);
    ASSERT_GE(clicked, 0);
    EXPECT_TRUE(snap_->occluders[size_t(clicked)].occluder.covers(far_voxel));

    // The polygons: one fan per polygon, (outline + 2) corners, so outline
    // triangles each, and every fan's corners are the polygon's outline.
    view = only(RgvcLayer::Polygon);
    view.occluder = index;
    const std::vector<DebugDrawBatch::Vertex>& fill = fillOf(view);
    size_t triangles = 0;
    for (int p = 0; p < picked.polygon_count; ++p)
        triangles += size_t(picked.polygons[size_t(p)].outline_count);
    ASSERT_EQ(fill.size(), 3 * triangles);
    size_t at = 0;
    for (int p = 0; p < picked.polygon_count; ++p) {
        const RgvcOcclusionPolygon& poly = picked.polygons[size_t(p)];
        // The fan from the far end of the first silhouette ray: triangle k's
        // second corner is outline point k.
        for (int k = 0; k < poly.outline_count; ++k) {
            const glm::vec3 drawn = fill[at + 3 * size_t(k) + 1].position;
            EXPECT_NEAR(drawn.x, poly.outline[size_t(k)].x, 1e-3);
            EXPECT_NEAR(drawn.y, poly.outline[size_t(k)].y, 1e-3);
        }
        at += 3 * size_t(poly.outline_count);
    }
}

// The whole panel column headless (no GL) with the rgvc family's view from the
// ui registry, its flags set and a voxel hovered: it draws, and without input
// asks for nothing.
TEST_F(RgvcViewTest, PanelDrawsHeadlessAndAsksForNothing) {
    test::createHeadlessImGui();

    const FamilyViewEntry* entry = familyViewOfAlgorithm("rgvc");
    ASSERT_NE(entry, nullptr);
    std::unique_ptr<FamilyView> view = entry->make();
    KnobValues flags;
    flags.set("rgvc-layer", double(snap_->first_layer + 2));
    flags.set("rgvc-occluder", 0);
    std::string error;
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;

    const std::vector<std::string> names = algorithmNames(2);
    const std::string file;
    const std::vector<std::string> errors;
    FrameSnapshot snapshot = test::snapshotOfSession(session_, names, file, errors);
    FamilyViewContext context;
    context.scene = &session_.scene();
    context.algo = "rgvc";
    context.snapshot = snap_;
    context.knobs = &session_.knobs();
    // Hover the centre of the last visited voxel.
    const glm::ivec2 voxel = snap_->visits.back().voxel;
    ViewPointer pointer;
    pointer.over_view = true;
    pointer.origin = voxelCentre(voxel);
    view->pointer(context, pointer);
    // The rgvc panel (toggles, sliders, memory, voxel) is a sizeable part of the column.
    EXPECT_GT(test::familyPanelVertices(snapshot, view.get(), context), 1000);
    ImGui::DestroyContext();
}

// A click over the view picks the extended occluder at the voxel under it: its
// steps and outline join the overlay.
TEST_F(RgvcViewTest, AClickPicksTheOccluderUnderThePointer) {
    ASSERT_FALSE(snap_->occluders.empty());
    std::unique_ptr<FamilyView> view = familyViewOfAlgorithm("rgvc")->make();
    FamilyViewContext context;
    context.scene = &session_.scene();
    context.snapshot = snap_;
    const size_t before = heavyLines(*view, context);
    ViewPointer pointer;
    pointer.over_view = true;
    pointer.origin = voxelCentre(snap_->occluders.back().occluder.initial);
    view->pointer(context, pointer);  // hovering picks nothing
    EXPECT_EQ(heavyLines(*view, context), before);
    pointer.clicked = true;
    view->pointer(context, pointer);
    EXPECT_GT(heavyLines(*view, context), before + 8);
    pointer.origin = {-1e6, -1e6, 0.0};  // a click off the grid clears the pick
    view->pointer(context, pointer);
    EXPECT_EQ(heavyLines(*view, context), before);
}

}  // namespace
}  // namespace gridcull
