// The rgvc view's per-layer history in 2D (ui/rgvc/rgvc_history.h) and the
// voxel under the mouse's "why": stepping to layer L shows H as the voxels
// with h_layer <= L, O without those a later reveal made opaque, T with the
// TBVs revealed later; the panel names the occluder that hid a voxel (its
// h_cause, not whichever occluder lies there) and its button picks it; and a
// culled object's voxels in I with what the traversal found in each.
#include <string>

#include <gtest/gtest.h>

#include "tests/ui/rgvc/rgvc_panel_probe.h"
#include "tests/ui/rgvc/rgvc_view_helpers.h"
#include "ui/registry/family_views.h"
#include "ui/rgvc/rgvc_frame_index.h"
#include "ui/rgvc/rgvc_history.h"
#include "ui/rgvc/rgvc_object_voxels.h"
#include "ui/rgvc/rgvc_overlay.h"
#include "ui/rgvc/rgvc_panel.h"
#include "ui/rgvc/rgvc_voxel_panel.h"

namespace gridcull {
namespace {

constexpr int kFrame = 60;

class RgvcHistoryView2dTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_NO_FATAL_FAILURE(test::openRgvc(session_, "figure1-2d.json", kFrame));
        snap_ = session_.debugSnapshot()->as<RgvcSnapshot>();
        ASSERT_GT(snap_->last_layer, snap_->first_layer + 10);
    }

    static RgvcViewState only(RgvcLayer layer, int64_t at) {
        RgvcViewState view;
        for (bool& on : view.show) on = false;
        view.show[int(layer)] = true;
        view.layer = at;
        return view;
    }

    test::VoxelSet drawn(const RgvcViewState& view, Swatch swatch) {
        batch_.clear();
        drawRgvcOverlay(*snap_, view, batch_, scratch_);
        return test::coveredVoxels(batch_, swatch, snap_->grid, 2, 0.0, 0);
    }

    template <typename In>
    test::VoxelSet expected(In&& in) const {
        test::VoxelSet out;
        for (int y = 0; y < snap_->grid.resolution.y; ++y)
            for (int x = 0; x < snap_->grid.resolution.x; ++x)
                if (in(x, y, rgvcLinear(snap_->grid, x, y, 0))) out.insert({x, y, 0});
        return out;
    }

    DebuggerSession session_{KnobValues{}};
    const RgvcSnapshot* snap_ = nullptr;
    DebugDrawBatch batch_;
    std::vector<uint8_t> scratch_;
};

TEST_F(RgvcHistoryView2dTest, HAtALayerIsTheVoxelsThatEnteredHByThen) {
    const int64_t mid = (snap_->first_layer + snap_->last_layer) / 2;
    size_t before = 0;
    for (const int64_t at : {snap_->first_layer + 5, mid, snap_->last_layer}) {
        const test::VoxelSet want =
            expected([&](int, int, size_t i) { return snap_->h_layer[i] <= at; });
        EXPECT_EQ(drawn(only(RgvcLayer::Occlusion, at), Swatch::LightGrey), want) << "layer " << at;
        EXPECT_GE(want.size(), before);
        before = want.size();
    }
    // The frame's H grows over the layers: the history is not the end of the frame.
    const test::VoxelSet early =
        drawn(only(RgvcLayer::Occlusion, snap_->first_layer + 5), Swatch::LightGrey);
    EXPECT_LT(early.size(), size_t(snap_->occlusion->count()));
    // Every layer (-1) is the end of the frame.
    EXPECT_EQ(drawn(only(RgvcLayer::Occlusion, -1), Swatch::LightGrey).size(),
              size_t(snap_->occlusion->count()));
}

