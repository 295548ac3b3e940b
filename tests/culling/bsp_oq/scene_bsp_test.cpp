// The scene tree (culling/bsp_oq/scene_bsp.h; Kovalčík & Sochor, "Fast
// rendering of complex dynamic scenes", sections 3.2 and 3.3), against brute
// force written here:
// - after the build and after every frame of seeded random moves (small steps,
//   jumps, exits from the world, NaN and huge boxes), every object is tied to
//   the smallest node whose cell contains its box, found by testing every node
//   (the containing nodes form one chain), or to the root flagged outside;
//   node lists, counts and cells agree with the tree;
// - relink (up to the first ancestor containing the box, then down) ends where
//   relinkFromRoot ends and reads fewer nodes on small moves;
// - the lazy reconstruction keeps all that, waits its delay, and leaves no node
//   out of shape once the scene is still (our rule, the paper's "after several
//   frames");
// - traversal: each object once, near subtree, then the node's objects by
//   centroid distance, then the far subtree; any two objects in an order that
//   an axis-aligned plane between their nodes' cells justifies;
// - a real scene's frames (rooms-3d.json).
// GRIDCULL_SEED=N replays one seed.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/bsp_oq/scene_bsp.h"
#include "culling/io/scene_loader.h"
#include "culling/scene/camera.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/test_seeds.h"

