// The OpenGL image target (app/gl_image_target.h) behind the -gl algorithms of
// app/app_cullers.h: the lazy grids on it cull as on the software target on a
// scene whose answer is plain, the read-back queries themselves, and the
// occlusion queries (GL_ANY_SAMPLES_PASSED) against the software target's on
// seeded random scenes. Needs a GL context (the test run provides an X display,
// under xvfb-run when headless).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "app/app_cullers.h"
#include "app/gl_image_target.h"
#include "culling/raster/screen_mapping.h"
#include "culling/raster/software_image_target.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/common/test_seeds.h"

namespace gridcull {
namespace {

// The wall of tests/culling/lazy_grid/lazy_grid_traversal_test.cpp.
Scene wallScene() { return test::sphereWallScene(); }

TEST(GlImageTarget, LazyGridsCullWhatTheWallHidesLikeOnTheSoftwareTarget) {
    const Scene scene = wallScene();
    KnobValues options;
    options.set("oracle-res", 320);
    for (const char* name :
         {"lazy-grid-gl", "lazy-grid-z-gl", "busy-grid-gl", "busy-grid-tight-gl"}) {
        std::string error;
        auto culler = makeAppCuller(name, options, error);
        ASSERT_TRUE(culler) << name << ": " << error;
        EXPECT_EQ(std::string(culler->name()), name);
        culler->reset(scene);
        FrameResult result;
        culler->cull(scene, cameraAt(scene, 0.0), 0.0, result);
        EXPECT_EQ(result.pvs, (std::vector<int>{1, 20, 21})) << name;
        EXPECT_GT(result.stats.get(Counter::PixelQueries), 0) << name;
    }
}

TEST(GlImageTarget, ReadBackQueriesSeeWhatWasDrawn) {
    std::string error;
    ASSERT_TRUE(makeAppCuller("lazy-grid-gl", {}, error)) << error;  // the context
    GlImageTarget target;
    ASSERT_TRUE(target.init(error)) << error;
    Camera camera;
    camera.position = {0, 0, 0};
    camera.target = {0, 0, 1};
    camera.fov_deg = 90.0;
    camera.aspect = 2.0;
    camera.near = 0.5;
    camera.far = 100.0;
    Scene empty;
    target.prepare(empty);
    target.begin(camera, 64, 32, true);
    const PixelRect all{0, 0, 63, 31};
    EXPECT_EQ(target.countFree(all), 64 * 32);
    EXPECT_TRUE(std::isinf(target.farthestDepth(all)));
    // A wall at depth 10 across the image's left half (world +x is the image's left).
    Scene scene = test::scene3d();
    test::addBox(scene, 0, {0, -50, 10}, {50, 50, 11});
    const SceneObject& wall = scene.objects[0];
    ScreenMapping mapping;
    mapping.set(camera, 64, 32);
    PixelRect written;
    ASSERT_TRUE(target.draw(wall, 0, {0, 0, 0}, mapping.project(wall.box).rect, written));
    target.end();
    EXPECT_EQ(target.countFree({0, 0, 30, 31}), 0);
    EXPECT_EQ(target.countFree({33, 0, 63, 31}), 31 * 32);
    const double depth = target.farthestDepth({0, 0, 30, 31});
    EXPECT_GE(depth, 10.0);  // never nearer than drawn
    EXPECT_LT(depth, 10.05);
}

// The GL target's occlusion queries against the software target's. Both sample
// the same pixel centres, so they differ only where an answer rests on less
// than OpenGL's own error, which the test bounds from above:
//  - spheres are drawn as a 32 x 16 latitude-longitude mesh inscribed in the
//    sphere: every facet lies between the sphere and the concentric sphere of
//    radius cos(half the facet's angular diagonal) = cos(pi/16 * sqrt(2)/2) =
//    0.9904 of it (a facet's corners are on a circle of that angular radius);
//    kFacetInnerRadius leaves a margin below;
//  - boxes, cubes and the camera go through 32-bit floats and the depth buffer
//    has 24 bits: at these coordinates (<= ~60 world units) and depths (<= 40,
//    near 0.5, far 100) that moves a surface by < 1e-4 units (a depth step is
//    z^2 (far - near) / (far near) 2^-24 <= 2e-4 at z = 40, float rounding ~1e-5
//    relative); kGlSlack is 50 times that.
// A query is decided when the software target answers it alike with every
// occluder at its largest (spheres at full radius, boxes grown by kGlSlack) and
// the query box shrunk by kGlSlack, and with every occluder at its smallest
// (spheres at kFacetInnerRadius, boxes shrunk) and the box grown: then GL must
// give that answer. The rest are marginal (GL may say either); the test prints
// how many there are and how often GL differs on them, and bounds their share.
constexpr double kFacetInnerRadius = 0.985;
constexpr double kGlSlack = 5e-3;
constexpr double kMaxMarginalShare = 0.05;

struct QueryScene {
    Camera camera;
    Scene nominal = test::scene3d(), largest = test::scene3d(), smallest = test::scene3d();
    std::vector<Aabb> queries;
};

glm::dvec3 atView(const Camera& camera, double x, double y, double z) {
    glm::dvec3 right, up, forward;
    camera.basis(right, up, forward);
    return camera.position + x * right + y * up + z * forward;
}

Aabb grown(const Aabb& box, double by) {
    return {box.min - glm::dvec3(by), box.max + glm::dvec3(by)};
}

QueryScene queryScene(uint64_t seed) {
    QueryScene s;
    s.camera.position = {1.0, 2.0, 3.0};
    s.camera.target = {1.4, 2.3, 13.0};
    s.camera.fov_deg = 60.0;
    s.camera.aspect = 1.5;
    s.camera.near = 0.5;
    s.camera.far = 100.0;
    SeededRandom rng(seed, 5);
    auto place = [&](double z_lo, double z_hi) {
        const double z = rng.uniform(z_lo, z_hi);
        const double spread = 0.7 * z;
        return atView(s.camera, rng.uniform(-spread, spread), rng.uniform(-spread, spread), z);
    };
    // Occluders wholly beyond the near plane (the targets clip differently there).
    for (int k = 0; k < 24; ++k) {
        const glm::dvec3 c = place(4.0, 30.0);
        if (rng.below(2)) {
            const double r = rng.uniform(0.4, 2.5);
            test::addSphere(s.nominal, k, c, r);
            test::addSphere(s.largest, k, c, r);
            test::addSphere(s.smallest, k, c, r * kFacetInnerRadius);
        } else {
            const glm::dvec3 half{rng.uniform(0.3, 2.0), rng.uniform(0.3, 2.0),
                                  rng.uniform(0.3, 2.0)};
            test::addBox(s.nominal, k, c - half, c + half);
            test::addBox(s.largest, k, c - half - kGlSlack, c + half + kGlSlack);
            test::addBox(s.smallest, k, c - half + kGlSlack, c + half - kGlSlack);
        }
    }
    for (int q = 0; q < 60; ++q) {
        const glm::dvec3 c = q % 12 == 0 ? place(-0.5, 1.0) : place(2.0, 40.0);
        const glm::dvec3 half{rng.uniform(0.1, 3.0), rng.uniform(0.1, 3.0), rng.uniform(0.1, 3.0)};
        s.queries.push_back({c - half, c + half});
    }
    return s;
}

// Every query issued at once after the scene, then read back in order.
std::vector<bool> answers(ImageTarget& target, const Camera& camera, const Scene& scene,
                          const std::vector<Aabb>& queries, double query_growth, int width,
                          int height) {
    target.prepare(scene);
    target.begin(camera, width, height, false);
    ScreenMapping mapping;
    mapping.set(camera, width, height);
    PixelRect written;
    for (size_t k = 0; k < scene.objects.size(); ++k) {
        const SceneObject& object = scene.objects[k];
        target.draw(object, int(k), {0, 0, 0}, mapping.project(object.bounds).rect, written);
    }
    std::vector<OcclusionQuery> ids;
    for (const Aabb& box : queries) ids.push_back(target.issueQuery(grown(box, query_growth)));
    std::vector<bool> visible;
    for (const OcclusionQuery& id : ids) visible.push_back(target.queryResult(id));
    target.end();
    return visible;
}

TEST(GlImageTarget, OcclusionQueriesAnswerAsTheSoftwareTargetDoes) {
    std::string error;
    ASSERT_TRUE(makeAppCuller("lazy-grid-gl", {}, error)) << error;  // the context
    GlImageTarget gl;
    ASSERT_TRUE(gl.init(error)) << error;
    EXPECT_EQ(gl.queryLatencyFrames(), 0);
    constexpr int kWidth = 144, kHeight = 96;
    long long decided_visible = 0, decided_hidden = 0, marginal = 0, marginal_differ = 0;
    for (uint64_t seed : test::seedsToRun(1, 32)) {
        test::withSeed(seed, [&] {
            const QueryScene s = queryScene(seed);
            SoftwareImageTarget software;
            const std::vector<bool> nominal =
                answers(software, s.camera, s.nominal, s.queries, 0.0, kWidth, kHeight);
            const std::vector<bool> low =
                answers(software, s.camera, s.largest, s.queries, -kGlSlack, kWidth, kHeight);
            const std::vector<bool> high =
                answers(software, s.camera, s.smallest, s.queries, kGlSlack, kWidth, kHeight);
            const std::vector<bool> on_gl =
                answers(gl, s.camera, s.nominal, s.queries, 0.0, kWidth, kHeight);
            EXPECT_EQ(gl.queryCounts().issued, long(s.queries.size()));
            EXPECT_EQ(gl.queryCounts().read, long(s.queries.size()));
            EXPECT_EQ(gl.outstandingQueries(), 0);
            for (size_t q = 0; q < s.queries.size(); ++q) {
                if (low[q] == high[q]) {
                    EXPECT_EQ(nominal[q], low[q]) << "query " << q;  // monotone in size
                    EXPECT_EQ(on_gl[q], low[q]) << "query " << q;
                    (low[q] ? decided_visible : decided_hidden)++;
                } else {
                    ++marginal;
                    if (on_gl[q] != nominal[q]) ++marginal_differ;
                }
            }
        });
    }
    if (!test::singleSeedRun()) {
        std::printf(
            "[gl occlusion queries] %lld decided visible, %lld decided hidden (all equal to the "
            "software target's); %lld marginal, of which GL answered %lld otherwise\n",
            decided_visible, decided_hidden, marginal, marginal_differ);
        EXPECT_GT(decided_visible, 200);
        EXPECT_GT(decided_hidden, 200);
        EXPECT_LE(double(marginal), kMaxMarginalShare * double(decided_visible + decided_hidden));
    }
}

// Several outstanding GL queries, polled until available, and a pool that grows.
TEST(GlImageTarget, OcclusionQueriesPollAndGrowThePool) {
    std::string error;
    ASSERT_TRUE(makeAppCuller("lazy-grid-gl", {}, error)) << error;  // the context
    GlImageTarget gl;
    ASSERT_TRUE(gl.init(error)) << error;
    const QueryScene s = queryScene(99);
    const int n = kOcclusionQueryReserve + 10;
    std::vector<Aabb> boxes;
    for (int q = 0; q < n; ++q) boxes.push_back(s.queries[size_t(q) % s.queries.size()]);
    // The software answers over the empty image, decided as above.
    SoftwareImageTarget software;
    const Scene empty = test::scene3d();
    const std::vector<bool> low = answers(software, s.camera, empty, boxes, -kGlSlack, 64, 48);
    const std::vector<bool> high = answers(software, s.camera, empty, boxes, kGlSlack, 64, 48);
    gl.prepare(s.nominal);
    gl.begin(s.camera, 64, 48, false);
    std::vector<OcclusionQuery> ids;
    for (const Aabb& box : boxes) ids.push_back(gl.issueQuery(box));
    EXPECT_EQ(gl.outstandingQueries(), n);
    for (int spins = 0; spins < 1000000 && !gl.queryAvailable(ids.back()); ++spins) {
    }
    EXPECT_TRUE(gl.queryAvailable(ids.back()));
    int decided = 0, visible = 0;
    for (size_t q = 0; q < ids.size(); ++q) {
        const bool answer = gl.queryResult(ids[q]);
        visible += answer;
        if (low[q] != high[q]) continue;
        ++decided;
        EXPECT_EQ(answer, low[q]) << "query " << q;
    }
    EXPECT_GT(decided, n * 9 / 10);
    EXPECT_GT(visible, n / 2);  // nothing drawn: most boxes are on screen
    EXPECT_LT(visible, n);      // some are behind the eye
    gl.end();
    EXPECT_EQ(gl.outstandingQueries(), 0);
    EXPECT_EQ(gl.queryCounts().read, n);
}

// Every algorithm of a family that draws an image gets a -gl twin; the others do not.
TEST(GlImageTarget, BenchAndCullKnowTheGlNamesTheWindowDoesNot) {
    const std::vector<std::string> all = appAlgorithmNames();
    const std::vector<std::string> core = algorithmNames();
    EXPECT_EQ(all.size(), core.size() + 4 + 3);  // the lazy grids' four, the BSP modes' three
    EXPECT_NE(std::find(all.begin(), all.end(), "busy-grid-gl"), all.end());
    EXPECT_EQ(std::find(all.begin(), all.end(), "vfc-gl"), all.end());
    EXPECT_EQ(std::find(core.begin(), core.end(), "busy-grid-gl"), core.end());
    EXPECT_EQ(registryAlgorithmOf("busy-grid-gl"), "busy-grid");
    EXPECT_EQ(registryAlgorithmOf("bsp-oq-simple-gl"), "bsp-oq-simple");
    EXPECT_EQ(registryAlgorithmOf("rgvc"), "rgvc");
    EXPECT_EQ(registryAlgorithmOf("rgvc-gl"), "");
}

}  // namespace
}  // namespace gridcull