TEST_F(RgvcHistoryView2dTest, OITAtALayerUndoTheLaterReveals) {
    // A frame whose traversal revealed a TBV in a later layer than its first.
    int64_t at = -1;
    for (int frame = kFrame; frame < session_.scene().frames && at < 0; frame += 3) {
        session_.seek(frame);
        snap_ = session_.debugSnapshot()->as<RgvcSnapshot>();
        for (const RgvcRevealView& r : snap_->reveals)
            if (r.layer > snap_->first_layer && !r.tbv.edge) at = r.layer - 1;
    }
    ASSERT_GE(at, 0) << "no reveal during a traversal in figure1-2d";
    const test::VoxelSet o_want = expected([&](int x, int y, size_t i) {
        return snap_->occluder->get(x, y) &&
               (snap_->o_layer[i] == kRgvcNoLayer || snap_->o_layer[i] <= at);
    });
    EXPECT_EQ(drawn(only(RgvcLayer::Occluder, at), Swatch::NearBlack), o_want);
    // T: the end of the frame's T and the cells of the TBVs revealed after `at`.
    test::VoxelSet t_want =
        expected([&](int x, int y, size_t) { return !snap_->tbvs->empty(x, y); });
    const size_t t_end = t_want.size();
    for (const RgvcRevealView& r : snap_->reveals)
        if (r.layer > at)
            rgvcForEachTbvVoxel(*snap_, r.tbv, [&](int x, int y, int) {
                t_want.insert({x, y, 0});
            });
    EXPECT_GT(t_want.size(), t_end) << "the revealed TBVs add cells";
    EXPECT_EQ(drawn(only(RgvcLayer::Tbv, at), Swatch::ReddishPurple), t_want);
    // I: without the objects revealed after `at`, which were under their TBVs then.
    const auto revealedAfter = [&](int32_t index) {
        for (const RgvcRevealView& r : snap_->reveals)
            if (r.tbv.object_index == index) return r.layer > at;
        return false;
    };
    size_t i_end = 0;
    const test::VoxelSet i_want = expected([&](int x, int y, size_t) {
        bool end = !snap_->identifiers_static->empty(x, y), then = end;
        snap_->identifiers_dynamic->forEach(x, y, [&](int32_t index) {
            end = true;
            then = then || !revealedAfter(index);
        });
        i_end += end ? 1 : 0;
        return then;
    });
    EXPECT_LT(i_want.size(), i_end) << "the revealed objects' voxels were not in I yet";
    EXPECT_EQ(drawn(only(RgvcLayer::Identifiers, at), Swatch::Orange), i_want);
}

// The voxel description and the panel name the occluder that hid a voxel: the
// one whose polygon marked it first (h_cause), here one that is not the
// occluder a click on that voxel would pick (rgvcOccluderAt).
TEST_F(RgvcHistoryView2dTest, WhyNamesTheOccluderThatHidTheVoxelAndItsButtonPicksIt) {
    glm::ivec2 voxel{-1};
    int32_t cause = -1;
    for (int y = 0; y < snap_->grid.resolution.y && cause < 0; ++y)
        for (int x = 0; x < snap_->grid.resolution.x && cause < 0; ++x) {
            const int32_t c = snap_->h_cause[rgvcLinear(snap_->grid, x, y, 0)];
            if (c > 0 && rgvcOccluderAt(*snap_, {x, y}) != c) voxel = {x, y}, cause = c;
        }
    ASSERT_GE(cause, 0);
    RgvcVoxelInfo info;
    describeRgvcVoxel(*snap_, session_.scene(), voxel, info);
    ASSERT_TRUE(info.h);
    EXPECT_EQ(info.cause, cause);

    test::PanelProbe probe;
    RgvcViewState view;
    const auto draw = [&] { drawRgvcVoxelInfo(*snap_, view, &info, true); };
    const std::string text = probe.text(draw);
    EXPECT_NE(text.find("hidden by"), std::string::npos) << text;
    EXPECT_NE(text.find("occluder " + std::to_string(cause)), std::string::npos) << text;
    EXPECT_TRUE(probe.clickUntil(draw, [&] { return view.occluder == cause; }))
        << "no click on the panel picked occluder " << cause;
}

// The family view's panel shows the voxel the pointer is over, and a click
// keeps it there once the pointer has left the view.
TEST_F(RgvcHistoryView2dTest, TheClickedVoxelStaysInThePanel) {
    std::unique_ptr<FamilyView> view = familyViewOfAlgorithm("rgvc")->make();
    FamilyViewContext context;
    context.scene = &session_.scene();
    context.snapshot = snap_;
    const RgvcVisit& visit = snap_->visits[snap_->visits.size() / 2];
    const glm::dvec3 d = snap_->grid.voxelSize();
    ViewPointer pointer;
    pointer.over_view = true;
    pointer.clicked = true;
    pointer.origin = {snap_->grid.world.min.x + (visit.voxel.x + 0.5) * d.x,
                      snap_->grid.world.min.y + (visit.voxel.y + 0.5) * d.y, 0.0};
    view->pointer(context, pointer);
    pointer = ViewPointer{};  // the pointer leaves the view
    view->pointer(context, pointer);
    test::PanelProbe probe;
    FamilyAction action;
    const std::string text = probe.text([&] { view->drawPanel(context, action); });
    char name[64];
    std::snprintf(name, sizeof name, "voxel (%d, %d) (clicked)", visit.voxel.x, visit.voxel.y);
    EXPECT_NE(text.find(name), std::string::npos) << text;
}

