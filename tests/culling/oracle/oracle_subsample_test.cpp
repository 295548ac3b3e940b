// The 3D oracle's sub-sample question (exact_oracle.h, "Sub-sample objects") on
// hand-made cases: a wall of two boxes with a gap narrower than one pixel and a
// sphere seen only through it. World [0, 100]^3, camera at (50, 50, 5) looking
// down +z with fov 90 and aspect 1, so that a 64-pixel oracle has pixel centres
// at slopes u = (px + 0.5) / 32 - 1 and the gap's place between them is known.
// And, on 200 seeded random scenes, the refined answer at 1024 pixels against a
// plain 4096-pixel buffer, whose pixel centres are the refinement's first level.
#include <algorithm>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "culling/oracle/exact_oracle.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/common/test_seeds.h"
#include "tests/culling/oracle/oracle_random_scene.h"

namespace gridcull {
namespace {

using V = std::vector<int>;

const glm::dvec3 kEye{50, 50, 5};
constexpr int kWallLeft = 1, kWallRight = 2, kBehind = 3;
constexpr double kWallDepth = 10.0;  // the wall's front, from the eye

// The view-space slope u of a world x at the wall's depth: the camera looks down
// +z with up +y, so right is -x.
double worldX(double u, double depth) {
    return kEye.x - u * depth;
}

// The wall covers every row; its two boxes leave the gap u in [-half, half].
Scene gapScene(double half_gap_u) {
    Scene scene = test::scene3d();
    const double z0 = kEye.z + kWallDepth, z1 = z0 + 1.0;
    // Right is -x: u in [half, 2] is x in [worldX(2), worldX(half)]. Seen through
    // the wall's thickness the gap narrows to |u| < half * 10 / 11.
    test::addBox(scene, kWallLeft, {worldX(2.0, kWallDepth), 0, z0},
                 {worldX(half_gap_u, kWallDepth), 100, z1});
    test::addBox(scene, kWallRight, {worldX(-half_gap_u, kWallDepth), 0, z0},
                 {worldX(-2.0, kWallDepth), 100, z1});
    test::addSphere(scene, kBehind, {50, 50, 40}, 3.0);
    test::setCamera(scene, kEye, {50, 50, 100}, 90.0, 0.1, 1000.0);
    scene.camera.aspect = 1.0;
    scene.finalize();
    return scene;
}

ExactOracle makeOracle(int refine, int resolution) {
    OracleOptions options;
    options.resolution = resolution;
    options.refine = refine;
    return ExactOracle{options};
}

FrameResult cull(ExactOracle& oracle, const Scene& scene) {
    oracle.reset(scene);
    FrameResult out;
    timedCull(oracle, scene, cameraAt(scene, 0.0), 0.0, out);
    return out;
}

FrameResult cull(const Scene& scene, int refine, int resolution = 64) {
    ExactOracle oracle = makeOracle(refine, resolution);
    return cull(oracle, scene);
}

// One pixel is 1/32 in u. A gap of 0.3 pixel centred on u = 0 lies between the
// centres of pixels 31 and 32 (u = -+1/64) and holds a 4 x 4 sub-sample.
constexpr double kPixelU = 1.0 / 32.0;

TEST(OracleSubsample, PixelCentresAloneMissAnObjectSeenThroughASubPixelGap) {
    const FrameResult out = cull(gapScene(0.15 * kPixelU), 0);
    EXPECT_EQ(out.pvs, (V{kWallLeft, kWallRight}));
    EXPECT_TRUE(out.sub_sample_visible.empty());
    EXPECT_TRUE(out.sub_sample_undecided.empty());
    EXPECT_FALSE(out.stats.has(Counter::SubSampleCandidates));
}

TEST(OracleSubsample, RefinementSeesAnObjectThroughASubPixelGap) {
    const FrameResult out = cull(gapScene(0.15 * kPixelU), 1);
    // Visible, but on no pixel centre: not in the PVS a culler must keep.
    EXPECT_EQ(out.pvs, (V{kWallLeft, kWallRight}));
    EXPECT_EQ(out.sub_sample_visible, V{kBehind});
    EXPECT_TRUE(out.sub_sample_undecided.empty());
    EXPECT_EQ(out.stats.get(Counter::SubSampleCandidates), 1);
    EXPECT_EQ(out.stats.get(Counter::SubSampleVisible), 1);
    EXPECT_GT(out.stats.get(Counter::RefineRays), 0);
}

// Level-12 sub-samples nearest the middle sit at u = -+(1/24) / 32: a gap of
// half that width holds none, so no ray decides and the sphere is sub-sample.
TEST(OracleSubsample, AGapNarrowerThanTheFinestLevelIsReportedSubSample) {
    const FrameResult out = cull(gapScene(0.5 * kPixelU / 24.0), 1);
    EXPECT_EQ(out.pvs, (V{kWallLeft, kWallRight}));
    EXPECT_TRUE(out.sub_sample_visible.empty());
    EXPECT_EQ(out.sub_sample_undecided, V{kBehind});
    EXPECT_EQ(out.stats.get(Counter::SubSampleUndecided), 1);
}

TEST(OracleSubsample, AnObjectBehindOneWideOccluderIsNoCandidate) {
    Scene scene = test::scene3d();
    test::addBox(scene, kWallLeft, {0, 0, 15}, {100, 100, 16});
    test::addSphere(scene, kBehind, {50, 50, 40}, 3.0);
    test::setCamera(scene, kEye, {50, 50, 100}, 90.0, 0.1, 1000.0);
    scene.camera.aspect = 1.0;
    scene.finalize();
    const FrameResult out = cull(scene, 1);
    EXPECT_EQ(out.pvs, V{kWallLeft});
    EXPECT_TRUE(out.sub_sample_visible.empty());
    EXPECT_TRUE(out.sub_sample_undecided.empty());
    EXPECT_EQ(out.stats.get(Counter::SubSampleCandidates), 0);
    EXPECT_EQ(out.stats.get(Counter::RefineRays), 0);
}

// Two walls that touch inside a pixel column (u = 0.3 / 32): no single object
// spans the nine centres around the seam, but the two together cover it
// (pair_cover.h), so the sphere behind is no candidate.
TEST(OracleSubsample, AnObjectBehindTwoTouchingWallsIsNoCandidate) {
    Scene scene = test::scene3d();
    const double z0 = kEye.z + kWallDepth, z1 = z0 + 1.0, seam_u = 0.3 / 32;
    test::addBox(scene, kWallLeft, {worldX(2.0, kWallDepth), 0, z0}, {worldX(seam_u, kWallDepth), 100, z1});
    test::addBox(scene, kWallRight, {worldX(seam_u, kWallDepth), 0, z0}, {worldX(-2.0, kWallDepth), 100, z1});
    test::addSphere(scene, kBehind, {50, 50, 40}, 3.0);
    test::setCamera(scene, kEye, {50, 50, 100}, 90.0, 0.1, 1000.0);
    scene.camera.aspect = 1.0;
    scene.finalize();
    const FrameResult out = cull(scene, 1);
    EXPECT_EQ(out.pvs, (V{kWallLeft, kWallRight}));
    EXPECT_TRUE(out.sub_sample_undecided.empty());
    EXPECT_EQ(out.stats.get(Counter::SubSampleCandidates), 0);
    EXPECT_EQ(out.stats.get(Counter::RefineRays), 0);
}

// The image's border pixels are proven covered as any other: the rays of their
// neighbours' centres outside the image are rays all the same. A box behind a
// wall, both wider than the image, is no candidate.
TEST(OracleSubsample, AnObjectHiddenAcrossTheImagesBorderIsNoCandidate) {
    Scene scene = test::scene3d();
    test::addBox(scene, kWallLeft, {0, 0, 15}, {100, 100, 16});
    test::addBox(scene, kBehind, {0, 0, 40}, {100, 100, 41});
    test::setCamera(scene, kEye, {50, 50, 100}, 90.0, 0.1, 1000.0);
    scene.camera.aspect = 1.0;
    scene.finalize();
    const FrameResult out = cull(scene, 1);
    EXPECT_EQ(out.pvs, V{kWallLeft});
    EXPECT_TRUE(out.sub_sample_undecided.empty());
    EXPECT_EQ(out.stats.get(Counter::SubSampleCandidates), 0);
    EXPECT_EQ(out.stats.get(Counter::RefineRays), 0);
}

// A ray that starts inside a solid sees that solid, at depth near, as the
// rasterizer does. The box holds the near plane on the image's left half (its
// side x = 50 passes through the eye: the line between pixel columns 31 and 32)
// and, inside it, a sphere that touches that side. Pixel column 31 is open (its
// right neighbours see nothing), so its sub-samples are cast; every one starts
// inside the box. Embree alone would meet the sphere before the box's far side
// and call it visible.
TEST(OracleSubsample, RaysFromInsideASolidSeeTheSolid) {
    Scene scene = test::scene3d();
    test::addBox(scene, kWallLeft, {50, 0, kEye.z + 0.05}, {100, 100, 90});
    test::addSphere(scene, kBehind, {53, 50, 40}, 3.0);
    test::setCamera(scene, kEye, {50, 50, 100}, 90.0, 0.1, 1000.0);
    scene.camera.aspect = 1.0;
    scene.finalize();
    const FrameResult out = cull(scene, 1);
    EXPECT_EQ(out.pvs, V{kWallLeft});
    EXPECT_GT(out.stats.get(Counter::RefineRays), 0);
    EXPECT_TRUE(out.sub_sample_visible.empty());
}

// Every object a 4096-pixel buffer sees, the 1024-pixel oracle sees after
// refinement (its PVS and its sub-sample visible objects): the first level's
// rays are the fine buffer's pixel centres, cast wherever the coarse buffer
// cannot prove the object hidden.
TEST(OracleSubsample, RefinedAnswerAgreesWithAFourTimesFinerBuffer) {
    const int scenes = test::sweepScenes(200);
    int fine_visible = 0, refined_found = 0, sub_sample = 0;
    // Made once: a 4096-pixel buffer is some 200 MB to allocate.
    ExactOracle coarse = makeOracle(1, 1024), fine_oracle = makeOracle(0, 4096);
    for (const uint64_t seed : test::seedsToRun(0, scenes))
        test::withSeed(seed, [&] {
            const Scene scene = test::oracleRandomScene(2 * seed);  // even seeds are 3D
            const FrameResult refined = cull(coarse, scene);
            const FrameResult fine = cull(fine_oracle, scene);
            std::set<int> got(refined.pvs.begin(), refined.pvs.end());
            got.insert(refined.sub_sample_visible.begin(), refined.sub_sample_visible.end());
            for (const int id : fine.pvs) EXPECT_TRUE(got.count(id)) << "missed id " << id;
            for (const int id : refined.sub_sample_undecided) EXPECT_FALSE(got.count(id)) << id;
            fine_visible += int(fine.pvs.size());
            refined_found += int(refined.sub_sample_visible.size());
            sub_sample += int(refined.sub_sample_undecided.size());
        });
    std::printf("[ refined ] %d scenes: the 4096-pixel buffer sees %d objects; refinement found %d "
                "that 1024 pixel centres missed; %d left sub-sample\n",
                scenes, fine_visible, refined_found, sub_sample);
    if (!test::singleSeedRun()) {
        EXPECT_GT(fine_visible, scenes);
    }
}

}  // namespace
}  // namespace gridcull
