// The rgvc overlay presets (ui/rgvc/rgvc_view.h) and the hovered voxel's
// outline (ui/rgvc/rgvc_hovered_voxel.h), through the family's view from the ui
// registry on the Figure 1 scene (2D) and hidden movers (3D): a new view starts
// with the first preset, not with every layer on; each preset shows its layers'
// colours and no others; the preset follows a change of dimension; --rgvc-tbv
// overrides it until another preset is picked; the voxel under the pointer is
// outlined in white, and nothing is when the pointer leaves the view.
#include <memory>
#include <set>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "tests/ui/overlay_swatches.h"
#include "tests/ui/rgvc/rgvc_view_helpers.h"
#include "ui/registry/family_views.h"
#include "ui/rgvc/rgvc_frame_index.h"
#include "ui/rgvc/rgvc_hovered_voxel.h"
#include "ui/rgvc/rgvc_pick3d.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {
namespace {

using L = RgvcLayer;

std::set<RgvcLayer> shownLayers(OverlayPreset preset, int dimensions) {
    RgvcViewState view;
    rgvcApplyPreset(view, preset, dimensions);
    std::set<RgvcLayer> out;
    for (int l = 0; l < kRgvcLayerCount; ++l)
        if (view.show[l]) out.insert(RgvcLayer(l));
    return out;
}

TEST(RgvcPresets, EachPresetShowsItsLayers) {
    const std::vector<OverlayPreset> presets = rgvcOverlayPresets();
    ASSERT_EQ(presets.size(), 4u);
    EXPECT_EQ(presets.front(), OverlayPreset::Occlusion) << "the readable one first";
    // The matrices of the occlusion computation and a picked occluder's steps and polygons.
    EXPECT_EQ(shownLayers(OverlayPreset::Occlusion, 2),
              (std::set<L>{L::Occluder, L::Occlusion, L::PickedOccluder, L::Polygon}));
    // In 3D too: Os stays folded into O (its grey boxes would cover O's).
    EXPECT_EQ(shownLayers(OverlayPreset::Occlusion, 3),
              (std::set<L>{L::Occluder, L::Occlusion, L::PickedOccluder, L::Polygon}));
    EXPECT_EQ(shownLayers(OverlayPreset::Traversal, 2),
              (std::set<L>{L::Visited, L::CurrentLayer, L::Seed, L::LineOfSight, L::Occluder}));
    EXPECT_EQ(shownLayers(OverlayPreset::Traversal, 3),
              (std::set<L>{L::Visited, L::CurrentLayer, L::Seed, L::LineOfSight}));
    for (int d : {2, 3})
        EXPECT_EQ(shownLayers(OverlayPreset::Tbvs, d), (std::set<L>{L::Tbv, L::Identifiers}));
    // All: every layer that applies (Os is 3D only), T in 3D too.
    EXPECT_EQ(shownLayers(OverlayPreset::All, 2).size(), size_t(kRgvcLayerCount - 1));
    EXPECT_EQ(shownLayers(OverlayPreset::All, 2).count(L::StaticOccluder), 0u);
    EXPECT_EQ(shownLayers(OverlayPreset::All, 3).size(), size_t(kRgvcLayerCount));
}

class RgvcPresetsTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_NO_FATAL_FAILURE(test::openRgvc(session2d_, "figure1-2d.json", 30));
        ASSERT_NO_FATAL_FAILURE(test::openRgvc(session3d_, "hidden-movers-3d.json", 60));
        view_ = findFamilyView("rgvc")->make();
    }

    static FamilyViewContext contextOf(const DebuggerSession& session) {
        FamilyViewContext context;
        context.scene = &session.scene();
        context.snapshot = session.debugSnapshot();
        return context;
    }
    const RgvcSnapshot& snap(const DebuggerSession& session) const {
        return *session.debugSnapshot()->as<RgvcSnapshot>();
    }

    // The swatches `view` draws over `session`'s frame.
    std::set<Swatch> drawn(FamilyView& view, const DebuggerSession& session) {
        batch_.clear();
        view.drawOverlay(contextOf(session), OverlayView{}, batch_);
        return test::swatchesIn(batch_);
    }
    std::set<Swatch> drawn(const DebuggerSession& session) { return drawn(*view_, session); }

    DebuggerSession session2d_{KnobValues{}}, session3d_{KnobValues{}};
    std::unique_ptr<FamilyView> view_;
    DebugDrawBatch batch_;
};

bool has(const std::set<Swatch>& s, Swatch w) {
    return s.count(w) != 0;
}

