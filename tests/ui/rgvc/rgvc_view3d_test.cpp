// The rgvc view in 3D (ui/rgvc/rgvc_overlay3d.h and what it is built from), on
// hidden-movers-3d (a wall hides 2000 movers under TBVs) and walkthrough-3d
// (static spheres around a corridor): the voxel boxes are the faces between
// drawn and undrawn voxels that face the eye, back to front; the slice shows
// each matrix's voxels of its plane, T by the 2-of-3 test; stepping to a layer
// shows H as it stood then; a picked occluder's cap; the voxel under a ray;
// the "why" of an occluded voxel and a click that picks its occluder; a culled
// object's voxels.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "culling/rgvc/rgvc_tbv3d.h"
#include "tests/ui/rgvc/rgvc_panel_probe.h"
#include "tests/ui/rgvc/rgvc_view_helpers.h"
#include "ui/registry/family_views.h"
#include "ui/rgvc/rgvc_cap3d.h"
#include "ui/rgvc/rgvc_history.h"
#include "ui/rgvc/rgvc_object_voxels.h"
#include "ui/rgvc/rgvc_overlay3d.h"
#include "ui/rgvc/rgvc_pick3d.h"
#include "ui/rgvc/rgvc_voxel_panel.h"

namespace gridcull {
namespace {

class RgvcView3dTest : public ::testing::Test {
protected:
    void open(const char* file, int frame) {
        ASSERT_NO_FATAL_FAILURE(test::openRgvc(session_, file, frame));
        snap_ = session_.debugSnapshot()->as<RgvcSnapshot>();
        ASSERT_EQ(snap_->dimensions, 3);
        ASSERT_GT(snap_->last_layer, snap_->first_layer + 4);
    }

    static RgvcViewState only(std::initializer_list<RgvcLayer> layers, int64_t at = -1) {
        RgvcViewState view;
        for (bool& on : view.show) on = false;
        for (const RgvcLayer l : layers) view.show[int(l)] = true;
        view.layer = at;
        return view;
    }
    static RgvcViewState slice(RgvcViewState view, int axis, int index) {
        view.mode = RgvcVoxelMode::Slice;
        view.slice_axis = axis;
        view.slice_index = index;
        return view;
    }

    const DebugDrawBatch& draw(const RgvcViewState& view, const glm::dvec3& eye) {
        batch_.clear();
        drawRgvcOverlay3d(*snap_, view, session_.scene().camera.near, eye, batch_, scratch_);
        return batch_;
    }
    // The voxels of the slice `view` draws in `swatch`.
    test::VoxelSet sliceOf(const RgvcViewState& view, Swatch swatch) {
        draw(view, {0.0, 0.0, 0.0});
        const int a = view.slice_axis, n = rgvcSliceIndex(*snap_, view);
        return test::coveredVoxels(
            batch_, swatch, snap_->grid, a,
            snap_->grid.world.min[a] + (n + 0.5) * snap_->grid.voxelSize()[a], n);
    }
    // The voxels of plane `index` across `axis` for which in(x, y, z) holds.
    template <typename In>
    test::VoxelSet plane(int axis, int index, In&& in) const {
        test::VoxelSet out;
        const glm::ivec3 res = snap_->grid.resolution;
        for (int z = 0; z < res.z; ++z)
            for (int y = 0; y < res.y; ++y)
                for (int x = 0; x < res.x; ++x) {
                    const glm::ivec3 v(x, y, z);
                    if (v[axis] == index && in(x, y, z)) out.insert({x, y, z});
                }
        return out;
    }
    size_t linear(int x, int y, int z) const { return rgvcLinear(snap_->grid, x, y, z); }
    glm::dvec3 centre(const glm::ivec3& v) const {
        return snap_->grid.world.min + (glm::dvec3(v) + 0.5) * snap_->grid.voxelSize();
    }
    glm::i64vec3 viewerVoxel() const {
        return {snap_->viewer_voxel.x, snap_->viewer_voxel.y, snap_->viewer_voxel_z};
    }