// A culled object: its voxels in I (a brute-force scan of I finds the same),
// each reached and occluded or not reached; the panel's buttons pick the
// occluders that hid them.
TEST_F(RgvcHistoryView2dTest, ACulledObjectListsTheVoxelsThatHidIt) {
    const std::vector<ObjectState>& states = session_.states();
    RgvcFrameIndex index;
    index.update(*snap_, rgvcShownLayer(*snap_, -1));
    RgvcObjectVoxels object;
    int picked = -1;
    for (size_t i = 0; i < states.size() && picked < 0; ++i) {
        if (states[i] != ObjectState::Culled) continue;
        describeRgvcObject(*snap_, session_.scene(), index, int(i), object);
        if (object.occluded > 0 && object.open == 0 && !object.under_tbv) picked = int(i);
    }
    ASSERT_GE(picked, 0) << "no culled object in I with an occluded voxel";
    int64_t in_i = 0;
    const IdListMatrix* list = session_.scene().objects[size_t(picked)].isDynamic()
                                   ? snap_->identifiers_dynamic
                                   : snap_->identifiers_static;
    for (int y = 0; y < snap_->grid.resolution.y; ++y)
        for (int x = 0; x < snap_->grid.resolution.x; ++x) in_i += list->contains(x, y, picked);
    EXPECT_EQ(int64_t(object.voxels.size()), in_i);
    EXPECT_EQ(object.occluded + object.unreached, in_i);
    int32_t cause = -1;
    for (const RgvcObjectVoxel& v : object.voxels) {
        EXPECT_TRUE(list->contains(v.voxel.x, v.voxel.y, picked));
        int64_t visit = -1;
        for (size_t k = 0; k < snap_->visits.size() && visit < 0; ++k)
            if (snap_->visits[k].voxel == glm::ivec2(v.voxel)) visit = int64_t(k);
        EXPECT_EQ(v.layer >= 0, visit >= 0);
        if (visit < 0) continue;
        EXPECT_EQ(v.layer, snap_->visits[size_t(visit)].layer);
        EXPECT_EQ(v.occluded, snap_->visits[size_t(visit)].occluded);
        if (v.occluded) {
            EXPECT_EQ(v.cause, snap_->h_cause[rgvcLinear(snap_->grid, v.voxel.x, v.voxel.y, 0)]);
            if (cause < 0) cause = v.cause;
        }
    }
    ASSERT_GE(cause, 0);
    test::PanelProbe probe;
    RgvcViewState view;
    const auto draw = [&] { drawRgvcObjectVoxels(*snap_, view, &object, ObjectState::Culled); };
    const std::string text = probe.text(draw);
    EXPECT_NE(text.find("occluded by"), std::string::npos) << text;
    EXPECT_TRUE(probe.clickUntil(draw, [&] { return view.occluder == cause; }));
}

}  // namespace
}  // namespace gridcull

namespace gridcull {
namespace {

// The picked occluder is explained in sentences (its growth, its Ls), not in
// code-like lists of numbers ("steps 0 66 13 2", "legs x 2 y 79").
TEST_F(RgvcHistoryView2dTest, ThePickedOccluderIsExplainedInSentences) {
    test::PanelProbe probe;
    RgvcViewState view;
    view.occluder = 0;
    RgvcPanelInput input;
    const std::string text = probe.text([&] { drawRgvcPanel(*snap_, view, input); });
    EXPECT_NE(text.find("Occluder 0 of"), std::string::npos) << text;
    EXPECT_NE(text.find("Extended into"), std::string::npos) << text;
    EXPECT_NE(text.find("turns at voxel"), std::string::npos) << text;
    EXPECT_EQ(text.find("legs x"), std::string::npos) << text;
    EXPECT_EQ(text.find("L, steps"), std::string::npos) << text;
}

}  // namespace
}  // namespace gridcull