// A new view shows occlusion only: O and H, not the traversal's green, T's
// purple, I's orange or the line of sight (the issue: ten layers at once).
TEST_F(RgvcPresetsTest, ANewViewStartsWithTheFirstPreset) {
    EXPECT_EQ(view_->overlayPresets(), rgvcOverlayPresets());
    const std::set<Swatch> fresh = drawn(session2d_);
    EXPECT_TRUE(has(fresh, Swatch::NearBlack) && has(fresh, Swatch::LightGrey));
    for (Swatch off : {Swatch::BluishGreen, Swatch::ReddishPurple, Swatch::Orange, Swatch::Yellow})
        EXPECT_FALSE(has(fresh, off)) << swatchName(off);
    std::unique_ptr<FamilyView> other = findFamilyView("rgvc")->make();
    other->applyOverlayPreset(rgvcOverlayPresets().front());
    EXPECT_EQ(drawn(*other, session2d_), fresh);
    other->applyOverlayPreset(OverlayPreset::All);
    EXPECT_NE(drawn(*other, session2d_), fresh);
}

TEST_F(RgvcPresetsTest, EachPresetDrawsItsLayersColours) {
    view_->applyOverlayPreset(OverlayPreset::Traversal);
    std::set<Swatch> s = drawn(session2d_);
    for (Swatch on : {Swatch::BluishGreen, Swatch::Yellow, Swatch::NearBlack})
        EXPECT_TRUE(has(s, on)) << "traversal: " << swatchName(on);
    for (Swatch off : {Swatch::LightGrey, Swatch::ReddishPurple, Swatch::Orange})
        EXPECT_FALSE(has(s, off)) << "traversal: " << swatchName(off);

    view_->applyOverlayPreset(OverlayPreset::Tbvs);
    s = drawn(session2d_);
    EXPECT_TRUE(has(s, Swatch::Orange)) << "TBVs: I";
    for (Swatch off : {Swatch::NearBlack, Swatch::LightGrey, Swatch::BluishGreen, Swatch::Yellow})
        EXPECT_FALSE(has(s, off)) << "TBVs: " << swatchName(off);

    view_->applyOverlayPreset(OverlayPreset::All);
    s = drawn(session2d_);
    for (Swatch on : {Swatch::NearBlack, Swatch::LightGrey, Swatch::Orange, Swatch::BluishGreen,
                      Swatch::Yellow})
        EXPECT_TRUE(has(s, on)) << "all: " << swatchName(on);
}

// T's boxes in 3D: hidden by the first preset, shown by "TBVs", also when the
// preset was picked in a 2D scene and a 3D one opened after it; --rgvc-tbv 0
// hides them over the preset until another preset is picked.
TEST_F(RgvcPresetsTest, ThePresetFollowsTheDimensionAndTheTbvFlagOverridesIt) {
    const Swatch t = rgvcLayerSwatch(L::Tbv);
    EXPECT_FALSE(has(drawn(session3d_), t)) << "3D starts without T";
    view_->applyOverlayPreset(OverlayPreset::Tbvs);
    drawn(session2d_);
    EXPECT_TRUE(has(drawn(session3d_), t)) << "2D, then 3D: still the TBVs preset";
    EXPECT_FALSE(has(drawn(session3d_), Swatch::NearBlack)) << "no O in the TBVs preset";

    KnobValues flags;
    flags.set("rgvc-tbv", 0);
    std::string error;
    ASSERT_TRUE(view_->applyFlags(flags, session3d_.scene(), error)) << error;
    EXPECT_FALSE(has(drawn(session3d_), t)) << "--rgvc-tbv 0";
    drawn(session2d_);
    EXPECT_FALSE(has(drawn(session3d_), t)) << "--rgvc-tbv 0 over a change of dimension";
    view_->applyOverlayPreset(OverlayPreset::All);
    EXPECT_TRUE(has(drawn(session3d_), t)) << "a preset picked after the flag";
}

// Os (grey) is folded into O by the first preset in 3D, drawn apart by "all";
// --rgvc-static sets it over the preset, and flags a step leaves out go back
// to their defaults (a lesson sets them step after step).
TEST_F(RgvcPresetsTest, TheStaticFlagOverridesThePresetAndFlagsLeftOutReset) {
    const Swatch os = rgvcLayerSwatch(L::StaticOccluder);
    EXPECT_FALSE(has(drawn(session3d_), os)) << "Os folded into O";
    view_->applyOverlayPreset(OverlayPreset::All);
    EXPECT_TRUE(has(drawn(session3d_), os)) << "all: Os apart";
    KnobValues flags;
    flags.set("rgvc-static", 0);
    std::string error;
    ASSERT_TRUE(view_->applyFlags(flags, session3d_.scene(), error)) << error;
    EXPECT_FALSE(has(drawn(session3d_), os)) << "--rgvc-static 0 over all";
    flags = KnobValues{};
    flags.set("rgvc-static", 1);
    view_->applyOverlayPreset(OverlayPreset::Occlusion);
    ASSERT_TRUE(view_->applyFlags(flags, session3d_.scene(), error)) << error;
    EXPECT_TRUE(has(drawn(session3d_), os)) << "--rgvc-static 1 over occlusion only";

    // A slice asked for, then a step without it: the voxel boxes again.
    flags = KnobValues{};
    flags.set("rgvc-slice", 6);
    ASSERT_TRUE(view_->applyFlags(flags, session3d_.scene(), error)) << error;
    drawn(session3d_);
    const size_t slice_triangles = batch_.layer(DrawSpace::World).fill.size();
    ASSERT_TRUE(view_->applyFlags(KnobValues{}, session3d_.scene(), error)) << error;
    drawn(session3d_);
    EXPECT_NE(batch_.layer(DrawSpace::World).fill.size(), slice_triangles)
        << "the slice stayed after its flag went";
}