namespace gridcull {
namespace {

const Aabb kWorld{{0, 0, 0}, {100, 100, 50}};
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The cell predicate, written again: closed min faces, max faces open where
// the open_max bit says so.
bool cellHolds(const Aabb& cell, int open_max, const Aabb& box) {
    for (int a = 0; a < 3; ++a) {
        if (!(box.min[a] >= cell.min[a])) return false;
        if ((open_max >> a) & 1) {
            if (!(box.max[a] < cell.max[a])) return false;
        } else if (!(box.max[a] <= cell.max[a])) {
            return false;
        }
    }
    return true;
}

std::vector<int> liveNodes(const SceneBsp& tree) {
    std::vector<int> nodes;
    tree.forEachNode([&](int n) { nodes.push_back(n); });
    return nodes;
}

// The brute-force invariant of section 3.2.
void expectInvariant(const SceneBsp& tree) {
    const std::vector<int> nodes = liveNodes(tree);
    ASSERT_EQ(int(nodes.size()), tree.nodeCount());
    const SceneBspParams& params = tree.params();
    // Structure: every live node reachable, children halve their parent's cell.
    int reachable = 0;
    std::vector<int> stack{SceneBsp::kRoot};
    while (!stack.empty()) {
        const int v = stack.back();
        stack.pop_back();
        ++reachable;
        ASSERT_TRUE(tree.isLive(v));
        ASSERT_LE(tree.nodeDepth(v), params.max_depth);
        if (tree.nodeIsLeaf(v)) {
            ASSERT_EQ(tree.nodeHigh(v), SceneBsp::kNone);
            continue;
        }
        const int a = tree.nodeAxis(v);
        const double s = tree.nodeSplit(v);
        const int lo = tree.nodeLow(v), hi = tree.nodeHigh(v);
        ASSERT_TRUE(tree.isLive(lo) && tree.isLive(hi));
        EXPECT_EQ(tree.nodeParent(lo), v);
        EXPECT_EQ(tree.nodeParent(hi), v);
        EXPECT_EQ(tree.nodeDepth(lo), tree.nodeDepth(v) + 1);
        Aabb low_cell = tree.nodeCell(v), high_cell = tree.nodeCell(v);
        low_cell.max[a] = s;
        high_cell.min[a] = s;
        EXPECT_TRUE(s > tree.nodeCell(v).min[a] && s < tree.nodeCell(v).max[a]);
        EXPECT_EQ(tree.nodeCell(lo).min, low_cell.min);
        EXPECT_EQ(tree.nodeCell(lo).max, low_cell.max);
        EXPECT_EQ(tree.nodeCell(hi).min, high_cell.min);
        EXPECT_EQ(tree.nodeCell(hi).max, high_cell.max);
        EXPECT_EQ(tree.nodeOpenMax(lo), tree.nodeOpenMax(v) | (1 << a));
        EXPECT_EQ(tree.nodeOpenMax(hi), tree.nodeOpenMax(v));
        stack.push_back(lo);
        stack.push_back(hi);
    }
    EXPECT_EQ(reachable, tree.nodeCount());
    EXPECT_EQ(tree.nodeCell(SceneBsp::kRoot).min, params.world.min);
    EXPECT_EQ(tree.nodeCell(SceneBsp::kRoot).max, params.world.max);

    // Every object in the deepest node containing it, found among all nodes.
    int outside = 0;
    for (int id = 0; id < tree.objectCount(); ++id) {
        const Aabb& box = tree.boxOf(id);
        int deepest = SceneBsp::kNone, containing = 0;
        for (int v : nodes)
            if (cellHolds(tree.nodeCell(v), tree.nodeOpenMax(v), box)) {
                ++containing;
                if (deepest == SceneBsp::kNone || tree.nodeDepth(v) > tree.nodeDepth(deepest))
                    deepest = v;
            }
        if (deepest == SceneBsp::kNone) {
            EXPECT_EQ(tree.nodeOf(id), SceneBsp::kRoot) << "object " << id;
            EXPECT_TRUE(tree.isOutside(id)) << "object " << id;
            ++outside;
            continue;
        }
        // The containing nodes are one chain: deepest's ancestors, itself.
        EXPECT_EQ(containing, tree.nodeDepth(deepest) + 1) << "object " << id;
        EXPECT_FALSE(tree.isOutside(id)) << "object " << id;
        EXPECT_EQ(tree.nodeOf(id), deepest) << "object " << id << " not in its smallest node";
    }
    EXPECT_EQ(tree.outsideCount(), outside);

    // Lists and counts.
    std::vector<int> own(size_t(tree.poolSize()), 0);
    for (int v : nodes)
        tree.forEachObjectOf(v, [&](int id) {
            EXPECT_EQ(tree.nodeOf(id), v) << "object " << id << " listed in node " << v;
            ++own[size_t(v)];
        });
    for (int v : nodes) {
        EXPECT_EQ(tree.nodeObjectCount(v), own[size_t(v)]) << "node " << v;
        int subtree = 0;
        for (int id = 0; id < tree.objectCount(); ++id)
            for (int u = tree.nodeOf(id); u != SceneBsp::kNone; u = tree.nodeParent(u))
                if (u == v) ++subtree;
        EXPECT_EQ(tree.nodeSubtreeObjects(v), subtree) << "node " << v;
    }
}

Aabb randomBox(SeededRandom& rng, const Aabb& world) {
    const double size = rng.below(10) == 0 ? rng.uniform(5, 30) : rng.uniform(0.1, 3);
    glm::dvec3 c;
    for (int a = 0; a < 3; ++a) c[a] = rng.uniform(world.min[a], world.max[a]);
    const glm::dvec3 h(0.5 * size, 0.4 * size, 0.3 * size);
    return {c - h, c + h};
}

std::vector<Aabb> randomBoxes(SeededRandom& rng, int n) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < n; ++i) boxes.push_back(randomBox(rng, kWorld));
    return boxes;
}

glm::dvec3 randomStep(SeededRandom& rng, double length) {
    return length * randomDirection(rng, 3) * rng.uniform();
}

// One frame's random motion: most objects still, some small steps, some
// jumps, some out of the world, and (if `wild`) NaN and huge boxes.
void moveSome(SeededRandom& rng, std::vector<Aabb>& boxes, bool wild) {
    for (Aabb& box : boxes) {
        const uint64_t r = rng.below(100);
        if (r < 50) continue;
        if (!std::isfinite(box.min.x + box.max.x + box.min.y + box.max.y + box.min.z + box.max.z))
            box = randomBox(rng, kWorld);  // back from the wild
        if (r < 90) {
            box = box.translated(randomStep(rng, 1.0));
        } else if (r < 95) {
            box = randomBox(rng, kWorld);
        } else if (r < 98) {
            box = box.translated({150.0, 0.0, 0.0});  // out of the world
        } else if (wild) {
            const uint64_t w = rng.below(4);
            if (w == 0) box.min.y = kNaN;
            if (w == 1) box = {{-1e300, -1e300, -1e300}, {1e300, 1e300, 1e300}};
            if (w == 2) box = {{-kInf, 0, 0}, {kInf, 1, 1}};
            if (w == 3) box = {{1e300, 1e300, 1e300}, {1e300, 1e300, 1e300}};
        }
    }
}

