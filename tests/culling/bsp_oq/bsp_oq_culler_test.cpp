// The frame of BSP culling with occlusion queries (culling/bsp_oq/
// bsp_oq_culler.h) on its own: Algorithm 3's skip counter, Algorithm 2's
// batches of non-overlapping rectangles, what each mode queries, and a second
// pass over a scene allocating nothing.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/bsp_oq/bsp_oq_culler.h"
#include "culling/io/scene_loader.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/allocation_counter.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/bsp_oq/bsp_random_scenes.h"

namespace gridcull {
namespace {

constexpr int kResolution = 256;
// A steady view's queries a frame, peak over mean: all nodes due together give
// a peak of about the skip (8) times the mean; spread, a few times it at most.
constexpr double kBunchedPeak = 5.0;
constexpr double kSpreadPeak = 3.0;

BspOqOptions testOptions() {
    BspOqOptions options;
    options.leaf_triangles = test::kBspTestLeafTriangles;
    return options;
}

// Figure 3's count alone, as the model below computes it.
BspOqOptions unspreadOptions() {
    BspOqOptions options = testOptions();
    options.skip_spread = 0;
    return options;
}

TEST(BspSkipFrames, CountsTheVisibleAnswersAmongTheLastN) {
    EXPECT_EQ(bspSkipFrames(0b1011u, 8), 3);
    EXPECT_EQ(bspSkipFrames(0xFFFFFFFFu, 8), 8);
    EXPECT_EQ(bspSkipFrames(0xFFFFFFFFu, 32), 32);
    EXPECT_EQ(bspSkipFrames(0b1110u, 2), 1);  // only the last two answers count
    EXPECT_EQ(bspSkipFrames(0xFFFFFFFFu, 0), 0);
    EXPECT_EQ(bspSkipFrames(0u, 8), 0);
}

// A wall, a complex object in front of it in view, and one behind it.
Scene wallScene() {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 20, 0}, {50, 20, 100}, 60.0);
    test::addBox(scene, 1, {20, 0, 40}, {80, 40, 41});
    SeededRandom rng(7);
    const auto mesh = test::bumpySphereMesh(rng, 4.0, 16, 10, 0.2);
    test::addMesh(scene, 2, {35, 20, 25}, mesh);  // in front of the wall
    test::addMesh(scene, 3, {50, 20, 70}, mesh);  // behind it
    scene.dt = 0.1;
    scene.frames = 40;
    scene.finalize();
    return scene;
}

// Algorithm 3 with Figure 3's rule, written out for a node that is in view
// and visible every frame: queried while it was not visible the frame before,
// then skipped for as many frames as its last `history` answers were visible.
TEST(BspOqCuller, SkipCounterFollowsAlgorithm3) {
    const Scene scene = wallScene();
    BspOqCuller culler("bsp-oq", BspOqMode::Full, unspreadOptions(), kResolution);
    culler.setDebugCapture(true);
    culler.reset(scene);
    ASSERT_NE(culler.objectTree(1), nullptr);
    ASSERT_NE(culler.objectTree(2), nullptr);
    FrameResult out;
    uint32_t answers = 0;
    int skip = 0;
    bool visible_last = false;
    int queries = 0;
    for (int frame = 0; frame < scene.frames; ++frame) {
        const double t = scene.timeOfFrame(frame);
        culler.cull(scene, cameraAt(scene, t), t, out);
        const BspOqSnapshot& snap = culler.snapshot();
        // The model.
        BspNodeState want;
        if (!visible_last || skip == 0) {
            answers = (answers << 1) | 1u;
            skip = __builtin_popcount(answers & 0xFFu);
            want = BspNodeState::QueriedVisible;
            ++queries;
        } else {
            --skip;
            want = BspNodeState::AssumedVisible;
        }
        visible_last = true;
        // The front object's tree root follows it.
        ASSERT_GE(snap.object_first[1], 0) << "frame " << frame;
        const BspNodeRecord& front = snap.object_nodes[size_t(snap.object_first[1])];
        EXPECT_EQ(front.state, want) << "frame " << frame;
        EXPECT_EQ(front.skip, skip) << "frame " << frame;
        // The hidden object's root is queried every frame and stays hidden.
        ASSERT_GE(snap.object_first[2], 0) << "frame " << frame;
        const BspNodeRecord& back = snap.object_nodes[size_t(snap.object_first[2])];
        EXPECT_EQ(back.state, BspNodeState::QueriedHidden) << "frame " << frame;
        EXPECT_EQ(back.skip, 0);
        EXPECT_EQ(back.history & 0xFFu, 0u);
        EXPECT_EQ(out.pvs, (std::vector<int>{1, 2})) << "frame " << frame;
    }
    // 1, 2, ... 8 frames skipped after each query, then 8: queries at frames
    // 0, 2, 5, 9, 14, 20, 27, 35 of 40.
    EXPECT_EQ(queries, 8);
}

