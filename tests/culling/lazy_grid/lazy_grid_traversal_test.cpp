// The front-to-back traversals of Hey et al. section 4, read from the culler's
// snapshot (culling/lazy_grid/lazy_grid_snapshot.h) on seeded random scenes:
//  - occlusion-buffer variant (Fig. 6, lazy-grid and busy-grid): an object is
//    drawn only after every box that it is not wholly in front of has been
//    tested, i.e. every test after a draw is of a box whose znear lies beyond the
//    drawn object's zfar, so nothing drawn can falsely occlude a later box;
//  - z-buffer variant (Fig. 4, lazy-grid-z): boxes are tested in order of znear;
//  - both: an object is drawn only after its own leaf box was tested and found
//    not occluded, each at most once; the PVS is exactly the objects drawn; the
//    deciding test of every culled object was occluded or outside the frustum.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "culling/lazy_grid/lazy_grid_culler.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/lazy_grid/lazy_grid_random_scene.h"

namespace gridcull {
namespace {

void checkTraversal(LazyGridVariant variant, LazyGridUpdate update, uint64_t seed) {
    const Scene scene = test::lazyGridRandomScene(seed);
    LazyGridCuller culler(variant, update, LazyGridOptions{}, 200);
    culler.setDebugCapture(true);
    culler.reset(scene);
    FrameResult result;
    for (int frame = 0; frame < scene.frames; frame += 4) {
        const double t = scene.timeOfFrame(frame);
        culler.cull(scene, cameraAt(scene, t), t, result);
        const LazyGridSnapshot& snap = culler.snapshot();
        ASSERT_TRUE(snap.valid);
        std::vector<char> tested_visible(snap.nodes.size(), 0), drawn(scene.objects.size(), 0);
        std::vector<int> drawn_ids;
        double max_drawn_zfar = -1e300;
        double last_znear = -1e300;
        for (const LazyGridEvent& event : snap.events) {
            if (event.kind == LazyGridEvent::Draw) {
                const int leaf = snap.leaf_of_object[size_t(event.index)];
                EXPECT_TRUE(tested_visible[size_t(leaf)]) << "drawn before its box was tested";
                EXPECT_FALSE(drawn[size_t(event.index)]) << "drawn twice";
                drawn[size_t(event.index)] = 1;
                drawn_ids.push_back(scene.objects[size_t(event.index)].id);
                max_drawn_zfar = std::max(max_drawn_zfar, event.depth);
                continue;
            }
            const LazyGridTest& test = snap.tests[size_t(event.index)];
            if (!test.in_frustum) continue;
            if (variant == LazyGridVariant::OcclusionBuffer) {
                EXPECT_GT(test.box.znear, max_drawn_zfar)
                    << "a box was tested after an object not wholly in front of it was drawn";
            } else {
                EXPECT_GE(test.box.znear, last_znear) << "Fig. 4 tests in order of znear";
                last_znear = test.box.znear;
            }
            if (!test.occluded) tested_visible[size_t(test.node)] = 1;
        }
        std::sort(drawn_ids.begin(), drawn_ids.end());
        EXPECT_EQ(drawn_ids, result.pvs);
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            const LazyGridTest* decider = decidingTest(snap, int(i));
            if (drawn[i]) {
                ASSERT_NE(decider, nullptr);
                EXPECT_FALSE(decider->occluded);
            } else if (decider) {
                EXPECT_TRUE(decider->occluded || !decider->in_frustum);
            }
        }
    }
}

TEST(LazyGridTraversal, Fig6DrawsAnObjectOnlyAfterTestingEveryBoxNotWhollyBehindIt) {
    for (uint64_t seed : test::seedsToRun(1, 80)) {
        test::withSeed(seed, [&] {
            checkTraversal(LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Lazy, seed);
            checkTraversal(LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Busy, seed);
            checkTraversal(LazyGridVariant::OcclusionBuffer, LazyGridUpdate::BusyTight, seed);
        });
    }
}

TEST(LazyGridTraversal, Fig4TestsBoxesInOrderOfZnear) {
    for (uint64_t seed : test::seedsToRun(1, 80)) {
        test::withSeed(
            seed, [&] { checkTraversal(LazyGridVariant::ZBuffer, LazyGridUpdate::Lazy, seed); });
    }
}

// A hand-made case: a wall in front hides a row of spheres; one sphere peeks
// over the wall's top edge by a little, one stands beside it. The lazy grid must
// cull the hidden ones and keep the other two, in both variants.
TEST(LazyGridTraversal, AWallHidesWhatIsBehindItAndNothingThatPeeksOver) {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 20, 0}, {50, 20, 100}, 60.0);
    test::addBox(scene, 1, {30, 0, 30}, {70, 30, 31});  // the wall, top edge at y = 30
    // Behind it: sight lines over its edge reach y = 40 at z = 60, past its sides x < 10
    // and x > 90.
    for (int k = 0; k < 5; ++k) test::addSphere(scene, 10 + k, {35 + 7.5 * k, 15, 60}, 3);
    test::addSphere(scene, 20, {50, 38, 60}, 3.2);  // top at 41.2: over the wall's edge
    test::addSphere(scene, 21, {100, 15, 60}, 3);   // beside the wall
    scene.finalize();
    for (const char* name : {"lazy-grid", "lazy-grid-z", "busy-grid", "busy-grid-tight"}) {
        auto culler = test::makeOrDie(name);
        EXPECT_EQ(test::cullIds(*culler, scene), (std::vector<int>{1, 20, 21})) << name;
    }
    auto oracle = test::makeOrDie("exact");
    EXPECT_EQ(test::cullIds(*oracle, scene), (std::vector<int>{1, 20, 21}));
}

}  // namespace
}  // namespace gridcull