SceneBspParams randomParams(SeededRandom& rng) {
    SceneBspParams params;
    params.world = kWorld;
    params.max_node_objects = 1 + int(rng.below(6));
    params.max_depth = 2 + int(rng.below(14));
    params.rebuild_delay_frames = int(rng.below(6)) - 1;
    return params;
}

TEST(SceneBspBuild, EveryObjectInItsSmallestNode) {
    for (uint64_t seed : test::seedsToRun(1, 40)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            std::vector<Aabb> boxes = randomBoxes(rng, int(rng.below(300)));
            if (rng.below(3) == 0 && !boxes.empty()) boxes[0] = boxes[0].translated({-70, 0, 0});
            SceneBsp tree;
            tree.build(randomParams(rng), boxes);
            expectInvariant(tree);
            for (int id = 0; id < tree.objectCount(); ++id)
                EXPECT_EQ(tree.boxOf(id).min, boxes[size_t(id)].min);
        });
    }
}

TEST(SceneBspBuild, CoincidentObjectsEndTheBuild) {
    SceneBspParams params;
    params.world = kWorld;
    params.max_node_objects = 1;
    params.max_depth = kMaxSceneBspDepth;
    for (const Aabb& box : {Aabb{{10, 10, 10}, {11, 11, 11}}, Aabb{{5, 5, 5}, {5, 5, 5}}}) {
        const std::vector<Aabb> boxes(50, box);
        SceneBsp tree;
        tree.build(params, boxes);
        expectInvariant(tree);
        EXPECT_LE(tree.nodeCount(), 2 * 3 * 60 + 1);
    }
}

TEST(SceneBspUpdate, RandomMovesKeepEveryObjectInItsSmallestNode) {
    for (uint64_t seed : test::seedsToRun(1, 25)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            std::vector<Aabb> boxes = randomBoxes(rng, 20 + int(rng.below(200)));
            SceneBsp tree;
            tree.build(randomParams(rng), boxes);
            int rebuilt = 0;
            for (int frame = 1; frame <= 40; ++frame) {
                moveSome(rng, boxes, /*wild=*/true);
                rebuilt += tree.update(boxes, frame).subtrees_rebuilt;
                expectInvariant(tree);
                if (::testing::Test::HasFailure()) {
                    ADD_FAILURE() << "frame " << frame;
                    return;
                }
            }
            if (tree.params().rebuild_delay_frames < 0) {
                EXPECT_EQ(rebuilt, 0);
            }
        });
    }
}

// Boxes on a half-unit lattice, some of zero size: their faces fall exactly on
// split planes (medians of centroids), where the half-open cells decide.
TEST(SceneBspUpdate, BoxesOnTheSplitPlanes) {
    for (uint64_t seed : test::seedsToRun(1, 20)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            auto latticeBox = [&] {
                glm::dvec3 lo(0.0), hi(0.0);  // every axis is set below
                for (int a = 0; a < 3; ++a) {
                    lo[a] = 0.5 * double(rng.below(40));
                    hi[a] = lo[a] + 0.5 * double(rng.below(3));
                }
                return Aabb{lo, hi};
            };
            std::vector<Aabb> boxes;
            for (int i = 0; i < 150; ++i) boxes.push_back(latticeBox());
            SceneBspParams params;
            params.world = {{0, 0, 0}, {20, 20, 20}};
            params.max_node_objects = 1 + int(rng.below(3));
            params.rebuild_delay_frames = int(rng.below(3)) - 1;
            SceneBsp tree;
            tree.build(params, boxes);
            expectInvariant(tree);
            for (int frame = 1; frame <= 20; ++frame) {
                for (Aabb& box : boxes)
                    if (rng.below(3) == 0) box = latticeBox();
                tree.update(boxes, frame);
                expectInvariant(tree);
                if (::testing::Test::HasFailure()) return;
            }
        });
    }
}

