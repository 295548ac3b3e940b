// bsp-oq's query boxes against a surface drawn on their own face (culling/
// bsp_oq/bsp_oq_culler.h, "query boxes grown"): two boxes whose front faces
// lie in one plane tie in depth at every pixel the nearer of them covers, and
// the oracle credits such a pixel to the one it draws first. A node queried on
// the box of its objects (the shrunk box) has that very face: without the
// margin, the strict depth test of its query fails wherever the other box was
// drawn first, and the object the oracle sees is dropped. This is what the
// long sweep found in three rooms scenes, where walls overlap at the corners.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "culling/bsp_oq/bsp_oq_culler.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

constexpr int kResolution = 160;
constexpr int kWall = 1, kFlush = 2;

// A wall across the whole world (it straddles every split, so it sits at the
// root and is drawn before any child is queried), and behind it, in a child
// node of their own, a box whose front face is flush with the wall's and
// another box out of sight. Seen straight on, both are as near as can be at
// the same depth and the flush box comes first in the scene, so the oracle
// (nearest first, then by index) draws it before the wall.
Scene flushScene() {
    Scene scene = test::makeScene(3, {{0, 0, 0}, {200, 100, 100}}, {20, 10, 10});
    test::addBox(scene, kFlush, {5, 40, 40}, {15, 50, 45});
    test::addBox(scene, 3, {28, 40, 60}, {32, 50, 65});  // behind the wall
    test::addBox(scene, 4, {33, 40, 60}, {37, 50, 65});  // behind it, straddles the split
    test::addBox(scene, kWall, {0, 0, 40}, {200, 100, 41});
    test::setCamera(scene, {40, 45, 1}, {40, 45, 40}, 90.0);  // straight down +z
    scene.dt = 0.1;
    scene.frames = 20;
    scene.finalize();
    return scene;
}

TEST(BspOqCuller, KeepsABoxFlushWithAWallDrawnBeforeIt) {
    const Scene scene = flushScene();
    BspOqOptions options;
    options.node_objects = 2;  // the flush box and its neighbour in a child of the root
    BspOqCuller culler("bsp-oq", BspOqMode::Full, options, kResolution);
    KnobValues knobs;
    knobs.set("oracle-res", kResolution);
    auto exact = test::makeOrDie("exact", knobs);
    culler.setDebugCapture(true);
    culler.reset(scene);
    exact->reset(scene);
    const int flush = scene.indexOf(kFlush), wall = scene.indexOf(kWall);
    FrameResult got, want;
    int seen = 0, shrunk_queries = 0;
    for (int frame = 0; frame < scene.frames; ++frame) {
        const double t = scene.timeOfFrame(frame);
        culler.cull(scene, cameraAt(scene, t), t, got);
        exact->cull(scene, cameraAt(scene, t), t, want);
        // The set-up: the wall at the root, the flush box below it.
        const SceneBsp& tree = culler.sceneTree();
        ASSERT_EQ(tree.nodeOf(wall), SceneBsp::kRoot);
        ASSERT_NE(tree.nodeOf(flush), SceneBsp::kRoot);
        if (!std::binary_search(want.pvs.begin(), want.pvs.end(), kFlush)) continue;
        ++seen;
        EXPECT_TRUE(std::binary_search(got.pvs.begin(), got.pvs.end(), kFlush))
            << "frame " << frame << ": the oracle sees the flush box, bsp-oq dropped it";
        for (const BspNodeRecord& r : culler.snapshot().scene_nodes)
            shrunk_queries += r.node == tree.nodeOf(flush) && r.shrunk && r.query >= 0;
    }
    // Not vacuous: the oracle sees the box (through the tie alone: the wall
    // hides everything behind its face), and its node was queried on its
    // shrunk box.
    EXPECT_EQ(seen, scene.frames);
    EXPECT_GT(shrunk_queries, 0);
}

}  // namespace
}  // namespace gridcull