    DebuggerSession session_{KnobValues{}};
    const RgvcSnapshot* snap_ = nullptr;
    DebugDrawBatch batch_;
    RgvcOverlay3dScratch scratch_;
};

// Each face is a frame quad and an inner quad (4 triangles), back to front:
// the Manhattan distance of its voxel from the eye's never grows.
TEST_F(RgvcView3dTest, BoxesAreTheExposedFacesFacingTheEyeBackToFront) {
    ASSERT_NO_FATAL_FAILURE(open("hidden-movers-3d.json", 60));
    const RegularGrid& g = snap_->grid;
    const glm::dvec3 eye(-40.0, 90.0, -70.0);  // outside the grid, above its near corner
    const glm::ivec3 e = rgvcVoxelOfPoint(g, eye);
    const auto& fill = draw(only({RgvcLayer::Occluder}), eye).layer(DrawSpace::World).fill;
    // The faces by brute force.
    int64_t faces = 0;
    const glm::ivec3 res = g.resolution;
    for (int z = 0; z < res.z; ++z)
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                if (!snap_->occluder->get(x, y, z)) continue;
                const glm::ivec3 v(x, y, z);
                for (int a = 0; a < 3; ++a) {
                    if (v[a] == e[a]) continue;
                    glm::ivec3 n = v;
                    n[a] += e[a] > v[a] ? 1 : -1;
                    if (g.inside(n) && snap_->occluder->get(n.x, n.y, n.z)) continue;
                    ++faces;
                }
            }
    ASSERT_GT(faces, 100);
    ASSERT_EQ(int64_t(fill.size()), faces * 12) << "4 triangles a face";
    int64_t last = INT64_MAX;
    for (size_t f = 0; f < fill.size(); f += 12) {
        EXPECT_TRUE(test::sameColor(fill[f].color, RgvcVoxelBoxes::kFrameSwatch));
        EXPECT_TRUE(test::sameColor(fill[f + 6].color, Swatch::NearBlack));
        glm::dvec3 c(0.0);
        for (size_t k = 0; k < 6; ++k) c += glm::dvec3(fill[f + k].position) / 6.0;
        // The face's axis: the one its corners share; its voxel lies away from the eye.
        int axis = 0;
        for (int a = 0; a < 3; ++a)
            if (std::abs(double(fill[f].position[a]) - double(fill[f + 1].position[a])) < 1e-6 &&
                std::abs(double(fill[f].position[a]) - double(fill[f + 2].position[a])) < 1e-6)
                axis = a;
        glm::dvec3 inward(0.0);
        inward[axis] = eye[axis] > c[axis] ? -1e-3 : 1e-3;
        const glm::ivec3 v = rgvcVoxelOfPoint(g, c + inward);
        EXPECT_TRUE(snap_->occluder->get(v.x, v.y, v.z));
        const int64_t key = std::abs(v.x - e.x) + std::abs(v.y - e.y) + std::abs(v.z - e.z);
        EXPECT_LE(key, last);
        last = key;
    }
}

TEST_F(RgvcView3dTest, BoxesAtALayerDrawOnlyTheVoxelsInHByThen) {
    ASSERT_NO_FATAL_FAILURE(open("hidden-movers-3d.json", 60));
    // The layer by which half the frame's H had been marked.
    std::vector<int32_t> entered;
    for (const int32_t l : snap_->h_layer)
        if (l != kRgvcNoLayer) entered.push_back(l);
    ASSERT_FALSE(entered.empty());
    std::sort(entered.begin(), entered.end());
    const int64_t at = entered[entered.size() / 2];
    ASSERT_LT(at, entered.back());
    const glm::dvec3 eye(150.0, 80.0, 160.0);
    const auto& fill = draw(only({RgvcLayer::Occlusion}, at), eye).layer(DrawSpace::World).fill;
    ASSERT_FALSE(fill.empty());
    for (size_t f = 0; f < fill.size(); f += 12) {
        glm::dvec3 c(0.0);
        for (size_t k = 6; k < 12; ++k) c += glm::dvec3(fill[f + k].position) / 6.0;
        // Step into the voxel: away from the eye, along the face's normal.
        glm::ivec3 best{0};
        bool found = false;
        for (int a = 0; a < 3 && !found; ++a)
            for (const double s : {-1e-3, 1e-3}) {
                glm::dvec3 p = c;
                p[a] += s;
                const glm::ivec3 v = rgvcVoxelOfPoint(snap_->grid, p);
                if (!snap_->grid.inside(v) || !snap_->occlusion->get(v.x, v.y, v.z)) continue;
                if (snap_->h_layer[linear(v.x, v.y, v.z)] <= at) best = v, found = true;
            }
        EXPECT_TRUE(found) << "a face of a voxel not in H at layer " << at;
    }
    // Fewer faces than at the end of the frame: H grew after the layer.
    const size_t mid_faces = fill.size();
    EXPECT_LT(mid_faces,
              draw(only({RgvcLayer::Occlusion}), eye).layer(DrawSpace::World).fill.size());
}

TEST_F(RgvcView3dTest, TheSliceAtALayerShowsHAsItStoodThen) {
    ASSERT_NO_FATAL_FAILURE(open("hidden-movers-3d.json", 60));
    const int y = int(std::clamp<int64_t>(viewerVoxel().y, 0, snap_->grid.resolution.y - 1));
    size_t before = 0;
    for (const int64_t at : {snap_->first_layer + 3, (snap_->first_layer + snap_->last_layer) / 2,
                             snap_->last_layer}) {
        const test::VoxelSet want = plane(
            1, y, [&](int x, int vy, int z) { return snap_->h_layer[linear(x, vy, z)] <= at; });
        EXPECT_EQ(sliceOf(slice(only({RgvcLayer::Occlusion}, at), 1, y), Swatch::LightGrey), want)
            << "layer " << at;
        EXPECT_GE(want.size(), before);
        before = want.size();
    }
    EXPECT_LT(sliceOf(slice(only({RgvcLayer::Occlusion}, snap_->first_layer + 3), 1, y),
                      Swatch::LightGrey)
                  .size(),
              before);
}

TEST_F(RgvcView3dTest, TheSliceShowsEachMatrixOfItsPlaneAlongEveryAxis) {
    ASSERT_NO_FATAL_FAILURE(open("hidden-movers-3d.json", 60));
    const int64_t at = (snap_->first_layer + snap_->last_layer) / 2;
    const glm::i64vec3 e = viewerVoxel();
    for (int axis = 0; axis < 3; ++axis) {
        const int n = int(std::clamp<int64_t>(e[axis] + 3, 0, snap_->grid.resolution[axis] - 1));
        const test::VoxelSet o_want =
            plane(axis, n, [&](int x, int y, int z) { return snap_->occluder->get(x, y, z); });
        EXPECT_EQ(sliceOf(slice(only({RgvcLayer::Occluder}), axis, n), Swatch::NearBlack), o_want)
            << "axis " << axis;
        // The traversal up to the layer: the layer's voxels solid, the earlier ones tiles.
        const test::VoxelSet visited_want = plane(axis, n, [&](int x, int y, int z) {
            for (const RgvcVisit& v : snap_->visits)
                if (v.voxel == glm::ivec2(x, y) && v.z == z) return v.layer <= at;
            return false;
        });
        EXPECT_FALSE(visited_want.empty()) << "axis " << axis;
        EXPECT_EQ(sliceOf(slice(only({RgvcLayer::Visited, RgvcLayer::CurrentLayer}, at), axis, n),
                          Swatch::BluishGreen),
                  visited_want)
            << "axis " << axis;
    }
}

// T in the slice: the voxels where a TBV id is in two of Txy, Txz and Tyz,
// which are exactly the surfaces of the TBVs' boxes (filled: the boxes); one
// of the three would be many more.
TEST_F(RgvcView3dTest, TheSliceShowsTbvsByTheTwoOfThreeTest) {
    ASSERT_NO_FATAL_FAILURE(open("hidden-movers-3d.json", 60));
    const RgvcTbvView* tbv = nullptr;
    for (const RgvcTbvView& t : snap_->tbv_list)
        if (!t.edge && t.cells.hi.z > t.cells.lo.z + 2) tbv = &t;
    ASSERT_NE(tbv, nullptr);
    const int z = (tbv->cells.lo.z + tbv->cells.hi.z) / 2;
    const test::VoxelSet want = plane(2, z, [&](int x, int y, int vz) {
        for (const RgvcTbvView& t : snap_->tbv_list) {
            if (t.edge) continue;
            const glm::i64vec3 v(x, y, vz);
            if (t.filled ? t.cells.contains(v) : onTbvBoxSurface(t.cells, v)) return true;
        }
        return false;
    });
    const test::VoxelSet one_of_three = plane(2, z, [&](int x, int y, int vz) {
        return !snap_->tbvs->empty(x, y) || !snap_->tbvs_xz->empty(x, vz) ||
               !snap_->tbvs_yz->empty(y, vz);
    });
    ASSERT_FALSE(want.empty());
    EXPECT_GT(one_of_three.size(), want.size());
    EXPECT_EQ(sliceOf(slice(only({RgvcLayer::Tbv}), 2, z), Swatch::ReddishPurple), want);
}

TEST_F(RgvcView3dTest, APickedOccludersCapIsItsShellFacesBlockingVoxels) {
    ASSERT_NO_FATAL_FAILURE(open("hidden-movers-3d.json", 60));
    ASSERT_FALSE(snap_->occluders3d.empty());
    // An occluder of a layer after the first, with cells of its own.
    int k = -1;
    for (size_t i = 0; i < snap_->occluders3d.size(); ++i)
        if (snap_->occluders3d[i].cells_covered > 0) k = int(i);
    ASSERT_GE(k, 0);
    const RgvcOccluder3d& occ = snap_->occluders3d[size_t(k)];
    RgvcCap3d cap;
    buildRgvcCap3d(*snap_, session_.scene().camera.near, k, cap);
    ASSERT_TRUE(cap.valid);
    // The face: the occluder's voxel is at chess distance on that axis, and its pixel is filled.
    const glm::i64vec3 e = viewerVoxel();
    EXPECT_EQ(std::llabs(occ.voxel[cap.axis] - e[cap.axis]), occ.layer);
    // On the face's side away from the eye.
    const bool beyond = occ.voxel[cap.axis] > e[cap.axis];
    EXPECT_DOUBLE_EQ(cap.plane,
                     snap_->grid.world.min[cap.axis] + (occ.voxel[cap.axis] + (beyond ? 1 : 0)) *
                                                           snap_->grid.voxelSize()[cap.axis]);
    const int u = occ.voxel[cap.b] - cap.b0, w = occ.voxel[cap.c] - cap.c0;
    ASSERT_TRUE(u >= 0 && w >= 0 && u < cap.width && w < cap.height);
    EXPECT_TRUE(cap.filled[size_t(w) * size_t(cap.width) + size_t(u)]);
    // The loops bound exactly the blocking voxels: H after the layer, or O beyond near.
    int64_t blocking = 0, area = 0;
    for (int j = 0; j < cap.height; ++j)
        for (int i = 0; i < cap.width; ++i) {
            glm::ivec3 v;
            v[cap.axis] = cap.fixed;
            v[cap.b] = cap.b0 + i;
            v[cap.c] = cap.c0 + j;
            const size_t at = linear(v.x, v.y, v.z);
            bool blocks = snap_->occlusion->get(v.x, v.y, v.z) && snap_->h_layer[at] <= occ.layer;
            if (!blocks && snap_->occluder->get(v.x, v.y, v.z) &&
                (snap_->o_layer[at] == kRgvcNoLayer || snap_->o_layer[at] <= occ.layer)) {
                const Aabb box = snap_->grid.voxelBounds(v);
                double depth = 1e300;
                for (int c = 0; c < 8; ++c)
                    depth =
                        std::min(depth, glm::dot(box.corner(c) - snap_->viewpoint, snap_->forward));
                blocks = depth >= session_.scene().camera.near;
            }
            blocking += blocks;
            EXPECT_EQ(bool(cap.filled[size_t(j) * size_t(cap.width) + size_t(i)]), blocks);
        }
    for (const BitmapLoop& loop : cap.vectorizer.loops())
        area += signedDoubleArea(cap.vectorizer.corners(loop), loop.count);
    EXPECT_EQ(cap.blocking, blocking);
    EXPECT_EQ(area, 2 * blocking);
    // The direction-map cells of its pass: as many as it says it covered.
    EXPECT_EQ(int64_t(cap.cells.size()), occ.cells_covered);

    // Drawn: the loops on the face's plane (heavy), a ray from the eye through
    // each corner (hairlines from the viewpoint). The polygon alone: the picked
    // voxel's boxes share its colour (picked things).
    RgvcViewState view = only({RgvcLayer::Polygon});
    view.occluder = k;
    const DebugDrawBatch& batch = draw(view, {150.0, 80.0, 160.0});
    int64_t on_plane = 0, rays = 0, corners = 0;
    int64_t drawn_corners = 0;
    for (const BitmapLoop& loop : cap.vectorizer.loops()) {
        drawn_corners += loop.count;
        corners += loop.outer == cap.component ? loop.count : 0;
    }
    for (const DebugDrawBatch::LineSet& set : batch.layer(DrawSpace::World).lines)
        for (size_t i = 0; i + 1 < set.vertices.size(); i += 2) {
            const auto& a = set.vertices[i];
            const auto& b = set.vertices[i + 1];
            if (!test::sameColor(a.color, rgvcLayerSwatch(RgvcLayer::Polygon))) continue;
            if (set.width == kHeavyLine)
                on_plane += std::abs(a.position[cap.axis] - cap.plane) < 1e-3 &&
                            std::abs(b.position[cap.axis] - cap.plane) < 1e-3;
            if (set.width == kHairline &&
                glm::length(glm::dvec3(a.position) - snap_->viewpoint) < 1e-3)
                ++rays;
        }
    EXPECT_EQ(on_plane, drawn_corners) << "one edge per corner, each on the plane";
    const int64_t every =
        std::max<int64_t>(1, (corners + kRgvcMaxExtrusionRays - 1) / kRgvcMaxExtrusionRays);
    EXPECT_EQ(rays, (corners + every - 1) / every)
        << "a ray through every corner of the occluder's polygon, or every k-th";
    // That polygon holds the occluder's voxel.
    ASSERT_GE(cap.component, 0);
    const BitmapLoop& outer = cap.vectorizer.loops()[size_t(cap.component)];
    EXPECT_FALSE(outer.hole);
    EXPECT_TRUE(rgvcLoopHolds(cap.vectorizer.corners(outer), outer.count, u + 0.5, w + 0.5));
}

TEST_F(RgvcView3dTest, TheVoxelUnderARayIsTheFirstBoxAlongIt) {
    ASSERT_NO_FATAL_FAILURE(open("hidden-movers-3d.json", 60));
    RgvcViewState view;  // O, H, T and the layer's voxels
    RgvcFrameIndex& index = scratch_.index;
    const int64_t at = rgvcShownLayer(*snap_, view.layer);
    index.update(*snap_, at);
    // Off the voxel lattice, so that no ray grazes a voxel for less than the march's step.
    const glm::dvec3 origin(151.37, 79.71, 158.93);
    int checked = 0;
    for (int k = 0; k < 40; ++k) {
        // Rays towards points spread over the grid.
        const glm::dvec3 target(5.0 + 2.3 * k, 3.0 + 1.3 * k, 90.0 - 2.1 * k);
        const glm::dvec3 dir = glm::normalize(target - origin);
        glm::ivec3 picked;
        const bool hit = pickRgvcVoxel3d(*snap_, view, index, at, origin, dir, picked);
        // March in small steps for the first voxel drawn as a box.
        glm::ivec3 want{-1};
        for (double t = 0.0; t < 400.0; t += 0.01) {
            const glm::ivec3 v = rgvcVoxelOfPoint(snap_->grid, origin + dir * t);
            if (snap_->grid.inside(v) &&
                rgvcBoxKindAt(*snap_, view, index, at, v.x, v.y, v.z) != RgvcBoxKind::None) {
                want = v;
                break;
            }
        }
        if (want.x < 0) continue;
        ++checked;
        EXPECT_TRUE(hit);
        EXPECT_EQ(picked, want) << "ray " << k;
    }
    EXPECT_GT(checked, 10);
}

// An occluded voxel, looked at in a slice: the panel names the occluder whose
// pass hid it (h_cause), its button picks it, and a click on the voxel in the
// view picks it too.
TEST_F(RgvcView3dTest, WhyNamesTheOccluderAndAClickOnTheVoxelPicksIt) {
    ASSERT_NO_FATAL_FAILURE(open("hidden-movers-3d.json", 60));
    glm::ivec3 voxel{-1};
    int32_t cause = -1;
    const glm::ivec3 res = snap_->grid.resolution;
    for (int z = 0; z < res.z && cause < 0; ++z)
        for (int y = 0; y < res.y && cause < 0; ++y)
            for (int x = 0; x < res.x && cause < 0; ++x) {
                const int32_t c = snap_->h_cause[linear(x, y, z)];
                if (c > 0 && snap_->occluders3d[size_t(c)].voxel != glm::ivec3(x, y, z))
                    voxel = {x, y, z}, cause = c;
            }
    ASSERT_GE(cause, 0);
    RgvcVoxelInfo info;
    describeRgvcVoxel(*snap_, session_.scene(), voxel, info);
    EXPECT_TRUE(info.h);
    EXPECT_EQ(info.cause, cause);
    test::PanelProbe probe;
    RgvcViewState view;
    const auto panel = [&] { drawRgvcVoxelInfo(*snap_, view, &info, true); };
    const std::string text = probe.text(panel);
    char name[64];
    std::snprintf(name, sizeof name, "voxel (%d, %d, %d)", voxel.x, voxel.y, voxel.z);
    EXPECT_NE(text.find(name), std::string::npos) << text;
    EXPECT_NE(text.find("occluder " + std::to_string(cause)), std::string::npos) << text;
    EXPECT_TRUE(probe.clickUntil(panel, [&] { return view.occluder == cause; }));

    // In the window: a slice through the voxel, a click straight down on it.
    std::unique_ptr<FamilyView> family = familyViewOfAlgorithm("rgvc")->make();
    KnobValues flags;
    flags.set("rgvc-slice", voxel.y);
    flags.set("rgvc-slice-axis", 1);
    std::string error;
    ASSERT_TRUE(family->applyFlags(flags, session_.scene(), error)) << error;
    FamilyViewContext context;
    context.scene = &session_.scene();
    context.snapshot = snap_;
    ViewPointer pointer;
    pointer.over_view = true;
    pointer.clicked = true;
    pointer.origin = centre(voxel) + glm::dvec3(0.0, 100.0, 0.0);
    pointer.direction = {0.0, -1.0, 0.0};
    family->pointer(context, pointer);
    pointer.over_view = false;
    family->pointer(context, pointer);
    FamilyAction action;
    const std::string panel_text = probe.text([&] { family->drawPanel(context, action); });
    const glm::ivec3 o = snap_->occluders3d[size_t(cause)].voxel;
    std::snprintf(name, sizeof name, "is voxel (%d, %d, %d), met at chess layer", o.x, o.y, o.z);
    EXPECT_NE(panel_text.find(name), std::string::npos) << panel_text;
    EXPECT_NE(panel_text.find("direction map"), std::string::npos) << "3D memory rows";
}

TEST_F(RgvcView3dTest, ACulledObjectListsTheVoxelsThatHidIt) {
    ASSERT_NO_FATAL_FAILURE(open("walkthrough-3d.json", 40));
    RgvcFrameIndex index;
    index.update(*snap_, rgvcShownLayer(*snap_, -1));
    RgvcObjectVoxels object;
    int picked = -1;
    const std::vector<ObjectState>& states = session_.states();
    for (size_t i = 0; i < states.size() && picked < 0; ++i) {
        if (states[i] != ObjectState::Culled) continue;
        describeRgvcObject(*snap_, session_.scene(), index, int(i), object);
        if (object.occluded > 0 && object.unreached > 0 && object.open == 0) picked = int(i);
    }
    ASSERT_GE(picked, 0);
    const IdListMatrix* list = snap_->identifiers_static;
    int64_t in_i = 0;
    const glm::ivec3 res = snap_->grid.resolution;
    for (int z = 0; z < res.z; ++z)
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) in_i += list->contains(x, list->row(y, z), picked);
    EXPECT_EQ(int64_t(object.voxels.size()), in_i);
    for (const RgvcObjectVoxel& v : object.voxels) {
        const RgvcVisit* visit = nullptr;
        for (const RgvcVisit& s : snap_->visits)
            if (s.voxel == glm::ivec2(v.voxel.x, v.voxel.y) && s.z == v.voxel.z) visit = &s;
        EXPECT_EQ(v.layer >= 0, visit != nullptr);
        if (visit) {
            EXPECT_EQ(v.occluded, visit->occluded);
        }
    }
    // Open first, then occluded, then not reached.
    EXPECT_GE(object.voxels.back().layer, -1);
    EXPECT_EQ(object.voxels.back().layer, -1);
    test::PanelProbe probe;
    const std::string text = probe.text([&] {
        RgvcViewState view;
        drawRgvcObjectVoxels(*snap_, view, &object, ObjectState::Culled);
    });
    EXPECT_NE(text.find("not reached"), std::string::npos) << text;
    EXPECT_NE(text.find("occluded by"), std::string::npos) << text;
}

}  // namespace
}  // namespace gridcull
