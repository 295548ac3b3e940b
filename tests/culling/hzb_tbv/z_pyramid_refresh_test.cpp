// ZPyramid::refresh, the propagation of each drawn object's depths up the
// pyramid that the hzb cullers do after every draw: after any sequence of
// draws (spheres, boxes, meshes, closed meshes that the near plane cuts) and
// refreshes over the draws' rectangles, every level equals a pyramid built
// from scratch over the whole buffer. So each draw's rectangle holds every
// pixel it wrote.
#include <gtest/gtest.h>

#include "culling/hzb_tbv/z_pyramid.h"
#include "culling/raster/id_depth_buffer.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

void expectSamePyramid(const ZPyramid& a, const ZPyramid& b, uint64_t seed, int draw) {
    ASSERT_EQ(a.levelCount(), b.levelCount());
    for (int l = 0; l < a.levelCount(); ++l) {
        const ZPyramidLevel la = a.level(l), lb = b.level(l);
        for (int y = 0; y < la.height; ++y)
            for (int x = 0; x < la.width; ++x)
                ASSERT_EQ(la.at(x, y), lb.at(x, y)) << "seed " << seed << " draw " << draw
                                                    << " level " << l << " texel " << x << "," << y;
    }
}

TEST(ZPyramidRefresh, DrawByDrawEqualsAFullBuild) {
    for (uint64_t seed = 1; seed <= 40; ++seed) {
        SeededRandom rng(seed);
        Camera camera;
        camera.position = {rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0), -30.0};
        camera.target = {0, 0, 0};
        camera.fov_deg = rng.uniform(30.0, 100.0);
        camera.aspect = rng.uniform(0.3, 3.0);
        int w = 0, h = 0;
        imageSizeForAspect(1 + int(rng.below(200)), camera.aspect, w, h);
        IdDepthBuffer buffer;
        buffer.resize(w, h);
        buffer.begin(camera);
        ZPyramid incremental, full;
        // As the culler starts a frame: a cleared pyramid for a cleared buffer.
        incremental.resize(w, h);
        incremental.clear();
        for (int draw = 0; draw < 30; ++draw) {
            const glm::dvec3 c{rng.uniform(-20.0, 20.0), rng.uniform(-20.0, 20.0),
                               rng.uniform(-25.0, 40.0)};
            bool drawn;
            const double kind = rng.uniform();
            if (kind < 0.15) {
                // A closed mesh around or just in front of the eye: the near plane
                // cuts it and the solid fills pixels at depth near.
                const glm::dvec3 at =
                    camera.position + glm::dvec3{rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0),
                                                 rng.uniform(-1.0, 3.0)};
                drawn = buffer.drawMesh(draw, *test::cubeMesh(rng.uniform(0.5, 3.0)), at);
            } else if (kind < 0.3) {
                drawn = buffer.drawMesh(draw, *test::tetrahedronMesh(rng.uniform(1.0, 9.0)), c);
            } else if (kind < 0.65) {
                drawn = buffer.drawSphere(draw, c, rng.uniform(0.1, 8.0));
            } else {
                const glm::dvec3 half{rng.uniform(0.1, 6.0), rng.uniform(0.1, 6.0),
                                      rng.uniform(0.1, 6.0)};
                drawn = buffer.drawBox(draw, Aabb{c - half, c + half});
            }
            if (drawn) incremental.refresh(buffer, buffer.lastDrawCols(), buffer.lastDrawRows());
            full.build(buffer);
            expectSamePyramid(incremental, full, seed, draw);
        }
    }
}

}  // namespace
}  // namespace gridcull