TEST(SceneBspUpdate, RelinkMatchesRootRelinkAndVisitsFewerNodesOnSmallMoves) {
    for (uint64_t seed : test::seedsToRun(1, 20)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            std::vector<Aabb> boxes = randomBoxes(rng, 200);
            SceneBspParams params = randomParams(rng);
            params.max_node_objects = 2;
            params.max_depth = 12;
            params.rebuild_delay_frames = -1;  // the same subdivision in both
            SceneBsp up_down, from_root;
            up_down.build(params, boxes);
            from_root.build(params, boxes);
            long up_down_visits = 0, from_root_visits = 0;
            for (int frame = 1; frame <= 30; ++frame)
                for (int id = 0; id < int(boxes.size()); ++id) {
                    boxes[size_t(id)] = boxes[size_t(id)].translated(randomStep(rng, 0.3));
                    up_down_visits += up_down.relink(id, boxes[size_t(id)]).nodes_visited;
                    from_root_visits +=
                        from_root.relinkFromRoot(id, boxes[size_t(id)]).nodes_visited;
                    ASSERT_EQ(up_down.nodeOf(id), from_root.nodeOf(id)) << "object " << id;
                }
            expectInvariant(up_down);
            expectInvariant(from_root);
            EXPECT_LT(2 * up_down_visits, from_root_visits);
        });
    }
}

// Three objects apart, then together in one leaf: an over-full leaf, split
// after the delay; then apart again: an under-full inner node, collapsed.
TEST(SceneBspLazyRebuild, WaitsTheDelayThenSplitsAndCollapses) {
    for (int delay : {0, 1, 4}) {
        SCOPED_TRACE("delay " + std::to_string(delay));
        SceneBspParams params;
        params.world = {{0, 0, 0}, {64, 64, 64}};
        params.max_node_objects = 2;
        params.rebuild_delay_frames = delay;
        const std::vector<Aabb> apart = {
            {{1, 1, 1}, {2, 2, 2}}, {{30, 30, 30}, {31, 31, 31}}, {{60, 60, 60}, {61, 61, 61}}};
        SceneBsp tree;
        tree.build(params, apart);
        ASSERT_FALSE(tree.nodeIsLeaf(SceneBsp::kRoot));
        const int corner_leaf = tree.nodeOf(0);
        ASSERT_TRUE(tree.nodeIsLeaf(corner_leaf));
        const std::vector<Aabb> together = {{{1, 1, 1}, {1.5, 1.5, 1.5}},
                                            {{2, 2, 2}, {2.5, 2.5, 2.5}},
                                            {{3, 3, 3}, {3.5, 3.5, 3.5}}};
        int frame = 1;
        tree.update(together, frame);
        for (int wait = 0; wait < delay; ++wait) {
            EXPECT_TRUE(tree.nodeIsLeaf(corner_leaf)) << "rebuilt before the delay";
            EXPECT_EQ(tree.nodeObjectCount(corner_leaf), 3);
            const int rebuilt = tree.update(together, ++frame).subtrees_rebuilt;
            if (wait + 1 < delay) {
                EXPECT_EQ(rebuilt, 0) << "frame " << frame;
            }
            if (wait + 1 == delay) {
                EXPECT_GE(rebuilt, 1) << "frame " << frame;
            }
        }
        EXPECT_FALSE(tree.nodeIsLeaf(corner_leaf)) << "not rebuilt after the delay";
        expectInvariant(tree);
        for (int v : liveNodes(tree)) EXPECT_FALSE(tree.outOfShape(v)) << "node " << v;

        const std::vector<Aabb> far_apart = {
            {{1, 1, 1}, {2, 2, 2}}, {{20, 20, 20}, {50, 50, 50}}, {{62, 62, 62}, {63, 63, 63}}};
        tree.update(far_apart, ++frame);
        for (int wait = 0; wait < delay; ++wait) tree.update(far_apart, ++frame);
        expectInvariant(tree);
        for (int v : liveNodes(tree)) EXPECT_FALSE(tree.outOfShape(v)) << "node " << v;
        EXPECT_TRUE(tree.nodeIsLeaf(corner_leaf)) << "not collapsed";
    }
}

