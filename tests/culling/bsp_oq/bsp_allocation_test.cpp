// "Hot per-frame paths do not allocate" (docs/CONVENTIONS.md) for Kovalčík &
// Sochor's structures (culling/bsp_oq/): the scene tree's relinking, lazy
// reconstruction and traversal, and the object tree's traversal. The scene
// tree's node pool grows to its high-water mark in a first pass over
// precomputed frames; a second pass over the same frames, after build() on the
// same boxes (which keeps the memory), allocates nothing. Counted by
// tests/common/allocation_counter.h (core_tests replaces operator new in
// tests/culling/counting_new.cpp).
#include <vector>

#include <gtest/gtest.h>

#include "culling/bsp_oq/object_bsp.h"
#include "culling/bsp_oq/scene_bsp.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/allocation_counter.h"

namespace gridcull {
namespace {

const Aabb kWorld{{0, 0, 0}, {64, 64, 64}};

std::vector<std::vector<Aabb>> randomFrames(uint64_t seed, int objects, int frames) {
    SeededRandom rng(seed);
    std::vector<Aabb> boxes;
    for (int i = 0; i < objects; ++i) {
        glm::dvec3 c;
        for (int a = 0; a < 3; ++a) c[a] = rng.uniform(2, 62);
        boxes.push_back({c - glm::dvec3(0.5), c + glm::dvec3(0.5)});
    }
    std::vector<std::vector<Aabb>> out{boxes};
    for (int f = 1; f < frames; ++f) {
        for (Aabb& box : boxes) {
            const uint64_t r = rng.below(10);
            if (r < 6) box = box.translated(0.7 * randomDirection(rng, 3));
            if (r == 6) box = box.translated(-0.2 * box.min);  // drift to the corner: rebuilds
            if (r == 7) box = box.translated({100, 0, 0});     // out of the world
            if (r == 8 && box.min.x > 64) box = box.translated({-100, 0, 0});
        }
        out.push_back(boxes);
    }
    return out;
}

TEST(SceneBspAllocation, SecondPassOfUpdatesAndTraversalsAllocatesNothing) {
    const std::vector<std::vector<Aabb>> frames = randomFrames(3, 400, 60);
    SceneBspParams params;
    params.world = kWorld;
    params.max_node_objects = 3;
    params.rebuild_delay_frames = 2;
    SceneBsp tree;
    long allocations = 0;
    int rebuilt = 0;
    for (int pass = 0; pass < 2; ++pass) {
        tree.build(params, frames[0]);
        for (int f = 1; f < int(frames.size()); ++f) {
            long visited = 0;
            if (pass == 1) test::startCounting();
            rebuilt += tree.update(frames[size_t(f)], f).subtrees_rebuilt;
            tree.traverseFrontToBack(
                {f, 30, 70},
                [&](const SceneBspNodeView&) {
                    ++visited;
                    return true;
                },
                [&](int) { ++visited; });
            test::stopCounting();
            if (pass == 1) allocations += test::allocationCount();
            EXPECT_GT(visited, 0);
        }
    }
    EXPECT_GT(rebuilt, 0) << "the frames should exercise the lazy reconstruction";
    EXPECT_EQ(allocations, 0);
}

TEST(ObjectBspAllocation, TraversalAllocatesNothing) {
    SeededRandom rng(1);
    TriangleMesh mesh;
    for (int t = 0; t < 2000; ++t)
        for (int k = 0; k < 3; ++k) {
            mesh.vertices.push_back({rng.uniform(0, 10), rng.uniform(0, 10), rng.uniform(0, 10)});
            mesh.indices.push_back(uint32_t(mesh.vertices.size() - 1));
        }
    ObjectBspParams params;
    params.max_leaf_triangles = 8;
    const ObjectBsp bsp(mesh, params);
    int visited = 0;
    test::startCounting();
    bsp.traverseFrontToBack({-3, 4, 20}, {1, 2, 3}, [&](const ObjectBspNodeView& v) {
        ++visited;
        return v.piece_count > 0;
    });
    test::stopCounting();
    EXPECT_EQ(test::allocationCount(), 0);
    EXPECT_EQ(visited, bsp.nodeCount());
}

}  // namespace
}  // namespace gridcull
