// The dynamic octree (culling/hzb_tbv/dynamic_octree.h; Sudarsky & Gotsman,
// "Dynamic scene occlusion culling", section 4, Figs. 5, 7, 9): insertion,
// deletion and update keep each object in its smallest containing node with no
// empty leaf (against the brute-force reference of octree_reference.h); update
// under the LCA gives exactly the tree of delete + insert from the root, and of
// building from scratch, over thousands of seeded random moves, while visiting,
// creating and freeing fewer nodes; the depth limits; objects outside the root;
// steady updates reuse the node pool. Tolerances: none (octree_reference.h says
// why every comparison is exact). GRIDCULL_SEED=N replays one seed.
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/hzb_tbv/dynamic_octree.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/hzb_tbv/octree_reference.h"

namespace gridcull {
namespace {

using test::BoxMaker;
using test::expectInvariants;
using test::shapeOf;

const Aabb kCube{{0, 0, 0}, {16, 16, 16}};

// A root of each kind: a cube, an uneven box, a flat one (2D scenes: z = 0), and
// the depth limits in their ranges.
OctreeParams randomParams(SeededRandom& rng) {
    OctreeParams params;
    const int kind = int(rng.below(3));
    if (kind == 0) params.bounds = kCube;
    if (kind == 1) params.bounds = {{-8, 0, -4}, {24, 8, 4}};
    if (kind == 2) params.bounds = {{0, 0, 0}, {16, 16, 0}};
    params.max_depth = 3 + int(rng.below(6));
    params.min_node_size = rng.uniform() < 0.5 ? 0.0 : 0.3;
    return params;
}

Aabb pointBox(const glm::dvec3& p) {
    return {p, p};
}

TEST(DynamicOctree, InsertAndRemoveKeepEachObjectInItsSmallestNode) {
    for (uint64_t seed : test::seedsToRun(1, 20)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const OctreeParams params = randomParams(rng);
            const BoxMaker maker{params.bounds};
            DynamicOctree tree(params);
            std::map<int, Aabb> boxes;
            for (int id = 0; id < 120; ++id) {
                boxes[id] = maker.random(rng);
                tree.insert(id, boxes[id]);
                if (id % 20 == 19)
                    expectInvariants(tree, boxes, "after insert " + std::to_string(id));
            }
            EXPECT_GT(tree.nodeCount(), 10);
            std::vector<int> order;
            for (const auto& entry : boxes) order.push_back(entry.first);
            for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
            for (size_t i = 0; i < order.size(); ++i) {
                tree.remove(order[i]);
                boxes.erase(order[i]);
                EXPECT_FALSE(tree.contains(order[i]));
                if (i % 10 == 9) expectInvariants(tree, boxes, "after remove " + std::to_string(i));
            }
            EXPECT_EQ(tree.nodeCount(), 1);  // the root alone
            EXPECT_EQ(tree.nodeObjects(DynamicOctree::kRoot).size(), 0);
        });
    }
}

// The paper's claim for Fig. 7 (section 4): "This method can be shown to yield
// the same results as updating the entire octree".
TEST(DynamicOctree, LcaUpdateGivesTheTreeOfDeleteAndInsert) {
    int moves = 0;
    for (uint64_t seed : test::seedsToRun(1, 24)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const OctreeParams params = randomParams(rng);
            const BoxMaker maker{params.bounds};
            DynamicOctree lca(params), root(params);
            std::map<int, Aabb> boxes;
            const int n = 30 + int(rng.below(40));
            for (int id = 0; id < n; ++id) {
                boxes[id] = maker.random(rng);
                lca.insert(id, boxes[id]);
                root.insert(id, boxes[id]);
            }
            const glm::dvec3 e = params.bounds.extent();
            const double scale = std::max({e.x, e.y, e.z});
            for (int step = 0; step < 300; ++step) {
                const int id = int(rng.below(uint64_t(n)));
                const double r = rng.uniform();
                const Aabb next = r < 0.1   ? maker.random(rng)
                                  : r < 0.7 ? maker.moved(rng, boxes[id], scale * 0.005)
                                            : maker.moved(rng, boxes[id], scale * 0.05);
                const OctreeOpCost a = lca.update(id, next);
                const OctreeOpCost b = root.updateFromRoot(id, next);
                boxes[id] = next;
                ++moves;
                ASSERT_TRUE(shapeOf(lca) == shapeOf(root)) << "move " << step << " of " << id;
                // Same start, same end: the same net change, and the LCA update does
                // a subset of the root update's work.
                EXPECT_EQ(a.nodes_created - a.nodes_freed, b.nodes_created - b.nodes_freed);
                EXPECT_LT(a.nodes_visited, b.nodes_visited);
                EXPECT_LE(a.nodes_created, b.nodes_created);
                EXPECT_LE(a.nodes_freed, b.nodes_freed);
                if (step % 50 == 49) expectInvariants(lca, boxes, "move " + std::to_string(step));
            }
            DynamicOctree fresh(params);
            for (const auto& [id, box] : boxes) fresh.insert(id, box);
            EXPECT_TRUE(shapeOf(fresh) == shapeOf(lca)) << "not the tree built from scratch";
            expectInvariants(lca, boxes, "the end");
        });
    }
    if (!test::singleSeedRun()) {
        EXPECT_GE(moves, 7000);
    }
}

