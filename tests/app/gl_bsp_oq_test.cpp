// BSP culling with occlusion queries on the OpenGL image target
// (`bsp-oq-gl`, `bsp-oq-simple-gl`, `bsp-vfc-gl`): triangle sets drawn by
// ranges, and the three modes culling what a wall hides as on the software
// target, frame after frame while objects move, with the exact oracle's
// visible set in every PVS. Needs a GL context (under xvfb-run when headless).
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/app_cullers.h"
#include "app/gl_image_target.h"
#include "culling/raster/screen_mapping.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/bsp_oq/bsp_random_scenes.h"

namespace gridcull {
namespace {

// A wall with complex objects (each with its own BSP tree) behind it, one
// rising over its top edge as it moves, one in front, one beside.
Scene wallScene() {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 20, 0}, {50, 20, 100}, 60.0);
    test::addBox(scene, 1, {25, 0, 40}, {75, 30, 41});
    SeededRandom rng(11);
    const auto mesh = test::bumpySphereMesh(rng, 3.0, 16, 10, 0.2);
    for (int k = 0; k < 4; ++k) test::addMesh(scene, 10 + k, {35 + 10.0 * k, 14, 60}, mesh);
    test::addMesh(scene, 20, {50, 22, 70}, mesh);  // rises over the wall
    scene.objects.back().motion.kind = MotionKind::Linear;
    scene.objects.back().motion.velocity = {0, 10, 0};
    scene.objects.back().motion.max_speed = 10;
    test::addMesh(scene, 21, {40, 20, 20}, mesh);  // in front
    test::addMesh(scene, 22, {95, 14, 60}, mesh);  // beside
    scene.dt = 0.1;
    scene.frames = 20;
    scene.finalize();
    return scene;
}

TEST(GlBspOq, CullsWhatTheWallHidesAsOnTheSoftwareTarget) {
    const Scene scene = wallScene();
    KnobValues knobs;
    knobs.set("oracle-res", 320);
    knobs.set("bsp-leaf-triangles", test::kBspTestLeafTriangles);
    std::string error;
    auto exact = makeAppCuller("exact", knobs, error);
    ASSERT_TRUE(exact) << error;
    for (const char* algo : {"bsp-oq", "bsp-oq-simple", "bsp-vfc"}) {
        auto gl = makeAppCuller(std::string(algo) + "-gl", knobs, error);
        ASSERT_TRUE(gl) << algo << ": " << error;
        auto software = makeAppCuller(algo, knobs, error);
        ASSERT_TRUE(software) << error;
        gl->reset(scene);
        software->reset(scene);
        exact->reset(scene);
        FrameResult on_gl, on_software, seen;
        bool rose = false;
        for (int frame = 0; frame < scene.frames; ++frame) {
            const double t = scene.timeOfFrame(frame);
            const Camera camera = cameraAt(scene, t);
            gl->cull(scene, camera, t, on_gl);
            software->cull(scene, camera, t, on_software);
            exact->cull(scene, camera, t, seen);
            EXPECT_EQ(on_gl.pvs, on_software.pvs) << algo << " frame " << frame;
            EXPECT_TRUE(test::isSubset(seen.pvs, on_gl.pvs)) << algo << " frame " << frame;
            EXPECT_EQ(on_gl.stats.get(Counter::OcclusionQueries),
                      on_software.stats.get(Counter::OcclusionQueries))
                << algo << " frame " << frame;
            rose = rose || std::binary_search(seen.pvs.begin(), seen.pvs.end(), 20);
            if (std::string(algo) != "bsp-vfc") {
                for (int hidden : {10, 11, 12, 13})
                    EXPECT_FALSE(std::binary_search(on_gl.pvs.begin(), on_gl.pvs.end(), hidden))
                        << algo << " frame " << frame << " object " << hidden;
            }
        }
        EXPECT_TRUE(rose);  // the moving object did come into view
        if (std::string(algo) == "bsp-vfc")
            EXPECT_EQ(on_gl.stats.get(Counter::OcclusionQueries), 0);
        else
            EXPECT_GT(on_gl.stats.get(Counter::OcclusionQueries), 0);
    }
}

// A quad registered as a triangle set, drawn by a range: a query behind it is
// hidden, one in front or beside it visible; the other half of the set, not
// drawn, hides nothing.
TEST(GlBspOq, TriangleSetsDrawTheirRangesOnly) {
    std::string error;
    ASSERT_TRUE(makeAppCuller("bsp-oq-gl", {}, error)) << error;  // the context
    GlImageTarget gl;
    ASSERT_TRUE(gl.init(error)) << error;
    Scene scene = test::scene3d();
    test::setCamera(scene, {0, 0, -20}, {0, 0, 0}, 60.0);
    scene.finalize();
    const Camera camera = cameraAt(scene, 0.0);
    gl.prepare(scene);
    // Two quads side by side at z = 0: left [-6, -1], right [1, 6], y in [-3, 3].
    const std::vector<glm::dvec3> corners{{-6, -3, 0}, {-1, -3, 0}, {-1, 3, 0}, {-6, -3, 0},
                                          {-1, 3, 0},  {-6, 3, 0},  {1, -3, 0}, {6, -3, 0},
                                          {6, 3, 0},   {1, -3, 0},  {6, 3, 0},  {1, 3, 0}};
    const int set = gl.addTriangleSet(corners);
    gl.begin(camera, 160, 120, false);
    ScreenMapping mapping;
    mapping.set(camera, 160, 120);
    PixelRect written;
    const glm::dvec3 shift{0, 0, 5};
    EXPECT_TRUE(gl.drawTriangles(set, 0, 2, 7, shift,
                                 mapping.project(Aabb{{-6, -3, 5}, {-1, 3, 5}}).rect, written));
    const OcclusionQuery behind_left = gl.issueQuery({{-5, -2, 8}, {-2, 2, 9}});
    const OcclusionQuery behind_right = gl.issueQuery({{2, -2, 8}, {5, 2, 9}});
    const OcclusionQuery in_front = gl.issueQuery({{-5, -2, 1}, {-2, 2, 2}});
    EXPECT_FALSE(gl.queryResult(behind_left));
    EXPECT_TRUE(gl.queryResult(behind_right));
    EXPECT_TRUE(gl.queryResult(in_front));
    EXPECT_FALSE(gl.drawTriangles(set, 0, 0, 7, shift, written, written));  // an empty range
    gl.end();
}

}  // namespace
}  // namespace gridcull
