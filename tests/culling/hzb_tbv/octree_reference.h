// Brute-force references for the dynamic octree's tests (culling/hzb_tbv/
// dynamic_octree.h; Sudarsky & Gotsman, "Dynamic scene occlusion culling",
// section 4): where a box belongs, written as "the deepest node whose closed box
// contains it, the first such child in octant order 0..7 (ties to the low
// halves)", a comparison key for nodes that does not depend on pool indices,
// the structural invariants, and the random boxes and moves the tests use.
//
// Tolerance: none. The reference splits a node at (min + max) * 0.5 as the
// octree does (Aabb::center), so both compute bit-identical child boxes and every
// comparison below is exact.
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "culling/hzb_tbv/dynamic_octree.h"
#include "culling/scene/seeded_random.h"

namespace gridcull::test {

// A node named by its depth and box: unique in an octree.
using NodeKey = std::tuple<int, double, double, double, double, double, double>;

inline NodeKey keyOf(int depth, const Aabb& b) {
    return {depth, b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z};
}
inline NodeKey keyOfNode(const DynamicOctree& tree, int node) {
    return keyOf(tree.nodeDepth(node), tree.nodeBox(node));
}

inline bool closedContains(const Aabb& outer, const Aabb& inner) {
    for (int a = 0; a < 3; ++a)
        if (!(inner.min[a] >= outer.min[a] && inner.max[a] <= outer.max[a])) return false;
    return true;
}

inline Aabb childBox(const Aabb& box, int octant) {
    Aabb c;
    const glm::dvec3 mid = (box.min + box.max) * 0.5;
    for (int a = 0; a < 3; ++a) {
        const bool high = (octant >> a) & 1;
        c.min[a] = high ? mid[a] : box.min[a];
        c.max[a] = high ? box.max[a] : mid[a];
    }
    return c;
}

// The node `box` belongs in, by the definition in dynamic_octree.h.
inline NodeKey expectedNode(const OctreeParams& params, const Aabb& box) {
    Aabb node = params.bounds;
    int depth = 0;
    if (!closedContains(node, box)) return keyOf(0, node);
    for (;;) {
        const glm::dvec3 e = node.max - node.min;
        if (depth >= params.max_depth || std::max({e.x, e.y, e.z}) * 0.5 < params.min_node_size)
            break;
        int found = -1;
        for (int octant = 0; octant < 8 && found < 0; ++octant)
            if (closedContains(childBox(node, octant), box)) found = octant;
        if (found < 0) break;
        node = childBox(node, found);
        ++depth;
    }
    return keyOf(depth, node);
}

// The whole tree as keys: each object's node, and the set of live nodes.
struct TreeShape {
    std::map<int, NodeKey> node_of_object;
    std::set<NodeKey> nodes;
    bool operator==(const TreeShape& other) const {
        return node_of_object == other.node_of_object && nodes == other.nodes;
    }
};

inline TreeShape shapeOf(const DynamicOctree& tree) {
    TreeShape shape;
    tree.forEachNode([&](int node) {
        shape.nodes.insert(keyOfNode(tree, node));
        for (int object : tree.nodeObjects(node))
            shape.node_of_object[object] = keyOfNode(tree, node);
    });
    return shape;
}

// The invariants of dynamic_octree.h, each a gtest failure naming `what`:
// every object of `boxes` (id -> box) is in the tree, in its expected node, and
// listed by that node; every live node but the root holds an object or a child;
// parent and child links agree, and a child's box is its octant of the parent's;
// the live nodes are exactly those on the paths from the root to the objects.
inline void expectInvariants(const DynamicOctree& tree, const std::map<int, Aabb>& boxes,
                             const std::string& what) {
    SCOPED_TRACE(what);
    ASSERT_EQ(tree.objectCount(), int(boxes.size()));
    std::set<NodeKey> on_paths{keyOf(0, tree.params().bounds)};
    int outside = 0;
    for (const auto& [id, box] : boxes) {
        ASSERT_TRUE(tree.contains(id)) << "object " << id;
        const int node = tree.nodeOf(id);
        EXPECT_TRUE(keyOfNode(tree, node) == expectedNode(tree.params(), box))
            << "object " << id << " is in a node at depth " << tree.nodeDepth(node);
        const bool out = !closedContains(tree.params().bounds, box);
        EXPECT_EQ(tree.isOutside(id), out) << "object " << id;
        outside += out;
        for (int v = node; v != DynamicOctree::kNone; v = tree.nodeParent(v))
            on_paths.insert(keyOfNode(tree, v));
    }
    EXPECT_EQ(tree.outsideCount(), outside);
    int live = 0, listed = 0;
    tree.forEachNode([&](int node) {
        ++live;
        int children = 0;
        for (int octant = 0; octant < 8; ++octant) {
            const int child = tree.nodeChild(node, octant);
            if (child == DynamicOctree::kNone) continue;
            ++children;
            EXPECT_TRUE(tree.isLive(child));
            EXPECT_EQ(tree.nodeParent(child), node);
            EXPECT_EQ(tree.nodeDepth(child), tree.nodeDepth(node) + 1);
            EXPECT_TRUE(keyOfNode(tree, child) ==
                        keyOf(tree.nodeDepth(child), childBox(tree.nodeBox(node), octant)));
        }
        EXPECT_EQ(children, tree.nodeChildCount(node));
        const auto objects = tree.nodeObjects(node);
        int counted = 0;
        for (int object : objects) {
            ++counted;
            EXPECT_EQ(tree.nodeOf(object), node) << "object " << object;
        }
        EXPECT_EQ(counted, objects.size());
        listed += counted;
        if (node != DynamicOctree::kRoot) {
            EXPECT_TRUE(children > 0 || counted > 0)
                << "an empty leaf at depth " << tree.nodeDepth(node);
        }
    });
    EXPECT_EQ(listed, int(boxes.size()));
    EXPECT_EQ(live, tree.nodeCount());
    EXPECT_EQ(size_t(live), on_paths.size());
}

// Random boxes over `root`: sizes from a point to a quarter of the root,
// a share snapped to a grid that the split planes lie on (boxes touching a plane
// from either side), a share of zero thickness on an axis (lying on a plane),
// and a share sticking out of the root.
struct BoxMaker {
    Aabb root;
    double snap = 0.25;  // a step the split planes of the first levels are multiples of

