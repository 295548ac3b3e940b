// Occluder extension (s4.3) and occlusion computation (s4.4) of rgvc:
//  - the four extension steps on hand-made patterns;
//  - on random scenes, every extended occluder covers only opaque or occluded
//    voxels, every occluded voxel lies wholly inside an occlusion polygon (its
//    four corners, tested exactly in double), and each polygon lies in the
//    shadow of its occluder (sampled: the segment from the viewpoint to any
//    point of the polygon crosses the occluder).
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "culling/rgvc/rgvc_culler.h"
#include "culling/rgvc/rgvc_occlusion.h"
#include "culling/scene/seeded_random.h"
#include "grid/conservative_raster.h"
#include "tests/culling/rgvc/rgvc_random_scene.h"

namespace gridcull {
namespace {

using Blocks = std::set<std::pair<int, int>>;

RgvcExtendedOccluder extend(const Blocks& blocks, glm::ivec2 initial, glm::i64vec2 viewer) {
    return extendOccluder(initial, viewer, 20, 20, [&](int x, int y) {
        return blocks.count({x, y}) > 0;
    });
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
    EXPECT_EQ(occ.corner, glm::ivec2(2, 5));
    EXPECT_EQ(occ.leg_x, 7);
    EXPECT_EQ(occ.leg_y, 0);
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
    EXPECT_EQ(occ.corner, glm::ivec2(5, 2));
    EXPECT_EQ(occ.leg_x, 4);
    EXPECT_EQ(occ.leg_y, 6);
    EXPECT_TRUE(occ.covers({1, 2}));
    EXPECT_TRUE(occ.covers({5, 8}));
    EXPECT_FALSE(occ.covers({4, 3}));
}

TEST(RgvcExtension, ViewerOnTheRowExtendsTheColumnBothWays) {
    Blocks blocks;
    for (int y = 0; y <= 12; ++y) blocks.insert({8, y});
    const RgvcExtendedOccluder occ = extend(blocks, {8, 6}, {1, 6});
    EXPECT_TRUE(occ.primary_is_y);
    EXPECT_EQ(occ.leg_y, 12);  // the whole column, 0 to 12
    EXPECT_EQ(occ.leg_x, 0);
}

TEST(RgvcOcclusionPolygon, CornerPolygonIsTheShadowOfTheL) {
    RegularGrid grid;
    grid.dimensions = 2;
    grid.world = {{0, 0, 0}, {20, 20, 0}};
    grid.resolution = {20, 20, 1};
    Blocks blocks;
    for (int x = 5; x <= 12; ++x) blocks.insert({x, 8});
    for (int y = 8; y <= 15; ++y) blocks.insert({5, y});
    // Viewer below-left of the corner (5, 8): both outer edges face it.
    const RgvcExtendedOccluder occ = extend(blocks, {5, 8}, {1, 2});
    EXPECT_EQ(occ.corner, glm::ivec2(5, 8));
    std::array<RgvcOcclusionPolygon, 2> polys;
    ASSERT_EQ(occlusionPolygons(occ, grid, {1.5, 2.5}, polys), 1);
    EXPECT_EQ(polys[0].plane_count, 4);
    EXPECT_TRUE(polys[0].containsPoint({10.0, 12.0}, 0.0));  // inside the L's elbow
    EXPECT_FALSE(polys[0].containsPoint({3.0, 12.0}, 0.0));  // beside the column
    EXPECT_FALSE(polys[0].containsPoint({10.0, 6.0}, 0.0));  // in front of the row
}

// Does the segment from a to b meet the occluder's voxels?
bool segmentMeetsOccluder(const RgvcExtendedOccluder& occ, const RegularGrid& grid, glm::dvec3 a,
                          glm::dvec3 b) {
    for (const glm::ivec2 end : {occ.legXEnd(), occ.legYEnd()}) {
        const glm::ivec2 lo = glm::min(occ.corner, end), hi = glm::max(occ.corner, end);
        const Aabb box{grid.voxelBounds({lo.x, lo.y, 0}).min,
                       grid.voxelBounds({hi.x, hi.y, 0}).max};
        if (segmentMeetsRect(a, b, box.min, box.max)) return true;
    }
    return false;
}

TEST(RgvcOcclusion, OccludersAndOccludedVoxelsAreSoundOnRandomScenes) {
    SeededRandom rng(77);
    int64_t occluders = 0, occluded = 0;
    for (uint64_t seed = 1; seed <= 150; ++seed) {
        const Scene scene = test::rgvcRandomScene(seed);
        RgvcCuller rgvc;
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
            for (const RgvcOccluderView& view : snap.occluders) {
                const RgvcExtendedOccluder& occ = view.occluder;
                // Only opaque or occluded voxels (both matrices only grow in a frame).
                for (int i = 0; i <= occ.leg_x; ++i) {
                    const glm::ivec2 v = occ.corner + glm::ivec2(-occ.toward.x * i, 0);
                    ASSERT_TRUE(snap.occluder->get(v.x, v.y) || snap.occlusion->get(v.x, v.y));
                }
                for (int i = 0; i <= occ.leg_y; ++i) {
                    const glm::ivec2 v = occ.corner + glm::ivec2(0, -occ.toward.y * i);
                    ASSERT_TRUE(snap.occluder->get(v.x, v.y) || snap.occlusion->get(v.x, v.y));
                }
                ASSERT_TRUE(snap.occluder->get(occ.initial.x, occ.initial.y));
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
                ++occluders;
            }
            // Every occluded voxel lies wholly inside some polygon: all four corners.
            for (int y = 0; y < grid.resolution.y; ++y) {
                for (int x = 0; x < grid.resolution.x; ++x) {
                    if (!snap.occlusion->get(x, y)) continue;
                    const Aabb b = grid.voxelBounds({x, y, 0});
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
                    ++occluded;
                }
            }
        }
    }
    // The scenes must exercise the code.
    EXPECT_GT(occluders, 1000);
    EXPECT_GT(occluded, 10000);
}

}  // namespace
}  // namespace gridcull
