// Occluder extension (s4.3) and occlusion computation (s4.4) of rgvc:
//  - the four extension steps on hand-made patterns, in the convex (L) and the
//    staircase variant (a concave occluder: the staircase follows it where the L
//    stops), and the staircase's occlusion polygons;
//  - on random scenes, with either variant, every extended occluder covers only
//    opaque or occluded voxels, every occluded voxel lies wholly inside an
//    occlusion polygon (its four corners, tested exactly in double), each
//    polygon lies in the shadow of its occluder (sampled: the segment from the
//    viewpoint to any point of the polygon crosses the occluder), and (brute
//    force) every occluded voxel is hidden by opaque voxels: the segment from
//    the viewpoint to each of nine points of the voxel meets a voxel of O.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "culling/rgvc/rgvc_culler.h"
#include "culling/rgvc/rgvc_occlusion.h"
#include "culling/scene/seeded_random.h"
#include "grid/bit_matrix.h"
#include "grid/conservative_raster.h"
#include "tests/culling/rgvc/rgvc_random_scene.h"

namespace gridcull {
namespace {

using Blocks = std::set<std::pair<int, int>>;

RgvcExtendedOccluder extend(const Blocks& blocks, glm::ivec2 initial, glm::i64vec2 viewer,
                            RgvcExtension variant = RgvcExtension::ConvexL) {
    return extendOccluder(initial, viewer, 20, 20, variant, [&](int x, int y) {
        return blocks.count({x, y}) > 0;
    });
}

RegularGrid grid20() {
    RegularGrid grid;
    grid.dimensions = 2;
    grid.world = {{0, 0, 0}, {20, 20, 0}};
    grid.resolution = {20, 20, 1};
    return grid;
}

TEST(RgvcExtension, FourStepsTowardsThenAwayFromTheViewer) {
    // Viewer at the lower left of the initial voxel (5, 5): towards is -x, -y.
    // A row from x = 2 to 9 at y = 5 and a column below x = 2 down to y = 1.
    Blocks blocks;
    for (int x = 2; x <= 9; ++x) blocks.insert({x, 5});
    for (int y = 1; y <= 5; ++y) blocks.insert({2, y});
    blocks.insert({5, 6});  // above the initial voxel: step 3 must not take it
    const RgvcExtendedOccluder occ = extend(blocks, {5, 5}, {0, 0});
    EXPECT_EQ(occ.toward, glm::ivec2(-1, -1));
    EXPECT_EQ(occ.steps[0].count, 3);  // (1) left to x = 2
    // (2) from the leftmost voxel, away from the viewer in y (+y): nothing there.
    EXPECT_EQ(occ.steps[1].from, glm::ivec2(2, 5));
    EXPECT_EQ(occ.steps[1].direction, glm::ivec2(0, 1));
    EXPECT_EQ(occ.steps[1].count, 0);
    EXPECT_FALSE(occ.steps[2].run);  // (3) skipped: step 1 extended
    EXPECT_EQ(occ.steps[3].from, glm::ivec2(5, 5));
    EXPECT_EQ(occ.steps[3].count, 4);  // (4) right to x = 9
    ASSERT_EQ(occ.part_count, 1);
    EXPECT_EQ(occ.parts[0].corner, glm::ivec2(2, 5));
    EXPECT_EQ(occ.parts[0].leg_x, 7);
    EXPECT_EQ(occ.parts[0].leg_y, 0);
    for (int x = 2; x <= 9; ++x) EXPECT_TRUE(occ.covers({x, 5}));
    EXPECT_FALSE(occ.covers({2, 4}));  // towards the viewer: not part of a convex L
}

TEST(RgvcExtension, StepThreeRunsWhenStepOneFindsNothing) {
    // Viewer to the lower right of (5, 5): towards is +x, -y. A column x = 5 from
    // y = 2 to 8 and a row from (5, 2) going away (-x) to x = 1.
    Blocks blocks;
    for (int y = 2; y <= 8; ++y) blocks.insert({5, y});
    for (int x = 1; x <= 5; ++x) blocks.insert({x, 2});
    const RgvcExtendedOccluder occ = extend(blocks, {5, 5}, {12, 0});
    EXPECT_EQ(occ.toward, glm::ivec2(1, -1));
    EXPECT_EQ(occ.steps[0].count, 0);  // (1) +x: nothing
    EXPECT_EQ(occ.steps[1].count, 3);  // (2) away in y (+y) to y = 8
    EXPECT_TRUE(occ.steps[2].run);
    EXPECT_EQ(occ.steps[2].count, 3);  // (3) towards in y (-y) to y = 2
    EXPECT_EQ(occ.steps[3].from, glm::ivec2(5, 2));
    EXPECT_EQ(occ.steps[3].count, 4);  // (4) away in x (-x) to x = 1
    ASSERT_EQ(occ.part_count, 1);
    EXPECT_EQ(occ.parts[0].corner, glm::ivec2(5, 2));
    EXPECT_EQ(occ.parts[0].leg_x, 4);
    EXPECT_EQ(occ.parts[0].leg_y, 6);
    EXPECT_TRUE(occ.covers({1, 2}));
    EXPECT_TRUE(occ.covers({5, 8}));
    EXPECT_FALSE(occ.covers({4, 3}));
}

TEST(RgvcExtension, ViewerOnTheRowExtendsTheColumnBothWays) {
    Blocks blocks;
    for (int y = 0; y <= 12; ++y) blocks.insert({8, y});
    const RgvcExtendedOccluder occ = extend(blocks, {8, 6}, {1, 6});
    EXPECT_TRUE(occ.primary_is_y);
    EXPECT_EQ(occ.parts[0].leg_y, 12);  // the whole column, 0 to 12
    EXPECT_EQ(occ.parts[0].leg_x, 0);
}

// The staircase variant on an occluder shaped like one: viewer at the lower left
// of (10, 10), towards is -x, -y. A row y = 10 from x = 6 to 10 with a column
// x = 6 above it up to y = 14, and a column x = 10 from y = 10 down to 6 with a
// row y = 6 from x = 10 to 14: a zig-zag whose concave corner at (10, 10) faces
// the viewer.
Blocks staircaseBlocks() {
    Blocks blocks;
    for (int x = 6; x <= 10; ++x) blocks.insert({x, 10});
    for (int y = 10; y <= 14; ++y) blocks.insert({6, y});
    for (int y = 6; y <= 10; ++y) blocks.insert({10, y});
    for (int x = 10; x <= 14; ++x) blocks.insert({x, 6});
    return blocks;
}

TEST(RgvcExtension, ConvexLStopsAtAConcaveCorner) {
    const RgvcExtendedOccluder occ = extend(staircaseBlocks(), {10, 10}, {0, 0});
    EXPECT_EQ(occ.steps[0].count, 4);  // (1) left to x = 6
    EXPECT_EQ(occ.steps[1].count, 4);  // (2) up to y = 14
    EXPECT_FALSE(occ.steps[2].run);    // (3) skipped: step 1 extended
    EXPECT_EQ(occ.steps[3].from, glm::ivec2(10, 10));
    EXPECT_EQ(occ.steps[3].count, 0);  // (4) nothing right of (10, 10)
    ASSERT_EQ(occ.part_count, 1);
    EXPECT_FALSE(occ.isStaircase());
    EXPECT_FALSE(occ.covers({10, 8}));  // the lower half of the zig-zag is left out
    EXPECT_FALSE(occ.covers({14, 6}));
    EXPECT_EQ(occ.voxelCount(), 9);
}

TEST(RgvcExtension, StaircaseFollowsAConcaveOccluderWhereTheLStops) {
    const RgvcExtendedOccluder occ =
        extend(staircaseBlocks(), {10, 10}, {0, 0}, RgvcExtension::Staircase);
    EXPECT_EQ(occ.variant, RgvcExtension::Staircase);
    EXPECT_EQ(occ.steps[0].count, 4);  // (1) left to x = 6
    EXPECT_EQ(occ.steps[1].from, glm::ivec2(6, 10));
    EXPECT_EQ(occ.steps[1].count, 4);  // (2) up (away) to y = 14
    EXPECT_TRUE(occ.steps[2].run);     // (3) always in the staircase variant
    EXPECT_EQ(occ.steps[2].direction, glm::ivec2(0, -1));
    EXPECT_EQ(occ.steps[2].count, 4);                 // down (towards) to y = 6
    EXPECT_EQ(occ.steps[3].from, glm::ivec2(10, 6));  // (4) from the end of step 3
    EXPECT_EQ(occ.steps[3].direction, glm::ivec2(1, 0));
    EXPECT_EQ(occ.steps[3].count, 4);  // right (away) to x = 14
    ASSERT_EQ(occ.part_count, 2);
    EXPECT_TRUE(occ.isStaircase());
    EXPECT_EQ(occ.parts[0].corner, glm::ivec2(6, 10));
    EXPECT_EQ(occ.parts[0].leg_x, 4);
    EXPECT_EQ(occ.parts[0].leg_y, 4);
    EXPECT_EQ(occ.parts[1].corner, glm::ivec2(10, 6));
    EXPECT_EQ(occ.parts[1].leg_x, 4);
    EXPECT_EQ(occ.parts[1].leg_y, 4);
    // Exactly the zig-zag's 17 voxels.
    const Blocks blocks = staircaseBlocks();
    EXPECT_EQ(occ.voxelCount(), int(blocks.size()));
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x)
            EXPECT_EQ(occ.covers({x, y}), blocks.count({x, y}) > 0) << x << "," << y;
}

TEST(RgvcExtension, StaircaseIsTheLWhenStepOneOrThreeAddsNothing) {
    // The convex pattern of FourStepsTowardsThenAwayFromTheViewer plus nothing
    // below the initial voxel: step 3 runs but adds nothing, one L.
    Blocks blocks;
    for (int x = 2; x <= 9; ++x) blocks.insert({x, 5});
    for (int y = 6; y <= 9; ++y) blocks.insert({2, y});
    const RgvcExtendedOccluder l = extend(blocks, {5, 5}, {0, 0});
    const RgvcExtendedOccluder st = extend(blocks, {5, 5}, {0, 0}, RgvcExtension::Staircase);
    EXPECT_TRUE(st.steps[2].run);
    EXPECT_EQ(st.steps[2].count, 0);
    ASSERT_EQ(st.part_count, 1);
    EXPECT_EQ(st.parts[0].corner, l.parts[0].corner);
    EXPECT_EQ(st.parts[0].leg_x, l.parts[0].leg_x);
    EXPECT_EQ(st.parts[0].leg_y, l.parts[0].leg_y);
    EXPECT_EQ(st.parts[0].leg_x, 7);
    EXPECT_EQ(st.parts[0].leg_y, 4);
    // Step 1 adds nothing: step 3 runs in both variants and they agree.
    const RgvcExtendedOccluder l2 = extend(blocks, {9, 5}, {12, 0});
    const RgvcExtendedOccluder st2 = extend(blocks, {9, 5}, {12, 0}, RgvcExtension::Staircase);
    ASSERT_EQ(st2.part_count, 1);
    EXPECT_EQ(st2.parts[0].corner, l2.parts[0].corner);
    EXPECT_EQ(st2.parts[0].leg_x, l2.parts[0].leg_x);
    EXPECT_EQ(st2.parts[0].leg_y, l2.parts[0].leg_y);
}

// Is the segment from a to b blocked by one of `blocks` (unit voxels of grid20)?
bool blockedByBlocks(const Blocks& blocks, glm::dvec2 a, glm::dvec2 b) {
    for (const auto& [x, y] : blocks)
        if (segmentMeetsRect({a.x, a.y, 0}, {b.x, b.y, 0}, {x, y, 0}, {x + 1, y + 1, 0}))
            return true;
    return false;
}

// The voxels of grid20 wholly inside one of the polygons (the culler's
// rasterization), as (x, y).
Blocks marked(const RgvcOcclusionPolygons& polys, int count) {
    const RegularGrid grid = grid20();
    Blocks out;
    for (int p = 0; p < count; ++p)
        rasterizeOcclusionPolygon(polys[size_t(p)], grid, 0, 19, 0, 19, [&](int y, int x0, int x1) {
            for (int x = x0; x <= x1; ++x) out.insert({x, y});
        });
    return out;
}

TEST(RgvcOcclusionPolygon, StaircasePolygonsCoverItsShadowAndOnlyThat) {
    const RegularGrid grid = grid20();
    const Blocks blocks = staircaseBlocks();
    const glm::dvec2 apex{1.5, 0.5};
    const RgvcExtendedOccluder l = extend(blocks, {10, 10}, {1, 0});
    const RgvcExtendedOccluder st = extend(blocks, {10, 10}, {1, 0}, RgvcExtension::Staircase);
    ASSERT_TRUE(st.isStaircase());
    RgvcOcclusionPolygons l_polys, st_polys;
    const int l_count = occlusionPolygons(l, grid, apex, l_polys);
    const int st_count = occlusionPolygons(st, grid, apex, st_polys);
    EXPECT_EQ(l_count, 1);
    // The viewpoint is in the quadrant both Ls' corners face: one polygon each.
    ASSERT_EQ(st_count, 2);
    EXPECT_EQ(st_polys[0].plane_count, 4);
    EXPECT_EQ(st_polys[1].plane_count, 4);
    // Behind the lower row, hidden by the staircase only.
    EXPECT_FALSE(l_polys[0].containsPoint({13.5, 8.0}, 0.0));
    EXPECT_TRUE(st_polys[1].containsPoint({13.5, 8.0}, 0.0));
    EXPECT_TRUE(blockedByBlocks(blocks, apex, {13.5, 8.0}));
    // In front of the concave corner: seen.
    EXPECT_FALSE(st_polys[0].containsPoint({8.5, 8.5}, 0.0));
    EXPECT_FALSE(st_polys[1].containsPoint({8.5, 8.5}, 0.0));
    // Brute force on the voxels: every marked voxel is hidden (nine points each),
    // and the staircase marks every voxel the L marks and more.
    const Blocks l_marked = marked(l_polys, l_count);
    const Blocks st_marked = marked(st_polys, st_count);
    for (const auto& [x, y] : st_marked)
        for (int i = 0; i <= 2; ++i)
            for (int j = 0; j <= 2; ++j)
                ASSERT_TRUE(blockedByBlocks(blocks, apex, {x + 0.5 * i, y + 0.5 * j}))
                    << "voxel " << x << "," << y << " marked but not hidden";
    for (const auto& v : l_marked) EXPECT_TRUE(st_marked.count(v)) << v.first << "," << v.second;
    EXPECT_GT(st_marked.size(), l_marked.size() + 10);
    EXPECT_TRUE(st_marked.count({13, 8}));
    // The voxel on the ray through the concave corner (10, 10) and the apex: the
    // Ls' polygons overlap there, so it is marked (a partition of the hidden
    // region split along that ray would lose it).
    EXPECT_TRUE(st_marked.count({13, 13}));
}

TEST(RgvcOcclusionPolygon, CornerPolygonIsTheShadowOfTheL) {
    const RegularGrid grid = grid20();
    Blocks blocks;
    for (int x = 5; x <= 12; ++x) blocks.insert({x, 8});
    for (int y = 8; y <= 15; ++y) blocks.insert({5, y});
    // Viewer below-left of the corner (5, 8): both outer edges face it.
    const RgvcExtendedOccluder occ = extend(blocks, {5, 8}, {1, 2});
    EXPECT_EQ(occ.parts[0].corner, glm::ivec2(5, 8));
    RgvcOcclusionPolygons polys;
    ASSERT_EQ(occlusionPolygons(occ, grid, {1.5, 2.5}, polys), 1);
    EXPECT_EQ(polys[0].plane_count, 4);
    EXPECT_TRUE(polys[0].containsPoint({10.0, 12.0}, 0.0));  // inside the L's elbow
    EXPECT_FALSE(polys[0].containsPoint({3.0, 12.0}, 0.0));  // beside the column
    EXPECT_FALSE(polys[0].containsPoint({10.0, 6.0}, 0.0));  // in front of the row
}

// Does the segment from a to b meet the occluder's voxels?
bool segmentMeetsOccluder(const RgvcExtendedOccluder& occ, const RegularGrid& grid, glm::dvec3 a,
                          glm::dvec3 b) {
    for (int i = 0; i < occ.part_count; ++i) {
        for (const glm::ivec2 end : {occ.legXEnd(i), occ.legYEnd(i)}) {
            const glm::ivec2 corner = occ.parts[size_t(i)].corner;
            const glm::ivec2 lo = glm::min(corner, end), hi = glm::max(corner, end);
            const Aabb box{grid.voxelBounds({lo.x, lo.y, 0}).min,
                           grid.voxelBounds({hi.x, hi.y, 0}).max};
            if (segmentMeetsRect(a, b, box.min, box.max)) return true;
        }
    }
    return false;
}

// Brute force: does the closed segment from a to b meet a voxel of O? Each grid
// column the segment crosses holds it over a range of rows; every opaque voxel
// there is tested exactly.
bool segmentMeetsOpaque(const RegularGrid& grid, const BitMatrix& o, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec3 d = grid.voxelSize();
    const glm::dvec3& w = grid.world.min;
    const int res_x = grid.resolution.x, res_y = grid.resolution.y;
    constexpr double kEdge = 1e-9;  // voxels: a segment on a grid line touches both sides
    const int c0 = std::max(0, int(std::floor((std::min(a.x, b.x) - w.x) / d.x - kEdge)));
    const int c1 = std::min(res_x - 1, int(std::floor((std::max(a.x, b.x) - w.x) / d.x + kEdge)));
    for (int c = c0; c <= c1; ++c) {
        double y_lo = std::min(a.y, b.y), y_hi = std::max(a.y, b.y);
        if (a.x != b.x) {
            // The segment's part with x in the column [x0, x1].
            const double x0 = w.x + c * d.x, x1 = x0 + d.x;
            double t0 = (x0 - a.x) / (b.x - a.x), t1 = (x1 - a.x) / (b.x - a.x);
            if (t0 > t1) std::swap(t0, t1);
            t0 = std::clamp(t0, 0.0, 1.0), t1 = std::clamp(t1, 0.0, 1.0);
            const double ya = a.y + t0 * (b.y - a.y), yb = a.y + t1 * (b.y - a.y);
            y_lo = std::min(ya, yb), y_hi = std::max(ya, yb);
        }
        const int r0 = std::max(0, int(std::floor((y_lo - w.y) / d.y - kEdge)));
        const int r1 = std::min(res_y - 1, int(std::floor((y_hi - w.y) / d.y + kEdge)));
        for (int r = r0; r <= r1; ++r) {
            if (!o.get(c, r)) continue;
            const Aabb box = grid.voxelBounds({c, r, 0});
            if (segmentMeetsRect({a.x, a.y, 0}, {b.x, b.y, 0}, box.min, box.max)) return true;
        }
    }
    return false;
}

struct SoundnessCounts {
    int64_t occluders = 0;
    int64_t staircases = 0;
    int64_t occluded = 0;
};

void checkSoundnessOnRandomScenes(RgvcExtension variant, SoundnessCounts& counts) {
    SeededRandom rng(77);
    RgvcOptions options;
    options.extension = int(variant);
    for (uint64_t seed = 1; seed <= 150; ++seed) {
        const Scene scene = test::rgvcRandomScene(seed);
        RgvcCuller rgvc(options);
        rgvc.setDebugCapture(true);
        rgvc.reset(scene);
        FrameResult out;
        for (int frame = 0; frame < test::kRgvcFrames; frame += 2) {
            const double t = scene.timeOfFrame(frame);
            const Camera camera = cameraAt(scene, t);
            rgvc.cull(scene, camera, t, out);
            const RgvcSnapshot& snap = rgvc.snapshot();
            SCOPED_TRACE("seed " + std::to_string(seed) + " frame " + std::to_string(frame));
            const RegularGrid& grid = snap.grid;
            const glm::dvec2 apex{camera.position.x, camera.position.y};
            const auto inGrid = [&](glm::ivec2 v) {
                return v.x >= 0 && v.y >= 0 && v.x < grid.resolution.x && v.y < grid.resolution.y;
            };
            for (const RgvcOccluderView& view : snap.occluders) {
                const RgvcExtendedOccluder& occ = view.occluder;
                ASSERT_EQ(occ.variant, variant);
                // Only opaque or occluded voxels (both matrices only grow in a frame).
                for (int k = 0; k < occ.part_count; ++k) {
                    const RgvcOccluderL& l = occ.parts[size_t(k)];
                    for (int i = 0; i <= l.leg_x; ++i) {
                        const glm::ivec2 v = l.corner + glm::ivec2(-occ.toward.x * i, 0);
                        ASSERT_TRUE(inGrid(v) && (snap.occluder->get(v.x, v.y) ||
                                                  snap.occlusion->get(v.x, v.y)));
                    }
                    for (int i = 0; i <= l.leg_y; ++i) {
                        const glm::ivec2 v = l.corner + glm::ivec2(0, -occ.toward.y * i);
                        ASSERT_TRUE(inGrid(v) && (snap.occluder->get(v.x, v.y) ||
                                                  snap.occlusion->get(v.x, v.y)));
                    }
                }
                ASSERT_TRUE(snap.occluder->get(occ.initial.x, occ.initial.y));
                ASSERT_TRUE(occ.covers(occ.initial));
                // Each polygon lies in the occluder's shadow.
                for (int p = 0; p < view.polygon_count; ++p) {
                    const RgvcOcclusionPolygon& poly = view.polygons[size_t(p)];
                    for (int s = 0; s < 50; ++s) {
                        const glm::dvec3 q{rng.uniform(grid.world.min.x, grid.world.max.x),
                                           rng.uniform(grid.world.min.y, grid.world.max.y), 0};
                        if (!poly.containsPoint({q.x, q.y}, 1e-9)) continue;
                        ASSERT_TRUE(segmentMeetsOccluder(occ, grid, camera.position, q))
                            << "point " << q.x << "," << q.y << " in the polygon but not hidden";
                    }
                }
                ++counts.occluders;
                if (occ.isStaircase()) ++counts.staircases;
            }
            for (int y = 0; y < grid.resolution.y; ++y) {
                for (int x = 0; x < grid.resolution.x; ++x) {
                    if (!snap.occlusion->get(x, y)) continue;
                    const Aabb b = grid.voxelBounds({x, y, 0});
                    // Every occluded voxel lies wholly inside some polygon: all four corners.
                    bool inside_one = false;
                    for (const RgvcOccluderView& view : snap.occluders) {
                        for (int p = 0; p < view.polygon_count && !inside_one; ++p) {
                            const RgvcOcclusionPolygon& poly = view.polygons[size_t(p)];
                            bool all = true;
                            for (int c = 0; c < 4 && all; ++c) {
                                const double px = (c & 1) ? b.max.x : b.min.x;
                                const double py = (c & 2) ? b.max.y : b.min.y;
                                for (int i = 0; i < poly.plane_count; ++i)
                                    all = all && poly.planes[size_t(i)].eval(px, py) >= 0.0;
                            }
                            inside_one = all;
                        }
                        if (inside_one) break;
                    }
                    ASSERT_TRUE(inside_one)
                        << "occluded voxel " << x << "," << y << " not wholly inside";
                    ASSERT_FALSE(b.min.x <= apex.x && apex.x <= b.max.x && b.min.y <= apex.y &&
                                 apex.y <= b.max.y);
                    // ... and is hidden by opaque voxels: corners, edge midpoints, centre.
                    for (int i = 0; i <= 2; ++i) {
                        for (int j = 0; j <= 2; ++j) {
                            const glm::dvec2 q{b.min.x + 0.5 * i * (b.max.x - b.min.x),
                                               b.min.y + 0.5 * j * (b.max.y - b.min.y)};
                            ASSERT_TRUE(segmentMeetsOpaque(grid, *snap.occluder, apex, q))
                                << "occluded voxel " << x << "," << y << ": point " << q.x << ","
                                << q.y << " seen from " << apex.x << "," << apex.y;
                        }
                    }
                    ++counts.occluded;
                }
            }
        }
    }
}

TEST(RgvcOcclusion, OccludersAndOccludedVoxelsAreSoundOnRandomScenes) {
    SoundnessCounts counts;
    checkSoundnessOnRandomScenes(RgvcExtension::ConvexL, counts);
    // The scenes must exercise the code.
    EXPECT_GT(counts.occluders, 1000);
    EXPECT_GT(counts.occluded, 10000);
    EXPECT_EQ(counts.staircases, 0);
}

TEST(RgvcOcclusion, StaircaseOccludersAndOccludedVoxelsAreSoundOnRandomScenes) {
    SoundnessCounts counts;
    checkSoundnessOnRandomScenes(RgvcExtension::Staircase, counts);
    std::printf("[ rgvc ] staircase variant: %lld occluders, %lld staircases, %lld occluded\n",
                (long long)counts.occluders, (long long)counts.staircases,
                (long long)counts.occluded);
    EXPECT_GT(counts.occluders, 1000);
    EXPECT_GT(counts.staircases, 100);
    EXPECT_GT(counts.occluded, 10000);
}

}  // namespace
}  // namespace gridcull