TEST(BspSpreadSkip, LengthensBetweenNothingAndHalfAndVariesWithTheKey) {
    EXPECT_EQ(bspSpreadSkip(0, 12345), 0);
    EXPECT_EQ(bspSpreadSkip(1, 12345), 1);  // half of 1 is 0
    std::vector<int> seen(13, 0);
    for (uint64_t key = 0; key < 1000; ++key) {
        const int skip = bspSpreadSkip(8, key);
        ASSERT_GE(skip, 8);
        ASSERT_LE(skip, 12);
        ++seen[size_t(skip)];
    }
    for (int skip = 8; skip <= 12; ++skip) EXPECT_GT(seen[size_t(skip)], 120) << skip;
}

// A static view of many objects that all turn visible in the first frame: with
// Figure 3's count alone their queries come due together (frames 0, 2, 5, 9,
// ...), with the spread they spread over the frames between.
TEST(BspOqCuller, SpreadSkipsDoNotBunchTheQueries) {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 50, -40}, {50, 50, 50}, 60.0);
    SeededRandom rng(5);
    const auto mesh = test::bumpySphereMesh(rng, 2.5, 16, 10, 0.2);
    int id = 0;
    for (int x = 0; x < 8; ++x)
        for (int y = 0; y < 6; ++y) test::addMesh(scene, id++, {15 + 10.0 * x, 25 + 10.0 * y, 50}, mesh);
    scene.dt = 0.1;
    scene.frames = 80;
    scene.finalize();
    auto peakOverMean = [&](const BspOqOptions& options) {
        BspOqCuller culler("bsp-oq", BspOqMode::Full, options, kResolution);
        culler.reset(scene);
        FrameResult out;
        int64_t total = 0, peak = 0;
        for (int frame = 0; frame < scene.frames; ++frame) {
            const double t = scene.timeOfFrame(frame);
            culler.cull(scene, cameraAt(scene, t), t, out);
            EXPECT_EQ(int(out.pvs.size()), id);
            if (frame < 20) continue;  // past the start, where every node is new
            total += out.stats.get(Counter::OcclusionQueries);
            peak = std::max(peak, out.stats.get(Counter::OcclusionQueries));
        }
        return double(peak) / (double(total) / (scene.frames - 20));
    };
    const double bunched = peakOverMean(unspreadOptions());
    const double spread = peakOverMean(testOptions());
    std::printf("[bsp spread] queries a frame, peak / mean: %.2f alone, %.2f spread\n", bunched,
                spread);
    EXPECT_GT(bunched, kBunchedPeak);
    EXPECT_LT(spread, kSpreadPeak);
}

// With no history, a visible node is queried every frame.
TEST(BspOqCuller, NoHistoryQueriesEveryFrame) {
    const Scene scene = wallScene();
    BspOqOptions options = testOptions();
    options.history = 0;
    BspOqCuller culler("bsp-oq", BspOqMode::Full, options, kResolution);
    culler.setDebugCapture(true);
    culler.reset(scene);
    FrameResult out;
    for (int frame = 0; frame < 10; ++frame) {
        const double t = scene.timeOfFrame(frame);
        culler.cull(scene, cameraAt(scene, t), t, out);
        const BspOqSnapshot& snap = culler.snapshot();
        EXPECT_EQ(snap.object_nodes[size_t(snap.object_first[1])].state,
                  BspNodeState::QueriedVisible);
        EXPECT_EQ(out.stats.get(Counter::CoherenceSkips), 0);
    }
}

struct BatchTotals {
    int64_t queries = 0, batches = 0, largest = 0;
};

// Runs `mode` over random scenes with capture on and checks every batch.
void checkBatches(BspOqMode mode, int batch, BatchTotals& totals) {
    for (uint64_t seed = 1; seed <= 12; ++seed) {
        const Scene scene = test::bspRandomScene(seed);
        BspOqOptions options = testOptions();
        options.batch = batch;
        BspOqCuller culler("bsp", mode, options, kResolution);
        culler.setDebugCapture(true);
        culler.reset(scene);
        FrameResult out;
        for (int frame = 0; frame < scene.frames; ++frame) {
            const double t = scene.timeOfFrame(frame);
            culler.cull(scene, cameraAt(scene, t), t, out);
            const BspOqSnapshot& snap = culler.snapshot();
            ASSERT_EQ(int64_t(snap.queries.size()), out.stats.get(Counter::OcclusionQueries));
            ASSERT_EQ(snap.batch_count, out.stats.get(Counter::QueryBatches));
            std::vector<int> size(size_t(snap.batch_count), 0);
            for (size_t a = 0; a < snap.queries.size(); ++a) {
                const BspQueryRecord& qa = snap.queries[a];
                ASSERT_GE(qa.batch, 0);
                ASSERT_LT(qa.batch, snap.batch_count);
                ++size[size_t(qa.batch)];
                ASSERT_GE(qa.record, 0) << "a query without its node";
                for (size_t b = a + 1; b < snap.queries.size(); ++b) {
                    const BspQueryRecord& qb = snap.queries[b];
                    if (qa.batch != qb.batch) continue;
                    EXPECT_TRUE(qa.rect.intersect(qb.rect).empty())
                        << "seed " << seed << " frame " << frame << " batch " << qa.batch
                        << ": rectangles " << a << " and " << b << " overlap";
                }
            }
            for (int s : size) {
                EXPECT_GE(s, 1);
                EXPECT_LE(s, batch);
                totals.largest = std::max<int64_t>(totals.largest, s);
            }
            totals.queries += int64_t(snap.queries.size());
            totals.batches += snap.batch_count;
        }
    }
}

