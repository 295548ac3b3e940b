// The rgvc view's mapping from the culler's snapshot to what the window shows:
// the voxel description of the panel (ui/rgvc/rgvc_view.h) and the overlay geometry
// (app/rgvc_overlay.h), on the Figure 1 scene run through the debugger session.
#include <cfloat>
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <imgui.h>

#include "app/debugger_session.h"
#include "app/rgvc_overlay.h"
#include "culling/io/scene_loader.h"
#include "tests/app/session_frame_snapshot.h"
#include "ui/debugger_ui.h"
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
        snap_ = session_.rgvcSnapshot();
        ASSERT_NE(snap_, nullptr);
        ASSERT_FALSE(snap_->visits.empty());
    }

    // Total area of the triangles in `fill` (world units squared).
    static double area(const std::vector<ColorVertex>& fill) {
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

    static RgvcViewState only(RgvcLayer layer) {
        RgvcViewState view;
        for (bool& on : view.show) on = false;
        view.show[int(layer)] = true;
        return view;
    }

    DebuggerSession session_{CullerOptions{}};
    const RgvcSnapshot* snap_ = nullptr;
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
    EXPECT_EQ(session_.rgvcSnapshot(), nullptr);
}

TEST_F(RgvcViewTest, MatrixRunsCoverExactlyTheirVoxels) {
    RgvcOverlayGeometry geometry;
    buildRgvcOverlay(*snap_, only(RgvcLayer::Occluder), geometry);
    EXPECT_NEAR(area(geometry.fill), double(snap_->occluder->count()) * voxelArea(), 1e-3);
    buildRgvcOverlay(*snap_, only(RgvcLayer::Occlusion), geometry);
    EXPECT_GT(snap_->occlusion->count(), 0);
    EXPECT_NEAR(area(geometry.fill), double(snap_->occlusion->count()) * voxelArea(), 1e-3);
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
    RgvcOverlayGeometry geometry;
    buildRgvcOverlay(*snap_, view, geometry);
    EXPECT_NEAR(area(geometry.fill), double(before) * voxelArea(), 1e-3);
    buildRgvcOverlay(*snap_, only(RgvcLayer::CurrentLayer), geometry);
    // -1 (every layer): the current layer is the last one.
    int64_t last = 0;
    for (const RgvcVisit& v : snap_->visits) last += v.layer == snap_->last_layer ? 1 : 0;
    EXPECT_NEAR(area(geometry.fill), double(last) * voxelArea(), 1e-3);
    view = only(RgvcLayer::CurrentLayer);
    view.layer = snap_->first_layer + 3;
    buildRgvcOverlay(*snap_, view, geometry);
    EXPECT_NEAR(area(geometry.fill), double(current) * voxelArea(), 1e-3);
    EXPECT_EQ(rgvcShownLayer(*snap_, snap_->last_layer + 100), snap_->last_layer);
}

TEST_F(RgvcViewTest, PickedOccluderDrawsItsStepsAndPolygon) {
    ASSERT_FALSE(snap_->occluders.empty());
    RgvcViewState view = only(RgvcLayer::Polygon);
    view.occluder = int(snap_->occluders.size()) - 1;
    RgvcOverlayGeometry geometry;
    buildRgvcOverlay(*snap_, view, geometry);
    const RgvcOccluderView& picked = snap_->occluders.back();
    EXPECT_EQ(geometry.fill.empty(), picked.polygon_count == 0);
    // A click on its initial voxel picks it (or an earlier occluder starting there).
    const int clicked = rgvcOccluderAt(*snap_, picked.occluder.initial);
    ASSERT_GE(clicked, 0);
    EXPECT_EQ(snap_->occluders[size_t(clicked)].occluder.initial, picked.occluder.initial);
    EXPECT_EQ(rgvcOccluderAt(*snap_, {-5, -5}), -1);
    view.occluder = int(snap_->occluders.size());  // out of range: nothing, no crash
    buildRgvcOverlay(*snap_, view, geometry);
    EXPECT_TRUE(geometry.fill.empty());
}

// The whole panel column headless (no GL) with the rgvc panel and a hovered
// voxel: it draws, and without input asks for no change of the view.
TEST_F(RgvcViewTest, PanelDrawsHeadlessAndAsksForNothing) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);

    const std::vector<std::string> names = cullerNames();
    const std::string file;
    const std::vector<std::string> errors;
    RgvcVoxelInfo voxel;
    describeRgvcVoxel(*snap_, session_.scene(), snap_->visits.back().voxel, voxel);
    FrameSnapshot snapshot = test::snapshotOfSession(session_, names, file, errors);
    snapshot.rgvc = snap_;
    snapshot.rgvc_view.layer = snap_->first_layer + 2;
    snapshot.rgvc_view.occluder = 0;
    snapshot.rgvc_voxel = &voxel;
    UiState state;
    // Tall enough that no panel is clipped, so vertex counts compare.
    const WindowLayout layout = computeLayout(1280, 4000, true);
    int vertices_with = 0;
    for (int pass = 0; pass < 4; ++pass) {
        if (pass == 3) snapshot.rgvc = nullptr;  // another culler: no rgvc panel
        io.DisplaySize = ImVec2(1280, 4000);
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        ImGui::NewFrame();
        const UiActions actions = drawDebuggerUi(snapshot, state, layout);
        ImGui::Render();
        EXPECT_FALSE(actions.rgvc.view.has_value());
        if (pass == 2) vertices_with = ImGui::GetDrawData()->TotalVtxCount;
    }
    // The rgvc panel (toggles, sliders, memory, voxel) is a sizeable part of the column.
    EXPECT_GT(vertices_with, ImGui::GetDrawData()->TotalVtxCount + 1000);
    ImGui::DestroyContext();
}

}  // namespace
}  // namespace gridcull
