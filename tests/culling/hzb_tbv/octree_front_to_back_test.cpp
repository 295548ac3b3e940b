// The dynamic octree's front-to-back traversal (culling/hzb_tbv/
// dynamic_octree.h; the near-to-far octree order of Greene et al.'s hierarchical
// z-buffer that Sudarsky & Gotsman's section 2.1.1 describes): every live node
// once, a parent before its children, siblings in the order near ^ k of the
// eye's octant (the eye's octant first, the opposite last); against brute force
// with rays from the eye: whenever a ray leaves one node's box before it enters
// another's (neither containing the other), the traversal visits the first node
// first; a visitor's false skips exactly that node's subtree.
// GRIDCULL_SEED=N replays one seed.
#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "culling/hzb_tbv/dynamic_octree.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/hzb_tbv/octree_reference.h"

namespace gridcull {
namespace {

// A ray must leave one box at least this far (world units, along a unit
// direction, in a 16-unit scene) before it enters the other for the pair to be
// judged: rays through a shared face or grazing an edge, where which box comes
// first is a matter of rounding, are not.
constexpr double kChordGap = 1e-9;

DynamicOctree randomTree(SeededRandom& rng) {
    OctreeParams params;
    params.bounds = {{0, 0, 0}, {16, 16, 16}};
    params.max_depth = 6;
    DynamicOctree tree(params);
    const test::BoxMaker maker{params.bounds};
    for (int id = 0; id < 80; ++id) tree.insert(id, maker.random(rng));
    return tree;
}

glm::dvec3 randomEye(SeededRandom& rng) {
    // Inside the root half of the time, around it otherwise.
    const double lo = rng.uniform() < 0.5 ? 0.0 : -20.0, hi = lo == 0.0 ? 16.0 : 36.0;
    return {rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
}

std::vector<int> visitOrder(const DynamicOctree& tree, const glm::dvec3& eye) {
    std::vector<int> order;
    tree.traverseFrontToBack(eye, [&](const OctreeNodeView& node) {
        order.push_back(node.id);
        EXPECT_EQ(node.depth, tree.nodeDepth(node.id));
        EXPECT_EQ(node.objects.size(), tree.nodeObjects(node.id).size());
        return true;
    });
    return order;
}

bool isAncestor(const DynamicOctree& tree, int ancestor, int node) {
    for (int v = tree.nodeParent(node); v != DynamicOctree::kNone; v = tree.nodeParent(v))
        if (v == ancestor) return true;
    return false;
}

// The slab method: the ray's parameter interval inside the box (empty: t0 > t1).
void chord(const glm::dvec3& eye, const glm::dvec3& dir, const Aabb& box, double& t0, double& t1) {
    t0 = 0.0;
    t1 = 1e300;
    for (int a = 0; a < 3; ++a) {
        double lo = (box.min[a] - eye[a]) / dir[a], hi = (box.max[a] - eye[a]) / dir[a];
        if (lo > hi) std::swap(lo, hi);
        t0 = std::max(t0, lo);
        t1 = std::min(t1, hi);
    }
}

TEST(OctreeFrontToBack, ParentsFirstSiblingsFromTheEyesOctant) {
    for (uint64_t seed : test::seedsToRun(1, 30)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const DynamicOctree tree = randomTree(rng);
            for (int e = 0; e < 10; ++e) {
                const glm::dvec3 eye = randomEye(rng);
                const std::vector<int> order = visitOrder(tree, eye);
                ASSERT_EQ(int(order.size()), tree.nodeCount());
                std::map<int, int> position;
                for (int i = 0; i < int(order.size()); ++i) position[order[size_t(i)]] = i;
                ASSERT_EQ(position.size(), order.size()) << "a node visited twice";
                for (int node : order) {
                    if (node != DynamicOctree::kRoot) {
                        EXPECT_LT(position[tree.nodeParent(node)], position[node]);
                    }
                    // The eye's octant, computed here: bit a when the eye is past the centre.
                    const glm::dvec3 c = tree.nodeBox(node).center();
                    const int near = (eye.x > c.x) | (eye.y > c.y) << 1 | (eye.z > c.z) << 2;
                    std::vector<std::pair<int, int>> siblings;  // (position, octant)
                    for (int octant = 0; octant < 8; ++octant) {
                        const int child = tree.nodeChild(node, octant);
                        if (child != DynamicOctree::kNone)
                            siblings.push_back({position[child], octant});
                    }
                    std::sort(siblings.begin(), siblings.end());
                    if (siblings.empty()) continue;
                    if (tree.nodeChild(node, near) != DynamicOctree::kNone) {
                        EXPECT_EQ(siblings.front().second, near);
                    }
                    if (tree.nodeChild(node, near ^ 7) != DynamicOctree::kNone) {
                        EXPECT_EQ(siblings.back().second, near ^ 7);
                    }
                    // A child may hide a sibling only if, on every axis where they
                    // differ, it lies on the eye's side: that one must come first.
                    for (size_t i = 0; i < siblings.size(); ++i)
                        for (size_t j = i + 1; j < siblings.size(); ++j) {
                            const int first = siblings[i].second ^ near;
                            const int later = siblings[j].second ^ near;
                            EXPECT_FALSE((later & first) == later && later != first)
                                << "octant " << siblings[j].second << " may hide "
                                << siblings[i].second << " but comes after it";
                        }
                }
            }
        });
    }
}

TEST(OctreeFrontToBack, NoNodeBeforeOneARayMeetsWhollyInFrontOfIt) {
    long long pairs = 0;
    for (uint64_t seed : test::seedsToRun(1, 12)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const DynamicOctree tree = randomTree(rng);
            for (int e = 0; e < 4; ++e) {
                const glm::dvec3 eye = randomEye(rng);
                const std::vector<int> order = visitOrder(tree, eye);
                for (int r = 0; r < 100; ++r) {
                    const glm::dvec3 dir = randomDirection(rng, 3);
                    std::vector<std::pair<double, double>> chords(order.size());
                    for (size_t i = 0; i < order.size(); ++i)
                        chord(eye, dir, tree.nodeBox(order[i]), chords[i].first, chords[i].second);
                    for (size_t i = 0; i < order.size(); ++i) {
                        if (chords[i].first > chords[i].second) continue;
                        for (size_t j = i + 1; j < order.size(); ++j) {
                            // order[j] is visited after order[i]: the ray must not
                            // pass wholly through order[j] before reaching order[i].
                            if (chords[j].first > chords[j].second) continue;
                            if (isAncestor(tree, order[i], order[j])) continue;
                            ++pairs;
                            EXPECT_FALSE(chords[j].second + kChordGap < chords[i].first)
                                << "node " << order[j] << " lies in front of node " << order[i]
                                << " along a ray but is visited after it";
                        }
                    }
                }
            }
        });
    }
    if (!test::singleSeedRun()) {
        EXPECT_GT(pairs, 10000);
    }
}

TEST(OctreeFrontToBack, PruningSkipsExactlyTheSubtree) {
    for (uint64_t seed : test::seedsToRun(1, 20)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const DynamicOctree tree = randomTree(rng);
            std::set<int> pruned;
            tree.forEachNode([&](int node) {
                if (rng.uniform() < 0.15) pruned.insert(node);
            });
            std::set<int> visited;
            tree.traverseFrontToBack(randomEye(rng), [&](const OctreeNodeView& node) {
                EXPECT_TRUE(visited.insert(node.id).second);
                return !pruned.count(node.id);
            });
            int expected = 0;
            tree.forEachNode([&](int node) {
                bool hidden = false;  // below a pruned node
                for (int v = tree.nodeParent(node); v != DynamicOctree::kNone;
                     v = tree.nodeParent(v))
                    hidden = hidden || pruned.count(v);
                EXPECT_EQ(visited.count(node) == 1, !hidden) << "node " << node;
                expected += !hidden;
            });
            EXPECT_EQ(int(visited.size()), expected);
            EXPECT_LT(expected, tree.nodeCount());
        });
    }
}

}  // namespace
}  // namespace gridcull