// Section 4: under temporal coherence "the LCA is expected to be closer to the
// leaves than to the root". Small objects, small moves: the sums over many
// moves must show it, not only each move's strict inequality.
TEST(DynamicOctree, LcaUpdateVisitsFewerNodesOnSmallMoves) {
    long long lca_visits = 0, root_visits = 0, lca_churn = 0, root_churn = 0;
    for (uint64_t seed : test::seedsToRun(100, 5)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            OctreeParams params;
            params.bounds = kCube;
            params.max_depth = 8;
            DynamicOctree lca(params), root(params);
            std::vector<Aabb> boxes;
            for (int id = 0; id < 40; ++id) {
                const glm::dvec3 c{rng.uniform(1, 15), rng.uniform(1, 15), rng.uniform(1, 15)};
                boxes.push_back({c - 0.02, c + 0.02});
                lca.insert(id, boxes.back());
                root.insert(id, boxes.back());
            }
            for (int step = 0; step < 1000; ++step) {
                const int id = int(rng.below(boxes.size()));
                const glm::dvec3 d{rng.uniform(-0.01, 0.01), rng.uniform(-0.01, 0.01),
                                   rng.uniform(-0.01, 0.01)};
                boxes[size_t(id)] = boxes[size_t(id)].translated(d);
                const OctreeOpCost a = lca.update(id, boxes[size_t(id)]);
                const OctreeOpCost b = root.updateFromRoot(id, boxes[size_t(id)]);
                lca_visits += a.nodes_visited;
                root_visits += b.nodes_visited;
                lca_churn += a.nodes_created + a.nodes_freed;
                root_churn += b.nodes_created + b.nodes_freed;
            }
            ASSERT_TRUE(shapeOf(lca) == shapeOf(root));
        });
    }
    // Objects 0.04 wide at depth ~7-8: a root update walks ~2 x 8 nodes, an LCA
    // update ~1-3. A quarter is a wide margin over what these moves give.
    EXPECT_LT(lca_visits * 4, root_visits) << lca_visits << " vs " << root_visits;
    EXPECT_LT(lca_churn * 4, root_churn) << lca_churn << " vs " << root_churn;
}