TEST(SceneBspLazyRebuild, KeepsTheInvariantAndSettlesWhenStill) {
    for (uint64_t seed : test::seedsToRun(1, 20)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            std::vector<Aabb> boxes = randomBoxes(rng, 150);
            SceneBspParams params = randomParams(rng);
            params.rebuild_delay_frames = 1 + int(rng.below(4));
            SceneBsp tree;
            tree.build(params, boxes);
            int rebuilt = 0, frame = 0;
            // Everything drifts into one corner, then stops.
            for (; frame < 30; ++frame) {
                for (Aabb& box : boxes) box = box.translated(-0.1 * box.min + randomStep(rng, 0.2));
                rebuilt += tree.update(boxes, frame).subtrees_rebuilt;
                expectInvariant(tree);
                if (::testing::Test::HasFailure()) return;
            }
            EXPECT_GT(rebuilt, 0);
            for (int still = 0; still <= params.rebuild_delay_frames; ++still)
                tree.update(boxes, ++frame);
            expectInvariant(tree);
            // Out of shape now only: leaves no median plane can split (coincident
            // or straddling objects), which the build would leave as they are.
            for (int v : liveNodes(tree)) {
                if (!tree.outOfShape(v)) continue;
                ASSERT_TRUE(tree.nodeIsLeaf(v)) << "under-full inner node " << v;
                std::vector<Aabb> own;
                tree.forEachObjectOf(v, [&](int id) { own.push_back(tree.boxOf(id)); });
                SceneBspParams sub = params;
                sub.world = tree.nodeCell(v);
                sub.max_depth = params.max_depth - tree.nodeDepth(v);
                SceneBsp alone;
                alone.build(sub, own);
                EXPECT_EQ(alone.nodeCount(), 1) << "node " << v << " could be split";
            }
        });
    }
}

TEST(SceneBspUpdate, ObjectsLeavingTheWorldStayAtTheRoot) {
    SceneBspParams params;
    params.world = kWorld;
    params.max_node_objects = 1;
    SeededRandom rng(4);
    std::vector<Aabb> boxes = randomBoxes(rng, 30);
    SceneBsp tree;
    tree.build(params, boxes);
    const int outside_before = tree.outsideCount() - (tree.isOutside(0) ? 1 : 0);
    const Aabb leaving[] = {
        boxes[0].translated({200, 0, 0}),             // wholly outside
        {{-1, 10, 10}, {1, 11, 11}},                  // partly outside
        {{kNaN, 1, 1}, {2, 2, 2}},                    // NaN
        {{-1e300, 0, 0}, {1e300, 1, 1}},              // huge
        {{-kInf, -kInf, -kInf}, {kInf, kInf, kInf}},  // everything
        {{1e308, 1e308, 1e308}, {1e308, 1e308, 1e308}},
    };
    int frame = 1;
    for (const Aabb& box : leaving) {
        boxes[0] = box;
        tree.update(boxes, frame++);
        EXPECT_EQ(tree.nodeOf(0), SceneBsp::kRoot);
        EXPECT_TRUE(tree.isOutside(0));
        EXPECT_EQ(tree.outsideCount(), outside_before + 1);
        expectInvariant(tree);
        int seen = 0;
        tree.traverseFrontToBack(
            {50, 50, 25}, [](const SceneBspNodeView&) { return true; },
            [&](int id) { seen += id == 0; });
        EXPECT_EQ(seen, 1);
    }
    boxes[0] = {{10, 10, 10}, {10.5, 10.5, 10.5}};  // back inside: it goes down again
    tree.update(boxes, frame++);
    EXPECT_FALSE(tree.isOutside(0));
    EXPECT_EQ(tree.outsideCount(), outside_before);
    EXPECT_NE(tree.nodeOf(0), SceneBsp::kRoot);
    expectInvariant(tree);
}

