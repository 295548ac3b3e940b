// --hzb-octree-update: the update under the least common ancestor (0) and the
// paper's comparison, delete and reinsert from the root (1), build the same
// octree (dynamic_octree_test.cpp checks that node by node), so the culler's
// PVS and every other counter must match frame by frame; only the octree work
// (octree_update_nodes) differs, and the LCA's is the smaller.
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "culling/api/culler.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/hzb_tbv/hzb_random_rooms.h"

namespace gridcull {
namespace {

TEST(HzbOctreeUpdateKnob, RootUpdateGivesTheSamePvsForMoreOctreeWork) {
    for (const char* algo : {"hzb-tbv", "hzb"}) {
        int64_t lca_nodes = 0, root_nodes = 0;
        for (uint64_t seed = 1; seed <= 6; ++seed) {
            const Scene scene = test::hzbRandomRooms(seed);
            KnobValues lca_knobs, root_knobs;
            lca_knobs.set("oracle-res", 128);
            root_knobs.set("oracle-res", 128);
            root_knobs.set("hzb-octree-update", 1);
            auto lca = test::makeOrDie(algo, lca_knobs);
            auto root = test::makeOrDie(algo, root_knobs);
            lca->reset(scene);
            root->reset(scene);
            FrameResult a, b;
            for (int frame = 0; frame < scene.frames; ++frame) {
                const double t = scene.timeOfFrame(frame);
                const Camera camera = cameraAt(scene, t);
                lca->cull(scene, camera, t, a);
                root->cull(scene, camera, t, b);
                ASSERT_EQ(a.pvs, b.pvs) << algo << " seed " << seed << " frame " << frame;
                for (const Counter c : {Counter::ObjectUpdates, Counter::NodesVisited,
                                        Counter::OcclusionTests, Counter::TbvCreated})
                    EXPECT_EQ(a.stats.get(c), b.stats.get(c))
                        << algo << " " << counterName(c) << " seed " << seed << " frame " << frame;
                lca_nodes += a.stats.get(Counter::OctreeUpdateNodes);
                root_nodes += b.stats.get(Counter::OctreeUpdateNodes);
            }
        }
        std::printf("[ hzb octree ] %s: octree update nodes, LCA %lld, root %lld (%.2fx)\n", algo,
                    (long long)lca_nodes, (long long)root_nodes,
                    double(root_nodes) / double(lca_nodes));
        EXPECT_GT(lca_nodes, 0) << algo;
        EXPECT_LT(lca_nodes, root_nodes) << algo;
    }
}

}  // namespace
}  // namespace gridcull