// Figs. 6 and 8 by hand: a dynamic object alone in its branch at depth 7 of a
// [0, 16] cube (cells of 0.125), another object far away.
TEST(DynamicOctree, HandCountedUpdateCosts) {
    OctreeParams params;
    params.bounds = kCube;
    params.max_depth = 7;
    DynamicOctree tree(params);
    tree.insert(0, {{0.1, 0.1, 0.1}, {0.11, 0.11, 0.11}});
    const Aabb start{{15.01, 15.01, 15.01}, {15.05, 15.05, 15.05}};
    const OctreeOpCost inserted = tree.insert(1, start);
    EXPECT_EQ(inserted.nodes_visited, 8);  // root and 7 levels
    EXPECT_EQ(inserted.nodes_created, 7);
    EXPECT_EQ(tree.nodeDepth(tree.nodeOf(1)), 7);

    // Within its cell [15, 15.125]: the LCA is its own node.
    const Aabb inside = start.translated({0.01, 0.01, 0.01});
    const OctreeOpCost a = tree.update(1, inside);
    EXPECT_EQ(a.nodes_visited, 1);
    EXPECT_EQ(a.nodes_created, 0);
    EXPECT_EQ(a.nodes_freed, 0);
    // From the root: down 7 levels to find it (8 nodes), 7 nodes merged, then
    // 8 nodes down again with 7 created: Fig. 6's needless deletions.
    const OctreeOpCost b = tree.updateFromRoot(1, start);
    EXPECT_EQ(b.nodes_visited, 16);
    EXPECT_EQ(b.nodes_created, 7);
    EXPECT_EQ(b.nodes_freed, 7);

    // Across the x plane at 15.125 between two depth-7 cells: the LCA is the
    // depth-6 parent; one node freed, one created (Fig. 8).
    const Aabb across{{15.13, 15.01, 15.01}, {15.15, 15.05, 15.05}};
    const OctreeOpCost c = tree.update(1, across);
    EXPECT_EQ(c.nodes_visited, 3);
    EXPECT_EQ(c.nodes_created, 1);
    EXPECT_EQ(c.nodes_freed, 1);
    EXPECT_EQ(tree.nodeBox(tree.nodeOf(1)).min.x, 15.125);

    // Removing it frees its whole branch below the root.
    const int before = tree.nodeCount();
    const OctreeOpCost r = tree.remove(1);
    EXPECT_EQ(r.nodes_freed, 7);
    EXPECT_EQ(r.nodes_visited, 8);
    EXPECT_EQ(tree.nodeCount(), before - 7);
}

TEST(DynamicOctree, DepthLimitsStopTheDescent) {
    OctreeParams params;
    params.bounds = kCube;
    params.max_depth = 3;
    DynamicOctree tree(params);
    tree.insert(0, pointBox({1, 1, 1}));
    EXPECT_EQ(tree.nodeDepth(tree.nodeOf(0)), 3);
    EXPECT_EQ(tree.nodeBox(tree.nodeOf(0)).max, glm::dvec3(2.0));

    // Children of side 1 are allowed at min_node_size 1 (1 >= 1), of side 0.5 not.
    params.max_depth = 20;
    params.min_node_size = 1.0;
    tree.reset(params);
    tree.insert(0, pointBox({0.3, 0.3, 0.3}));
    EXPECT_EQ(tree.nodeDepth(tree.nodeOf(0)), 4);
    EXPECT_EQ(tree.nodeBox(tree.nodeOf(0)).max, glm::dvec3(1.0));
    params.min_node_size = 1.01;
    tree.reset(params);
    tree.insert(0, pointBox({0.3, 0.3, 0.3}));
    EXPECT_EQ(tree.nodeDepth(tree.nodeOf(0)), 3);

    params.max_depth = 0;
    params.min_node_size = 0.0;
    tree.reset(params);
    tree.insert(0, pointBox({0.3, 0.3, 0.3}));
    EXPECT_EQ(tree.nodeOf(0), DynamicOctree::kRoot);
    EXPECT_EQ(tree.nodeCount(), 1);
}

// A box touching a split plane from below goes low; one of zero thickness on
// the plane goes low too, and moving it there from the high side must land
// where a fresh insertion does (the exact descent predicate of the climb).
TEST(DynamicOctree, BoxesOnSplitPlanesGoLow) {
    OctreeParams params;
    params.bounds = kCube;
    params.max_depth = 2;
    DynamicOctree tree(params);
    tree.insert(0, {{7, 1, 1}, {8, 2, 2}});  // touches x = 8 from below
    EXPECT_EQ(tree.nodeBox(tree.nodeOf(0)).max.x, 8.0);
    tree.insert(1, {{8, 1, 1}, {9, 2, 2}});  // from above
    EXPECT_EQ(tree.nodeBox(tree.nodeOf(1)).min.x, 8.0);
    const Aabb on_plane{{8, 1, 1}, {8, 2, 2}};
    tree.update(1, on_plane);  // from the high side onto the plane
    DynamicOctree fresh(params);
    fresh.insert(1, on_plane);
    EXPECT_EQ(tree.nodeBox(tree.nodeOf(1)).max.x, 8.0);
    EXPECT_TRUE(test::keyOfNode(tree, tree.nodeOf(1)) == test::keyOfNode(fresh, fresh.nodeOf(1)));
}

