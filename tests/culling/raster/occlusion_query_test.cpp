// Occlusion queries on the software rasterizer: the depth-test-only pass
// IdDepthBuffer::boxPassesDepthTest against a brute-force per-pixel check
// (raster_brute_force.h's independent ray-box cast against the buffer's drawn
// depths) and against drawBox itself, and SoftwareImageTarget's queries
// (culling/api/occlusion_queries.h) against the same check on drawn scenes: the
// near-plane and eye-inside rule, conservativeness for objects inside a box,
// latency, several outstanding queries, checked ids, the pool's growth and no
// allocation after warm-up. GRIDCULL_SEED=N replays one random scene.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/raster/id_depth_buffer.h"
#include "culling/raster/software_image_target.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/allocation_counter.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/raster/raster_brute_force.h"

namespace gridcull {
namespace {

using test::atView;
constexpr int kWidth = test::kRasterWidth;
constexpr int kHeight = test::kRasterHeight;

// A random drawn scene: spheres and boxes in front of the oblique camera.
struct RandomScene {
    Camera camera = test::obliqueCamera();
    Scene scene = test::scene3d();
};

Aabb viewBox(const Camera& camera, SeededRandom& rng, double z_lo, double z_hi, double half_lo,
             double half_hi) {
    const double z = rng.uniform(z_lo, z_hi);
    const double spread = 0.6 * std::abs(z) + 1.0;
    const glm::dvec3 c =
        atView(camera, rng.uniform(-spread, spread), rng.uniform(-spread, spread), z);
    const glm::dvec3 half{rng.uniform(half_lo, half_hi), rng.uniform(half_lo, half_hi),
                          rng.uniform(half_lo, half_hi)};
    return {c - half, c + half};
}

RandomScene randomScene(uint64_t seed, int objects) {
    RandomScene r;
    SeededRandom rng(seed, 7);
    for (int k = 0; k < objects; ++k) {
        if (rng.below(2)) {
            const Aabb box = viewBox(r.camera, rng, 3.0, 30.0, 0.3, 3.0);
            test::addBox(r.scene, k, box.min, box.max);
        } else {
            const double z = rng.uniform(3.0, 30.0);
            const double spread = 0.6 * z;
            test::addSphere(
                r.scene, k,
                atView(r.camera, rng.uniform(-spread, spread), rng.uniform(-spread, spread), z),
                rng.uniform(0.3, 3.0));
        }
    }
    return r;
}

// A query box: mostly in front, some crossing the near plane (0.5), some
// behind the eye, a few containing it.
Aabb randomQueryBox(const Camera& camera, SeededRandom& rng) {
    switch (rng.below(10)) {
        case 0:
            return viewBox(camera, rng, -0.3, 0.8, 0.2, 1.5);  // about the eye and near
        case 1:
            return viewBox(camera, rng, -20.0, -1.0, 0.2, 3.0);  // behind
        default:
            return viewBox(camera, rng, 1.0, 40.0, 0.1, 4.0);
    }
}

// The brute-force answer of a box against per-pixel drawn depths (row-major,
// +infinity where empty): Definite when some pixel's ray, clear of grazing,
// enters the box clearly nearer than drawn (visible) or when every pixel clearly
// is not (hidden); Either when the decision rests on a grazing ray or a depth
// tie within rounding.
enum class Answer { Hidden, Visible, Either };
Answer bruteForce(const Camera& camera, const std::vector<double>& drawn, const Aabb& box) {
    const test::PixelRays rays(camera, kWidth, kHeight);
    bool maybe = false;
    for (int py = 0; py < kHeight; ++py) {
        for (int px = 0; px < kWidth; ++px) {
            const double d = drawn[size_t(py) * kWidth + size_t(px)];
            const test::RefHit hit = test::refBox(rays, rays.dir(px, py), box);
            if (hit.boundary) {
                maybe = true;
                continue;
            }
            if (!hit.hit) continue;
            const bool inf = d == std::numeric_limits<double>::infinity();
            if (inf || hit.depth < d * (1.0 - test::kDepthTolerance)) return Answer::Visible;
            if (hit.depth <= d * (1.0 + test::kDepthTolerance)) maybe = true;
        }
    }
    return maybe ? Answer::Either : Answer::Hidden;
}

std::vector<double> depthsOf(SoftwareImageTarget& target) {
    std::vector<double> depths;
    for (int py = 0; py < kHeight; ++py)
        for (int px = 0; px < kWidth; ++px)
            depths.push_back(target.farthestDepth({px, py, px, py}));
    return depths;
}

void drawAll(SoftwareImageTarget& target, const Scene& scene, size_t count) {
    PixelRect written;
    for (size_t k = 0; k < count && k < scene.objects.size(); ++k)
        target.draw(scene.objects[k], int(k), glm::dvec3(0.0), PixelRect{}, written);
}

// The raw pass: a box passes iff the brute force says so, iff drawBox would
// change some pixel. Boxes crossing the near plane and containing the eye
// included (the pass clips them as drawBox does).
TEST(IdDepthBufferDepthTest, BoxPassesIffSomePixelRayEntersNearerThanDrawn) {
    long long visible = 0, hidden = 0, either = 0;
    for (uint64_t seed : test::seedsToRun(1, 40)) {
        test::withSeed(seed, [&] {
            const RandomScene r = randomScene(seed, 12);
            IdDepthBuffer buffer;
            buffer.resize(kWidth, kHeight);
            buffer.begin(r.camera);
            for (size_t k = 0; k < r.scene.objects.size(); ++k)
                buffer.drawObject(int(k), r.scene.objects[k], glm::dvec3(0.0));
            const std::vector<double> drawn = test::depthImage(buffer);
            SeededRandom rng(seed, 11);
            for (int q = 0; q < 40; ++q) {
                const Aabb box = randomQueryBox(r.camera, rng);
                const bool passes = buffer.boxPassesDepthTest(box);
                IdDepthBuffer copy = buffer;
                copy.drawBox(99, box);
                EXPECT_EQ(passes, test::depthImage(copy) != drawn) << "query " << q;
                if (box.contains(r.camera.position)) {
                    EXPECT_TRUE(passes) << "query " << q << " contains the eye";
                    continue;
                }
                switch (bruteForce(r.camera, drawn, box)) {
                    case Answer::Visible:
                        ++visible;
                        EXPECT_TRUE(passes) << "query " << q;
                        break;
                    case Answer::Hidden:
                        ++hidden;
                        EXPECT_FALSE(passes) << "query " << q;
                        break;
                    case Answer::Either:
                        ++either;
                        break;
                }
            }
        });
    }
    if (!test::singleSeedRun()) {
        std::printf("[depth test] %lld visible, %lld hidden, %lld undecidable by rounding\n",
                    visible, hidden, either);
        EXPECT_GT(visible, 200);
        EXPECT_GT(hidden, 200);
        EXPECT_LT(either, (visible + hidden) / 100 + 1);
    }
}

// The target's queries on drawn scenes: the trivial rule, then the brute force;
// queries issued between draws see the depth of their moment.
TEST(SoftwareOcclusionQueries, AnswersMatchTheBruteForceOnDrawnScenes) {
    long long visible = 0, hidden = 0, trivial = 0;
    for (uint64_t seed : test::seedsToRun(100, 30)) {
        test::withSeed(seed, [&] {
            const RandomScene r = randomScene(seed, 14);
            SoftwareImageTarget target;
            target.prepare(r.scene);
            target.begin(r.camera, kWidth, kHeight, false);
            SeededRandom rng(seed, 13);
            // Half the scene drawn, a batch of queries, the rest drawn, another batch.
            for (size_t half : {r.scene.objects.size() / 2, r.scene.objects.size()}) {
                drawAll(target, r.scene, half);
                const std::vector<double> drawn = depthsOf(target);
                std::vector<OcclusionQuery> ids;
                std::vector<Answer> expected;
                for (int q = 0; q < 30; ++q) {
                    const Aabb box = randomQueryBox(r.camera, rng);
                    ids.push_back(target.issueQuery(box));
                    expected.push_back(occlusionQueryTriviallyVisible(r.camera, box)
                                           ? (++trivial, Answer::Visible)
                                           : bruteForce(r.camera, drawn, box));
                }
                // Read after more drawing (the second round draws nothing more).
                drawAll(target, r.scene, r.scene.objects.size());
                EXPECT_EQ(target.outstandingQueries(), 30);
                for (size_t q = ids.size(); q-- > 0;) {
                    ASSERT_TRUE(target.queryAvailable(ids[q]));
                    const bool answer = target.queryResult(ids[q]);
                    if (expected[q] == Answer::Either) continue;
                    const bool want = expected[q] == Answer::Visible;
                    (want ? visible : hidden)++;
                    EXPECT_EQ(answer, want) << "query " << q << " of batch " << half;
                }
            }
            target.end();
            EXPECT_EQ(target.outstandingQueries(), 0);
            EXPECT_EQ(target.queryCounts().issued, 60);
            EXPECT_EQ(target.queryCounts().read, 60);
            EXPECT_EQ(target.queryCounts().stalled, 0);
        });
    }
    if (!test::singleSeedRun()) {
        std::printf("[software queries] %lld visible (%lld trivially), %lld hidden\n", visible,
                    trivial, hidden);
        EXPECT_GT(visible, 300);
        EXPECT_GT(hidden, 300);
        EXPECT_GT(trivial, 50);
    }
}

// Conservative: every object the rasterizer (the oracle's sampling) would show
// past what is drawn makes its own box, and any box holding it, visible.
TEST(SoftwareOcclusionQueries, ObjectsSeenPastTheDrawnDepthMakeTheirBoxesVisible) {
    long long seen = 0;
    for (uint64_t seed : test::seedsToRun(200, 30)) {
        test::withSeed(seed, [&] {
            const RandomScene r = randomScene(seed, 20);
            const size_t occluders = 8;
            SoftwareImageTarget target;
            target.prepare(r.scene);
            target.begin(r.camera, kWidth, kHeight, false);
            drawAll(target, r.scene, occluders);
            IdDepthBuffer buffer;  // the same occluders, to draw each candidate alone after
            buffer.resize(kWidth, kHeight);
            buffer.begin(r.camera);
            for (size_t k = 0; k < occluders; ++k)
                buffer.drawObject(int(k), r.scene.objects[k], glm::dvec3(0.0));
            const std::vector<double> drawn = test::depthImage(buffer);
            for (size_t k = occluders; k < r.scene.objects.size(); ++k) {
                const SceneObject& object = r.scene.objects[k];
                IdDepthBuffer alone = buffer;
                alone.drawObject(int(k), object, glm::dvec3(0.0));
                if (test::depthImage(alone) == drawn) continue;  // hidden or off screen
                ++seen;
                Aabb box = object.bounds;
                box.min -= glm::dvec3(0.01, 0.2, 0.05);  // any box around it
                box.max += glm::dvec3(0.3, 0.02, 0.1);
                EXPECT_TRUE(target.queryResult(target.issueQuery(box))) << "object " << k;
                EXPECT_TRUE(target.queryResult(target.issueQuery(object.bounds))) << "object " << k;
            }
        });
    }
    if (!test::singleSeedRun()) {
        std::printf("[software queries] %lld objects seen past the drawn depth\n", seen);
        EXPECT_GT(seen, 100);
    }
}

// Designed cases: a wall at depth 10 in front of the camera.
struct WallFixture {
    Camera camera = test::obliqueCamera();
    Scene scene = test::scene3d();
    SoftwareImageTarget target;
    WallFixture() {
        const glm::dvec3 c = atView(camera, 0, 0, 10);
        test::addBox(scene, 0, c - glm::dvec3(30, 30, 0.5), c + glm::dvec3(30, 30, 0.5));
        target.prepare(scene);
        target.begin(camera, kWidth, kHeight, false);
        drawAll(target, scene, 1);
    }
    bool ask(const Aabb& box) { return target.queryResult(target.issueQuery(box)); }
    Aabb at(double x, double y, double z, double half) const {
        const glm::dvec3 c = atView(camera, x, y, z);
        return {c - glm::dvec3(half), c + glm::dvec3(half)};
    }
};

TEST(SoftwareOcclusionQueries, NearPlaneAndEyeInsideAnswerVisible) {
    WallFixture f;
    EXPECT_FALSE(f.ask(f.at(0, 0, 20, 1.0)));  // behind the wall
    EXPECT_TRUE(f.ask(f.at(0, 0, 5, 1.0)));    // in front of it
    EXPECT_FALSE(f.ask(f.at(0, 0, -5, 1.0)));  // behind the eye
    EXPECT_EQ(f.target.queryCounts().trivial, 0);
    // Containing the eye: visible, even a box too small to reach the near plane.
    EXPECT_TRUE(f.ask(f.at(0, 0, 0, 0.1)));
    EXPECT_TRUE(f.ask(f.at(0.05, 0, 0.1, 0.3)));
    // Crossing the near plane (0.5), even far off to the side of the frustum.
    EXPECT_TRUE(f.ask(f.at(0, 0, 0.6, 0.2)));
    EXPECT_TRUE(f.ask(f.at(50, 0, 0.5, 0.2)));
    EXPECT_EQ(f.target.queryCounts().trivial, 4);
    // Wholly beyond the near plane (a world-axis cube of half 0.5 spans about
    // +-0.53 in depth here) is an ordinary query; off screen is hidden.
    EXPECT_TRUE(f.ask(f.at(0, 0, 1.1, 0.5)));
    EXPECT_FALSE(f.ask(f.at(50, 0, 5, 1.0)));
    EXPECT_EQ(f.target.queryCounts().trivial, 4);
}

TEST(SoftwareOcclusionQueries, LatencyHoldsAnswersBackAndStallsAreCounted) {
    WallFixture f;
    f.target.setQueryLatency(2);
    EXPECT_EQ(f.target.queryLatencyFrames(), 2);
    const OcclusionQuery front = f.target.issueQuery(f.at(0, 0, 5, 1.0));
    const OcclusionQuery back = f.target.issueQuery(f.at(0, 0, 20, 1.0));
    const OcclusionQuery early = f.target.issueQuery(f.at(0, 0, 20, 1.0));
    EXPECT_FALSE(f.target.queryAvailable(front));
    EXPECT_FALSE(f.target.queryResult(early));  // read at once: right, but a stall
    EXPECT_EQ(f.target.queryCounts().stalled, 1);
    f.target.end();
    f.target.begin(f.camera, kWidth, kHeight, false);  // the next frame: empty image
    EXPECT_FALSE(f.target.queryAvailable(front));
    EXPECT_FALSE(f.target.queryAvailable(back));
    f.target.end();
    f.target.begin(f.camera, kWidth, kHeight, false);
    ASSERT_TRUE(f.target.queryAvailable(front));
    ASSERT_TRUE(f.target.queryAvailable(back));
    // The answers are those of the frame they were issued in.
    EXPECT_TRUE(f.target.queryResult(front));
    EXPECT_FALSE(f.target.queryResult(back));
    EXPECT_EQ(f.target.queryCounts().stalled, 1);
    EXPECT_EQ(f.target.queryCounts().read, 3);
    // Latency 0 again: available in the frame of issue.
    f.target.setQueryLatency(0);
    const OcclusionQuery now = f.target.issueQuery(f.at(0, 0, 20, 1.0));
    EXPECT_TRUE(f.target.queryAvailable(now));
    EXPECT_TRUE(f.target.queryResult(now));  // the image is empty this frame
}

TEST(SoftwareOcclusionQueries, ManyOutstandingQueriesGrowThePoolOnceThenAllocateNothing) {
    WallFixture f;
    EXPECT_EQ(f.target.queryCapacity(), kOcclusionQueryReserve);
    const int n = kOcclusionQueryReserve + 300;
    std::vector<OcclusionQuery> ids;
    ids.reserve(size_t(n));
    auto round = [&] {
        f.target.begin(f.camera, kWidth, kHeight, false);
        drawAll(f.target, f.scene, 1);
        for (int q = 0; q < n; ++q)
            ids.push_back(f.target.issueQuery(f.at(0, 0, q % 2 ? 5 : 20, 1)));
        int visible = 0;
        for (const OcclusionQuery& id : ids) visible += f.target.queryResult(id);
        ids.clear();
        f.target.end();
        return visible;
    };
    EXPECT_EQ(round(), n / 2);  // warm-up: the pool doubles
    EXPECT_EQ(f.target.queryCapacity(), 2 * kOcclusionQueryReserve);
    test::startCounting();
    const int visible = round();
    test::stopCounting();
    EXPECT_EQ(visible, n / 2);
    EXPECT_EQ(test::allocationCount(), 0);
    EXPECT_EQ(f.target.queryCapacity(), 2 * kOcclusionQueryReserve);
}

TEST(SoftwareOcclusionQueries, ResetForgetsOutstandingQueries) {
    WallFixture f;
    f.target.issueQuery(f.at(0, 0, 5, 1.0));
    f.target.issueQuery(f.at(0, 0, 5, 1.0));
    EXPECT_EQ(f.target.outstandingQueries(), 2);
    f.target.resetQueries();
    EXPECT_EQ(f.target.outstandingQueries(), 0);
    f.target.prepare(f.scene);
    EXPECT_EQ(f.target.queryCounts().issued, 0);
}

TEST(SoftwareOcclusionQueries, StaleAndForeignIdsFailAnAssert) {
    WallFixture f;
    const OcclusionQuery id = f.target.issueQuery(f.at(0, 0, 5, 1.0));
    f.target.queryResult(id);
    EXPECT_DEATH(f.target.queryResult(id), "stale occlusion query id");
    const OcclusionQuery reset = f.target.issueQuery(f.at(0, 0, 5, 1.0));
    f.target.resetQueries();
    EXPECT_DEATH(f.target.queryAvailable(reset), "stale occlusion query id");
    EXPECT_DEATH(f.target.queryResult(OcclusionQuery{}), "not an occlusion query id");
    f.target.end();
    EXPECT_DEATH(f.target.issueQuery(f.at(0, 0, 5, 1.0)), "between begin\\(\\) and end\\(\\)");
}

}  // namespace
}  // namespace gridcull