TEST(BspOqCuller, BatchedRectanglesNeverOverlap) {
    for (const int batch : {4, 64}) {
        BatchTotals totals;
        checkBatches(BspOqMode::Full, batch, totals);
        std::printf("[bsp batches] limit %d: %lld queries in %lld batches, the largest %lld\n",
                    batch, (long long)totals.queries, (long long)totals.batches,
                    (long long)totals.largest);
        // Not vacuous: batches of several queries happen, full ones too.
        EXPECT_GT(totals.queries, totals.batches + totals.batches / 4) << "batch " << batch;
        if (batch == 4) {
            EXPECT_EQ(totals.largest, 4);
        }
    }
}

TEST(BspOqCuller, SimpleOcIssuesOneQueryAtATimeAndVfcNone) {
    BatchTotals simple;
    checkBatches(BspOqMode::Simple, 64, simple);
    EXPECT_GT(simple.queries, 0);
    EXPECT_EQ(simple.queries, simple.batches);
    BatchTotals vfc;
    checkBatches(BspOqMode::Vfc, 64, vfc);
    EXPECT_EQ(vfc.queries, 0);
}

// Full skips queries that Simple OC issues, on the same frames, and draws no
// more parts than VFC only.
TEST(BspOqCuller, FullQueriesLessThanSimpleOcAndDrawsLessThanVfc) {
    int64_t full_queries = 0, simple_queries = 0, full_parts = 0, vfc_parts = 0;
    for (uint64_t seed = 1; seed <= 12; ++seed) {
        const Scene scene = test::bspRandomScene(seed);
        BspOqCuller full("bsp-oq", BspOqMode::Full, testOptions(), kResolution);
        BspOqCuller simple("bsp-oq-simple", BspOqMode::Simple, testOptions(), kResolution);
        BspOqCuller vfc("bsp-vfc", BspOqMode::Vfc, testOptions(), kResolution);
        full.reset(scene);
        simple.reset(scene);
        vfc.reset(scene);
        FrameResult a, b, c;
        for (int frame = 0; frame < scene.frames; ++frame) {
            const double t = scene.timeOfFrame(frame);
            const Camera camera = cameraAt(scene, t);
            full.cull(scene, camera, t, a);
            simple.cull(scene, camera, t, b);
            vfc.cull(scene, camera, t, c);
            full_queries += a.stats.get(Counter::OcclusionQueries);
            simple_queries += b.stats.get(Counter::OcclusionQueries);
            full_parts += a.stats.get(Counter::PartsDrawn);
            vfc_parts += c.stats.get(Counter::PartsDrawn);
            EXPECT_TRUE(test::isSubset(a.pvs, c.pvs)) << "seed " << seed << " frame " << frame;
        }
    }
    EXPECT_LT(full_queries, simple_queries);
    EXPECT_LT(full_parts, vfc_parts);
}

long secondPassAllocations(const std::string& algo, const Scene& scene, int frames) {
    KnobValues knobs;
    knobs.set("oracle-res", kResolution);
    knobs.set("bsp-leaf-triangles", test::kBspTestLeafTriangles);
    auto culler = test::makeOrDie(algo, knobs);
    FrameResult result;
    result.pvs.reserve(scene.objects.size());
    long allocations = 0;
    for (int pass = 0; pass < 2; ++pass) {
        culler->reset(scene);
        for (int frame = 0; frame < frames; ++frame) {
            const double t = scene.timeOfFrame(frame);
            const Camera camera = cameraAt(scene, t);
            if (pass == 1) test::startCounting();
            culler->cull(scene, camera, t, result);
            test::stopCounting();
            if (pass == 1) allocations += test::allocationCount();
        }
    }
    return allocations;
}

TEST(BspOqAllocation, SecondPassOverRandomScenesAllocatesNothing) {
    for (const char* algo : {"bsp-oq", "bsp-oq-simple", "bsp-vfc"})
        for (uint64_t seed = 1; seed <= 6; ++seed) {
            const Scene scene = test::bspRandomScene(seed);
            EXPECT_EQ(secondPassAllocations(algo, scene, scene.frames), 0)
                << algo << " seed " << seed;
        }
}

TEST(BspOqAllocation, SecondPassOverTheBunniesAllocatesNothing) {
    const SceneLoadResult loaded =
        loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/bunnies-3d.json");
    ASSERT_TRUE(loaded.scene.has_value());
    EXPECT_EQ(secondPassAllocations("bsp-oq", *loaded.scene, 20), 0);
}

}  // namespace
}  // namespace gridcull
