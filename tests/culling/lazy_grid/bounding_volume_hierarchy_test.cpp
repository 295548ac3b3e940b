// The AABB hierarchy of the lazy occlusion grid
// (culling/lazy_grid/bounding_volume_hierarchy.h): every object in exactly one leaf, every box containing its
// children and its objects' bounds at t, pre-order storage, refitting to moving
// objects, and a rebuild once refitting has loosened the boxes enough.
#include <vector>

#include <gtest/gtest.h>

#include "culling/lazy_grid/bounding_volume_hierarchy.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/lazy_grid/lazy_grid_random_scene.h"

namespace gridcull {
namespace {

bool contains(const Aabb& outer, const Aabb& inner) {
    return outer.contains(inner.min) && outer.contains(inner.max);
}

void checkTree(const BoundingVolumeHierarchy& bvh, const Scene& scene, double t, int max_leaf) {
    const auto& nodes = bvh.nodes();
    ASSERT_FALSE(nodes.empty());
    EXPECT_EQ(nodes[0].parent, -1);
    std::vector<int> seen(scene.objects.size(), 0);
    for (size_t k = 0; k < nodes.size(); ++k) {
        const BvhNode& node = nodes[k];
        if (node.isLeaf()) {
            EXPECT_GE(node.count, 1);
            EXPECT_LE(node.count, max_leaf);
            for (int32_t j = node.first; j < node.first + node.count; ++j) {
                const int i = bvh.objectOrder()[size_t(j)];
                ++seen[size_t(i)];
                EXPECT_EQ(bvh.leafOf(i), int32_t(k));
                EXPECT_TRUE(contains(node.box, scene.boundsAt(scene.objects[size_t(i)], t)));
            }
        } else {
            for (int32_t child : {node.left, node.right}) {
                EXPECT_GT(child, int32_t(k)) << "pre-order";
                EXPECT_EQ(nodes[size_t(child)].parent, int32_t(k));
                EXPECT_TRUE(contains(node.box, nodes[size_t(child)].box));
            }
        }
    }
    for (int count : seen) EXPECT_EQ(count, 1);
    if (max_leaf == 1) {
        EXPECT_EQ(nodes.size(), 2 * scene.objects.size() - 1) << "a full binary tree";
    }
}

TEST(BoundingVolumeHierarchy, HoldsEveryObjectOnceAndContainsItAtEveryFrame) {
    for (uint64_t seed : test::seedsToRun(1, 40)) {
        test::withSeed(seed, [&] {
            const Scene scene = test::lazyGridRandomScene(seed);
            BoundingVolumeHierarchy bvh;
            bvh.build(scene, 0.0);
            checkTree(bvh, scene, 0.0, 1);
            for (int frame = 1; frame < scene.frames; ++frame) {
                bvh.update(scene, scene.timeOfFrame(frame));
                checkTree(bvh, scene, scene.timeOfFrame(frame), 1);
            }
        });
    }
}

TEST(BoundingVolumeHierarchy, RebuildsOnceRefittingHasLoosenedTheBoxes) {
    // Two groups of spheres fly apart: refitting keeps each group's parent box
    // spanning both, so the summed area grows until a rebuild.
    Scene scene = test::scene3d();
    for (int k = 0; k < 16; ++k) {
        test::addSphere(scene, k, {50 + 0.5 * k, 50, 50}, 0.2);
        scene.objects.back().motion.kind = MotionKind::Linear;
        scene.objects.back().motion.velocity = {0, (k % 2 ? 1 : -1) * 20.0, 0};
    }
    scene.finalize();
    BoundingVolumeHierarchy bvh;
    bvh.build(scene, 0.0);
    const double area0 = bvh.surfaceAreaSum();
    int rebuilt_at = -1;
    for (int frame = 1; frame < 40 && rebuilt_at < 0; ++frame) {
        if (bvh.update(scene, frame * 0.05)) rebuilt_at = frame;
        if (rebuilt_at < 0) {
            EXPECT_LE(bvh.surfaceAreaSum(),
                      BoundingVolumeHierarchy::kRebuildGrowth * area0 * 1.0001);
        }
    }
    EXPECT_GT(rebuilt_at, 0);
    EXPECT_EQ(bvh.rebuilds(), 1);
    checkTree(bvh, scene, rebuilt_at * 0.05, 1);
    // A static scene is never refitted or rebuilt.
    Scene still = test::scene3d();
    test::addBox(still, 0, {1, 1, 1}, {2, 2, 2});
    test::addBox(still, 1, {5, 1, 1}, {6, 2, 2});
    still.finalize();
    BoundingVolumeHierarchy fixed;
    fixed.build(still, 0.0);
    EXPECT_FALSE(fixed.update(still, 3.0));
    EXPECT_EQ(fixed.rebuilds(), 0);
}

TEST(BoundingVolumeHierarchy, LeavesHoldUpToTheirLimitAndAnEmptySceneHasNoNodes) {
    const Scene scene = test::lazyGridRandomScene(7);
    BoundingVolumeHierarchy bvh;
    bvh.build(scene, 0.0, 4);
    const auto& nodes = bvh.nodes();
    std::vector<int> seen(scene.objects.size(), 0);
    for (const BvhNode& node : nodes)
        if (node.isLeaf()) {
            EXPECT_LE(node.count, 4);
            for (int32_t j = node.first; j < node.first + node.count; ++j)
                ++seen[size_t(bvh.objectOrder()[size_t(j)])];
        }
    for (int count : seen) EXPECT_EQ(count, 1);
    Scene empty = test::scene3d();
    empty.finalize();
    bvh.build(empty, 0.0);
    EXPECT_TRUE(bvh.empty());
    EXPECT_FALSE(bvh.update(empty, 1.0));
}

}  // namespace
}  // namespace gridcull