// The root rebuilt while it holds outside objects: they stay at the root,
// flagged, whether the root collapses (under-full) or splits again (over-full).
TEST(SceneBspLazyRebuild, RootWithOutsideObjects) {
    SceneBspParams params;
    params.world = {{0, 0, 0}, {64, 64, 64}};
    params.max_node_objects = 2;
    params.rebuild_delay_frames = 0;
    std::vector<Aabb> boxes = {{{1, 1, 1}, {2, 2, 2}},
                               {{20, 20, 20}, {21, 21, 21}},
                               {{40, 40, 40}, {41, 41, 41}},
                               {{60, 60, 60}, {61, 61, 61}}};
    SceneBsp tree;
    tree.build(params, boxes);
    ASSERT_FALSE(tree.nodeIsLeaf(SceneBsp::kRoot));
    for (int id = 1; id < 4; ++id) boxes[size_t(id)] = boxes[size_t(id)].translated({100, 0, 0});
    EXPECT_GE(tree.update(boxes, 1).subtrees_rebuilt, 1);
    EXPECT_TRUE(tree.nodeIsLeaf(SceneBsp::kRoot)) << "under-full root not collapsed";
    EXPECT_EQ(tree.outsideCount(), 3);
    expectInvariant(tree);
    boxes[1] = {{2, 2, 2}, {3, 3, 3}};
    boxes[2] = {{50, 50, 50}, {51, 51, 51}};
    EXPECT_GE(tree.update(boxes, 2).subtrees_rebuilt, 1);
    EXPECT_FALSE(tree.nodeIsLeaf(SceneBsp::kRoot)) << "over-full root not split";
    EXPECT_EQ(tree.outsideCount(), 1);
    expectInvariant(tree);
}

// Events of a traversal: a node entered, or an object reported.
struct Event {
    bool is_node;
    int id;
};

std::vector<Event> traversalEvents(const SceneBsp& tree, const glm::dvec3& eye) {
    std::vector<Event> events;
    tree.traverseFrontToBack(
        eye,
        [&](const SceneBspNodeView& v) {
            events.push_back({true, v.id});
            return true;
        },
        [&](int id) {
            events.push_back({false, id});
        });
    return events;
}

bool isAncestorOrSelf(const SceneBsp& tree, int ancestor, int node) {
    for (int u = node; u != SceneBsp::kNone; u = tree.nodeParent(u))
        if (u == ancestor) return true;
    return false;
}

// As in object_bsp_test.cpp: a plane between the cells with the eye on a's side.
bool mayPrecede(const Aabb& a, const Aabb& b, const glm::dvec3& eye) {
    for (int k = 0; k < 3; ++k) {
        if (a.max[k] <= b.min[k] && eye[k] <= b.min[k]) return true;
        if (b.max[k] <= a.min[k] && eye[k] >= b.max[k]) return true;
    }
    return false;
}

void expectTraversalOrder(const SceneBsp& tree, const glm::dvec3& eye) {
    const std::vector<Event> events = traversalEvents(tree, eye);
    std::vector<int> object_pos(size_t(tree.objectCount()), -1);
    std::vector<int> node_pos(size_t(tree.poolSize()), -1);
    for (int k = 0; k < int(events.size()); ++k) {
        const Event& e = events[size_t(k)];
        std::vector<int>& pos = e.is_node ? node_pos : object_pos;
        ASSERT_EQ(pos[size_t(e.id)], -1) << "visited twice";
        pos[size_t(e.id)] = k;
    }
    for (int id = 0; id < tree.objectCount(); ++id) ASSERT_GE(object_pos[size_t(id)], 0);
    // Per node: near subtree, own objects by distance, far subtree.
    for (int v : liveNodes(tree)) {
        std::vector<int> own;
        tree.forEachObjectOf(v, [&](int id) { own.push_back(id); });
        std::sort(own.begin(), own.end(),
                  [&](int x, int y) { return object_pos[size_t(x)] < object_pos[size_t(y)]; });
        for (size_t k = 1; k < own.size(); ++k) {
            const glm::dvec3 dx = tree.boxOf(own[k - 1]).center() - eye;
            const glm::dvec3 dy = tree.boxOf(own[k]).center() - eye;
            const double x = glm::dot(dx, dx), y = glm::dot(dy, dy);
            if (std::isfinite(x) && std::isfinite(y)) {
                EXPECT_LE(x, y) << "node " << v;
            }
            if (!std::isfinite(x)) {
                EXPECT_FALSE(std::isfinite(y)) << "non-finite sorts last";
            }
        }
        for (int id : own) EXPECT_GT(object_pos[size_t(id)], node_pos[size_t(v)]);
        if (tree.nodeIsLeaf(v)) continue;
        const bool low_near = eye[tree.nodeAxis(v)] < tree.nodeSplit(v);
        const int near = low_near ? tree.nodeLow(v) : tree.nodeHigh(v);
        const int far = low_near ? tree.nodeHigh(v) : tree.nodeLow(v);
        for (int id = 0; id < tree.objectCount(); ++id) {
            const int u = tree.nodeOf(id);
            for (int mine : own) {
                if (isAncestorOrSelf(tree, near, u)) {
                    EXPECT_LT(object_pos[size_t(id)], object_pos[size_t(mine)]);
                }
                if (isAncestorOrSelf(tree, far, u)) {
                    EXPECT_GT(object_pos[size_t(id)], object_pos[size_t(mine)]);
                }
            }
        }
        EXPECT_LT(node_pos[size_t(near)], node_pos[size_t(far)]);
    }
    // Any two objects in unrelated nodes: their cells justify the order.
    std::vector<int> by_order(size_t(tree.objectCount()));
    for (int id = 0; id < tree.objectCount(); ++id) by_order[size_t(id)] = id;
    std::sort(by_order.begin(), by_order.end(),
              [&](int x, int y) { return object_pos[size_t(x)] < object_pos[size_t(y)]; });
    for (size_t x = 0; x < by_order.size(); ++x)
        for (size_t y = x + 1; y < by_order.size(); ++y) {
            const int a = tree.nodeOf(by_order[x]), b = tree.nodeOf(by_order[y]);
            if (isAncestorOrSelf(tree, a, b) || isAncestorOrSelf(tree, b, a)) continue;
            if (!mayPrecede(tree.nodeCell(a), tree.nodeCell(b), eye)) {
                ADD_FAILURE() << "object " << by_order[x] << " before " << by_order[y];
                return;
            }
        }
}