    glm::dvec3 snapped(glm::dvec3 p) const {
        for (int a = 0; a < 3; ++a)
            p[a] = root.min[a] + std::round((p[a] - root.min[a]) / snap) * snap;
        return p;
    }
    Aabb random(SeededRandom& rng) const {
        const glm::dvec3 e = root.max - root.min;
        glm::dvec3 c(0.0), half(0.0);
        for (int a = 0; a < 3; ++a) {
            c[a] = rng.uniform(root.min[a], root.max[a]);
            half[a] = e[a] * 0.125 * std::pow(2.0, -rng.uniform(0.0, 10.0));
        }
        Aabb box{c - half, c + half};
        return shaped(rng, box);
    }
    // A move by about `step` (world units) on each axis.
    Aabb moved(SeededRandom& rng, const Aabb& box, double step) const {
        glm::dvec3 d(0.0);
        for (int a = 0; a < 3; ++a) d[a] = root.max[a] > root.min[a] ? rng.uniform(-step, step) : 0;
        return shaped(rng, box.translated(d));
    }
    Aabb shaped(SeededRandom& rng, Aabb box) const {
        const double kind = rng.uniform();
        if (kind < 0.3) {
            box = {snapped(box.min), snapped(box.max)};
        } else if (kind < 0.4) {
            const int a = int(rng.below(3));
            box.min[a] = box.max[a] = snapped(box.min)[a];
        } else if (kind < 0.43) {
            const int a = int(rng.below(3));
            const double e = root.max[a] - root.min[a];
            box.max[a] += e * 0.5;  // out of the root on that side
        }
        for (int a = 0; a < 3; ++a) {
            if (!(root.max[a] > root.min[a])) box.min[a] = box.max[a] = root.min[a];  // flat root
            if (box.min[a] > box.max[a]) std::swap(box.min[a], box.max[a]);
        }
        return box;
    }
};

}  // namespace gridcull::test