// 2D: the hovered voxel's square, white at kBoldLine, and nothing once the
// pointer leaves the view.
TEST_F(RgvcPresetsTest, TheVoxelUnderThePointerIsOutlined) {
    const RgvcSnapshot& s = snap(session2d_);
    const glm::ivec2 v = s.visits.back().voxel;
    const glm::dvec3 d = s.grid.voxelSize();
    const double x0 = s.grid.world.min.x + v.x * d.x, y0 = s.grid.world.min.y + v.y * d.y;
    ViewPointer pointer;
    pointer.over_view = true;
    pointer.origin = {x0 + 0.5 * d.x, y0 + 0.5 * d.y, 0.0};
    const FamilyViewContext context = contextOf(session2d_);
    view_->pointer(context, pointer);
    drawn(session2d_);
    const std::vector<DebugDrawBatch::Vertex> outline =
        test::linesOf(batch_, DrawSpace::World, kRgvcHoverPaint.swatch, kRgvcHoverWidth);
    ASSERT_EQ(outline.size(), 8u) << "four sides";
    const glm::vec4 b = test::boundsXY(outline);
    EXPECT_NEAR(b.x, x0, 1e-3);
    EXPECT_NEAR(b.y, y0, 1e-3);
    EXPECT_NEAR(b.z, x0 + d.x, 1e-3);
    EXPECT_NEAR(b.w, y0 + d.y, 1e-3);

    pointer.over_view = false;
    view_->pointer(context, pointer);
    drawn(session2d_);
    EXPECT_FALSE(has(test::swatchesIn(batch_), kRgvcHoverPaint.swatch)) << "white: the pointer's";
}

// 3D: the box of the voxel the pointer's ray picks, its twelve edges.
TEST_F(RgvcPresetsTest, TheVoxelUnderThePointerIsOutlinedIn3d) {
    const RgvcSnapshot& s = snap(session3d_);
    RgvcViewState state;
    rgvcApplyPreset(state, rgvcOverlayPresets().front(), 3);
    RgvcFrameIndex index;
    const int64_t at = rgvcShownLayer(s, state.layer);
    index.update(s, at);
    const glm::dvec3 origin(151.37, 79.71, 158.93);
    const FamilyViewContext context = contextOf(session3d_);
    int checked = 0;
    for (int k = 0; k < 40 && checked < 3; ++k) {
        const glm::dvec3 target(5.0 + 2.3 * k, 3.0 + 1.3 * k, 90.0 - 2.1 * k);
        const glm::dvec3 dir = glm::normalize(target - origin);
        glm::ivec3 voxel;
        if (!pickRgvcVoxel3d(s, state, index, at, origin, dir, voxel)) continue;
        ++checked;
        ViewPointer pointer;
        pointer.over_view = true;
        pointer.origin = origin;
        pointer.direction = dir;
        view_->pointer(context, pointer);
        drawn(session3d_);
        const std::vector<DebugDrawBatch::Vertex> edges =
            test::linesOf(batch_, DrawSpace::World, kRgvcHoverPaint.swatch, kRgvcHoverWidth);
        ASSERT_EQ(edges.size(), 24u) << "ray " << k;
        const Aabb box = s.grid.voxelBounds(voxel);
        glm::dvec3 lo(1e30), hi(-1e30);
        for (const DebugDrawBatch::Vertex& e : edges) {
            lo = glm::min(lo, glm::dvec3(e.position));
            hi = glm::max(hi, glm::dvec3(e.position));
        }
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(lo[a], box.min[a], 1e-3) << "ray " << k;
            EXPECT_NEAR(hi[a], box.max[a], 1e-3) << "ray " << k;
        }
    }
    EXPECT_EQ(checked, 3);
    ViewPointer away;
    view_->pointer(context, away);
    drawn(session3d_);
    EXPECT_TRUE(
        test::linesOf(batch_, DrawSpace::World, kRgvcHoverPaint.swatch, kRgvcHoverWidth).empty());
}

}  // namespace
}  // namespace gridcull