TEST(SceneBspTraversal, NearChildThenObjectsByDistanceThenFarChild) {
    for (uint64_t seed : test::seedsToRun(1, 15)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            std::vector<Aabb> boxes = randomBoxes(rng, 120);
            SceneBsp tree;
            tree.build(randomParams(rng), boxes);
            for (int frame = 1; frame <= 5; ++frame) {
                moveSome(rng, boxes, /*wild=*/frame > 3);
                tree.update(boxes, frame);
                for (int k = 0; k < 4; ++k) {
                    glm::dvec3 eye;
                    for (int a = 0; a < 3; ++a)
                        eye[a] = rng.uniform(kWorld.min[a] - 20, kWorld.max[a] + 20);
                    expectTraversalOrder(tree, eye);
                }
            }
        });
    }
}

TEST(SceneBspTraversal, SkippedNodesHideTheirObjectsAndSubtree) {
    SeededRandom rng(9);
    const std::vector<Aabb> boxes = randomBoxes(rng, 100);
    SceneBspParams params;
    params.world = kWorld;
    params.max_node_objects = 2;
    SceneBsp tree;
    tree.build(params, boxes);
    const int skipped = tree.nodeLow(SceneBsp::kRoot);
    ASSERT_NE(skipped, SceneBsp::kNone);
    int reported = 0;
    tree.traverseFrontToBack(
        {10, 10, 10}, [&](const SceneBspNodeView& v) { return v.id != skipped; },
        [&](int id) {
            ++reported;
            EXPECT_FALSE(isAncestorOrSelf(tree, skipped, tree.nodeOf(id))) << "object " << id;
        });
    EXPECT_EQ(reported, tree.objectCount() - tree.nodeSubtreeObjects(skipped));
}

TEST(SceneBspUpdate, RoomsSceneFrames) {
    const SceneLoadResult loaded =
        loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/rooms-3d.json");
    ASSERT_TRUE(loaded.scene.has_value());
    const Scene& scene = *loaded.scene;
    std::vector<Aabb> boxes;
    objectBoxesAt(scene, 0.0, boxes);
    SceneBspParams params;
    params.world = scene.grid.world;
    SceneBsp tree;
    tree.build(params, boxes);
    expectInvariant(tree);
    for (int frame = 1; frame < std::min(scene.frames, 60); ++frame) {
        objectBoxesAt(scene, scene.timeOfFrame(frame), boxes);
        tree.update(boxes, frame);
        if (frame % 10 == 0) expectInvariant(tree);
    }
    expectInvariant(tree);
    expectTraversalOrder(tree, cameraAt(scene, 0.0).position);
}

}  // namespace
}  // namespace gridcull