TEST(DynamicOctree, ObjectsOutsideTheRootStayAtTheRoot) {
    OctreeParams params;
    params.bounds = kCube;
    params.max_depth = 5;
    DynamicOctree tree(params);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::map<int, Aabb> boxes{
        {0, {{15, 1, 1}, {17, 2, 2}}},      // partly outside
        {1, {{20, 20, 20}, {21, 21, 21}}},  // wholly outside
        {2, {{nan, 1, 1}, {nan, 2, 2}}},    // not a box at all
        {3, {{7, 7, 7}, {9, 9, 9}}},        // inside, straddles the centre
        {4, {{16, 1, 1}, {16, 2, 2}}},      // on the root's face: inside
        {5, kCube},                         // the root's box itself
    };
    for (const auto& [id, box] : boxes) tree.insert(id, box);
    for (int id : {0, 1, 2, 3, 5}) EXPECT_EQ(tree.nodeOf(id), DynamicOctree::kRoot) << id;
    for (int id : {0, 1, 2}) EXPECT_TRUE(tree.isOutside(id)) << id;
    for (int id : {3, 4, 5}) EXPECT_FALSE(tree.isOutside(id)) << id;
    EXPECT_GT(tree.nodeDepth(tree.nodeOf(4)), 0);
    EXPECT_EQ(tree.outsideCount(), 3);
    boxes.erase(2);  // NaN never equals itself: keep it out of the reference
    tree.remove(2);
    expectInvariants(tree, boxes, "outside objects");

    // Moving in and out, by either update.
    boxes[0] = {{14, 1, 1}, {14.5, 1.5, 1.5}};
    tree.update(0, boxes[0]);
    EXPECT_GT(tree.nodeDepth(tree.nodeOf(0)), 0);
    EXPECT_EQ(tree.outsideCount(), 1);
    boxes[3] = {{-3, 7, 7}, {-2, 8, 8}};
    tree.updateFromRoot(3, boxes[3]);
    EXPECT_TRUE(tree.isOutside(3));
    boxes[1] = {{1, 1, 1}, {1.2, 1.2, 1.2}};
    tree.updateFromRoot(1, boxes[1]);
    boxes[0] = {{14, 1, 1}, {18, 1.5, 1.5}};
    tree.update(0, boxes[0]);
    EXPECT_EQ(tree.nodeOf(0), DynamicOctree::kRoot);
    EXPECT_EQ(tree.outsideCount(), 2);
    expectInvariants(tree, boxes, "after moves");

    // The traversal reports them with the root.
    int seen_at_root = 0;
    tree.traverseFrontToBack({-5, -5, -5}, [&](const OctreeNodeView& node) {
        if (node.id == DynamicOctree::kRoot)
            for (int id : node.objects) seen_at_root += tree.isOutside(id);
        return true;
    });
    EXPECT_EQ(seen_at_root, 2);
}

// "Steady updates do not allocate": once objects have moved between the same
// places, neither update grows the node pool or moves it.
TEST(DynamicOctree, SteadyUpdatesReuseTheNodePool) {
    SeededRandom rng(5);
    OctreeParams params;
    params.bounds = kCube;
    params.max_depth = 7;
    const BoxMaker maker{params.bounds};
    for (bool from_root : {false, true}) {
        DynamicOctree tree(params);
        std::vector<Aabb> here, there;
        for (int id = 0; id < 60; ++id) {
            here.push_back(maker.random(rng));
            there.push_back(maker.random(rng));
            tree.insert(id, here.back());
        }
        auto moveAll = [&](const std::vector<Aabb>& to) {
            for (int id = 0; id < 60; ++id)
                from_root ? tree.updateFromRoot(id, to[size_t(id)])
                          : tree.update(id, to[size_t(id)]);
        };
        moveAll(there);
        moveAll(here);
        const int pool = tree.poolSize();
        const int live = tree.nodeCount();
        for (int cycle = 0; cycle < 20; ++cycle) {
            moveAll(there);
            moveAll(here);
            EXPECT_EQ(tree.poolSize(), pool) << "cycle " << cycle << (from_root ? " root" : " lca");
        }
        EXPECT_EQ(tree.nodeCount(), live);
        EXPECT_LT(live, pool);  // some nodes wait in the free list
    }
}

}  // namespace
}  // namespace gridcull
