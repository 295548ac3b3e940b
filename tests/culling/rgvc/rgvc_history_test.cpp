// The snapshot's per-layer history (RgvcSnapshot::h_layer, o_layer, h_cause,
// reveals), from which the window shows the matrices as they were at any chess
// layer: on random 2D and 3D scenes, each visit's "occluded" agrees with the
// layer at which its voxel entered H, every occluded voxel names an occluder of
// an earlier (2D: not later) layer, and the reveals carry their layers.
#include <gtest/gtest.h>

#include "culling/rgvc/rgvc_culler.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/rgvc/rgvc_random_scene.h"
#include "tests/culling/rgvc/rgvc_random_scene3d.h"

namespace gridcull {
namespace {

void checkHistory(const Scene& scene, int64_t& occluded_seen) {
    RgvcCuller rgvc;
    rgvc.setDebugCapture(true);
    rgvc.reset(scene);
    FrameResult out;
    for (int frame = 0; frame < scene.frames; ++frame) {
        const double t = scene.timeOfFrame(frame);
        rgvc.cull(scene, cameraAt(scene, t), t, out);
        const RgvcSnapshot& s = rgvc.snapshot();
        ASSERT_TRUE(s.valid);
        const RegularGrid& g = s.grid;
        ASSERT_EQ(s.h_layer.size(), size_t(g.voxelCount()));
        for (const RgvcVisit& v : s.visits) {
            const size_t i = size_t(g.linearIndex({v.voxel.x, v.voxel.y, v.z}));
            const int32_t entered = s.h_layer[i];
            if (v.occluded) {
                ++occluded_seen;
                // 2D marks H eagerly (a layer's polygons may mark voxels of the
                // same layer before the walk reaches them); 3D at the visit.
                if (s.dimensions == 2)
                    EXPECT_LE(entered, v.layer) << "frame " << frame;
                else
                    EXPECT_EQ(entered, v.layer) << "frame " << frame;
                const int32_t cause = s.h_cause[i];
                if (s.dimensions == 2) {
                    ASSERT_GE(cause, 0);
                    ASSERT_LT(size_t(cause), s.occluders.size());
                    EXPECT_LE(s.occluders[size_t(cause)].layer, entered);
                } else if (cause >= 0) {
                    ASSERT_LT(size_t(cause), s.occluders3d.size());
                    EXPECT_LT(s.occluders3d[size_t(cause)].layer, entered);
                }
            } else {
                EXPECT_GE(entered, v.layer) << "frame " << frame;
            }
            // O set by a reveal during the traversal: at a layer the traversal had reached.
            const int32_t opaque = s.o_layer[i];
            if (opaque != kRgvcNoLayer) {
                EXPECT_LE(opaque, s.last_layer);
            }
        }
        for (const RgvcRevealView& r : s.reveals) {
            EXPECT_GE(r.layer, -1);
            EXPECT_LE(r.layer, s.last_layer);
            EXPECT_GE(r.tbv.object_index, 0);
        }
    }
}

TEST(RgvcHistory, VisitsAgreeWithTheLayersVoxelsEnteredH2d) {
    int64_t occluded = 0;
    for (const uint64_t seed : test::seedsToRun(600000, 40))
        test::withSeed(seed, [&] { checkHistory(test::rgvcRandomScene(seed), occluded); });
    if (!test::singleSeedRun()) {
        EXPECT_GT(occluded, 0);
    }
}

TEST(RgvcHistory, VisitsAgreeWithTheLayersVoxelsEnteredH3d) {
    int64_t occluded = 0;
    for (const uint64_t seed : test::seedsToRun(610000, 40))
        test::withSeed(seed, [&] { checkHistory(test::rgvcRandomScene3d(seed), occluded); });
    if (!test::singleSeedRun()) {
        EXPECT_GT(occluded, 0);
    }
}

}  // namespace
}  // namespace gridcull
