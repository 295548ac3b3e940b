// The view-frustum traversal of rgvc (Batagelo & Wu, s4.2): checked against
// brute force over every voxel of the grid, for cameras inside and outside the
// grid, on voxel faces and corners, fov 10 to 360, near and far `far`.
//  - The frustum test itself against an independent exact reference (the voxel
//    square clipped by the wedge's half-planes).
//  - With nothing to occlude, every frustum voxel is visited exactly once, in
//    non-decreasing chess distance, each tagged with its chess layer.
//  - With occluders, no voxel is visited twice and every frustum voxel up to the
//    last layer traversed is visited.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

#include "culling/rgvc/rgvc_culler.h"
#include "grid/chess_ring.h"
#include "tests/culling/rgvc/rgvc_random_scene.h"

namespace gridcull {
namespace {

using Poly = std::vector<glm::dvec2>;

// Sutherland-Hodgman: the part of `poly` with dot(n, p) >= k.
Poly clip(const Poly& poly, glm::dvec2 n, double k) {
    Poly out;
    for (size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
        const double da = n.x * a.x + n.y * a.y - k, db = n.x * b.x + n.y * b.y - k;
        if (da >= 0) out.push_back(a);
        if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// Does the closed box meet the closed wedge (apex, heading, fov) at all? The
// wedge is cut into convex pieces of at most 90 degrees, each the intersection
// of two half-planes through the apex.
bool boxMeetsWedge(double x0, double y0, double x1, double y1, glm::dvec2 apex, double heading,
                   double fov) {
    if (apex.x >= x0 && apex.x <= x1 && apex.y >= y0 && apex.y <= y1) return true;
    const int pieces = std::max(1, int(std::ceil(fov / (0.5 * 3.141592653589793))));
    for (int i = 0; i < pieces; ++i) {
        const double a0 = heading - 0.5 * fov + fov * i / pieces;
        const double a1 = heading - 0.5 * fov + fov * (i + 1) / pieces;
        const glm::dvec2 d0{std::cos(a0), std::sin(a0)}, d1{std::cos(a1), std::sin(a1)};
        Poly box = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
        // Left of d0 and right of d1, with a hair of slack.
        box = clip(box, {-d0.y, d0.x}, -d0.y * apex.x + d0.x * apex.y - 1e-9);
        if (box.empty()) continue;
        box = clip(box, {d1.y, -d1.x}, d1.y * apex.x - d1.x * apex.y - 1e-9);
        if (!box.empty()) return true;
    }
    return false;
}

// The voxels of the grid in the frustum, by brute force; and their layers.
std::map<std::pair<int, int>, int64_t> bruteForceFrustum(const RegularGrid& grid,
                                                         const Camera& camera, glm::i64vec2 viewer,
                                                         bool use_reference) {
    RgvcWedge wedge;
    wedge.set(camera, grid.voxelSize());
    const double heading = std::atan2(camera.forward().y, camera.forward().x);
    std::map<std::pair<int, int>, int64_t> in;
    for (int y = 0; y < grid.resolution.y; ++y) {
        for (int x = 0; x < grid.resolution.x; ++x) {
            bool touches;
            if (use_reference) {
                const Aabb b = grid.voxelBounds({x, y, 0});
                const double gx =
                    std::max({b.min.x - camera.position.x, 0.0, camera.position.x - b.max.x});
                const double gy =
                    std::max({b.min.y - camera.position.y, 0.0, camera.position.y - b.max.y});
                touches = std::hypot(gx, gy) <= camera.far &&
                          (camera.fov_deg >= 360.0 ||
                           boxMeetsWedge(b.min.x, b.min.y, b.max.x, b.max.y,
                                         {camera.position.x, camera.position.y}, heading,
                                         glm::radians(camera.fov_deg)));
            } else {
                touches = wedge.touchesVoxel(grid, {x, y});
            }
            if (touches) in[{x, y}] = chessDistance(glm::i64vec2(x, y) - viewer);
        }
    }
    return in;
}

Scene emptyScene(uint64_t seed) {
    Scene scene = test::rgvcRandomScene(seed);
    scene.objects.clear();
    scene.finalize();
    return scene;
}

TEST(RgvcFrustum, VoxelTestMatchesAnExactReference) {
    int disagreements = 0, voxels = 0;
    for (uint64_t seed = 1; seed <= 150; ++seed) {
        const Scene scene = emptyScene(seed);
        for (int frame = 0; frame < test::kRgvcFrames; frame += 7) {
            const Camera camera = cameraAt(scene, scene.timeOfFrame(frame));
            const glm::ivec3 v = scene.grid.voxelOf(camera.position);
            const auto fast = bruteForceFrustum(scene.grid, camera, {v.x, v.y}, false);
            const auto exact = bruteForceFrustum(scene.grid, camera, {v.x, v.y}, true);
            // Conservative: every voxel meeting the frustum is in.
            for (const auto& entry : exact)
                ASSERT_TRUE(fast.count(entry.first))
                    << "seed " << seed << " frame " << frame << " voxel " << entry.first.first
                    << "," << entry.first.second << " meets the frustum but was left out";
            // And not loose: extra voxels can only come from rounding slack.
            disagreements += int(fast.size() - exact.size());
            voxels += int(exact.size());
        }
    }
    EXPECT_LE(disagreements, voxels / 1000);
}

TEST(RgvcTraversal, VisitsEveryFrustumVoxelOnceInChessOrder) {
    int cameras = 0;
    for (uint64_t seed = 1; seed <= 300; ++seed) {
        const Scene scene = emptyScene(seed);
        RgvcCuller rgvc;
        rgvc.setDebugCapture(true);
        rgvc.reset(scene);
        FrameResult out;
        for (int frame = 0; frame < test::kRgvcFrames; frame += 3) {
            const double t = scene.timeOfFrame(frame);
            const Camera camera = cameraAt(scene, t);
            rgvc.cull(scene, camera, t, out);
            const RgvcSnapshot& snap = rgvc.snapshot();
            ASSERT_TRUE(snap.valid);
            SCOPED_TRACE("seed " + std::to_string(seed) + " frame " + std::to_string(frame) +
                         " fov " + std::to_string(camera.fov_deg));
            const auto want = bruteForceFrustum(scene.grid, camera, snap.viewer_voxel, false);
            std::map<std::pair<int, int>, int> times;
            int64_t last_layer = -1;
            for (const RgvcVisit& visit : snap.visits) {
                const std::pair<int, int> key{visit.voxel.x, visit.voxel.y};
                ++times[key];
                ASSERT_GE(visit.layer, last_layer) << "layers must not decrease";
                last_layer = visit.layer;
                const auto it = want.find(key);
                ASSERT_TRUE(it != want.end())
                    << "visited " << key.first << "," << key.second << " outside the frustum";
                ASSERT_EQ(it->second, visit.layer);
                ASSERT_FALSE(visit.occluded);  // nothing to occlude
            }
            for (const auto& entry : want)
                ASSERT_EQ(times[entry.first], 1)
                    << "voxel " << entry.first.first << "," << entry.first.second << " layer "
                    << entry.second << " viewer " << snap.viewer_voxel.x << ","
                    << snap.viewer_voxel.y;
            ASSERT_EQ(out.stats.get(Counter::VoxelsVisited), int64_t(want.size()));
            // One seed per layer traversed, on that layer.
            for (const RgvcSeed& seed_voxel : snap.seeds)
                ASSERT_EQ(chessDistance(seed_voxel.voxel - snap.viewer_voxel), seed_voxel.layer);
            ++cameras;
        }
    }
    EXPECT_GT(cameras, 1500);
}

// Checks one camera on an empty scene: every frustum voxel exactly once, in
// chess order, tagged with its layer.
void checkEmptySceneCamera(const Scene& base, const glm::dvec3& eye, double heading_deg, double fov,
                           double far) {
    Scene scene = base;
    const double h = glm::radians(heading_deg);
    test::setCamera(scene, eye, eye + glm::dvec3(std::cos(h), std::sin(h), 0) * 10.0, fov, 0.1,
                    far);
    RgvcCuller rgvc;
    rgvc.setDebugCapture(true);
    rgvc.reset(scene);
    FrameResult out;
    const Camera camera = cameraAt(scene, 0.0);
    rgvc.cull(scene, camera, 0.0, out);
    const RgvcSnapshot& snap = rgvc.snapshot();
    const auto want = bruteForceFrustum(scene.grid, camera, snap.viewer_voxel, false);
    const auto exact = bruteForceFrustum(scene.grid, camera, snap.viewer_voxel, true);
    std::map<std::pair<int, int>, int> times;
    int64_t last_layer = -1;
    for (const RgvcVisit& visit : snap.visits) {
        ASSERT_EQ(++times[std::make_pair(visit.voxel.x, visit.voxel.y)], 1);
        ASSERT_GE(visit.layer, last_layer);
        last_layer = visit.layer;
        ASSERT_EQ(want.at({visit.voxel.x, visit.voxel.y}), visit.layer);
    }
    for (const auto& entry : want) ASSERT_EQ(times[entry.first], 1);
    for (const auto& entry : exact) ASSERT_EQ(times[entry.first], 1);
}

TEST(RgvcTraversal, GridPointsGridLinesAndFarOutside) {
    // 32 x 24 voxels of 2.5 x 2 units over [-40, 40] x [-24, 24].
    const Scene base = test::makeScene(2, Aabb{{-40, -24, 0}, {40, 24, 0}}, {32, 24, 1});
    const std::vector<glm::dvec3> eyes = {
        {0, 0, 0},        // a voxel corner in the middle
        {-40, -24, 0},    // the grid's corner
        {40, 24, 0},      // the opposite corner (outside the half-open grid)
        {2.5, 1.0, 0},    // on a vertical voxel face
        {1.25, 2.0, 0},   // on a horizontal voxel face
        {-45, 0, 0},      // just outside, left
        {0, 30, 0},       // just outside, above
        {-300, -200, 0},  // far outside, diagonal
        {5000, 0, 0},     // very far outside, on the grid's middle row
    };
    const double fovs[] = {10, 45, 90, 179.9, 180, 180.1, 270, 359.9, 360};
    const double fars[] = {1000, 17.5, 1e6};
    int cameras = 0;
    for (const glm::dvec3& eye : eyes) {
        for (int heading = 0; heading < 360; heading += 15) {
            for (const double fov : fovs) {
                for (const double far : fars) {
                    SCOPED_TRACE("eye " + std::to_string(eye.x) + "," + std::to_string(eye.y) +
                                 " heading " + std::to_string(heading) + " fov " +
                                 std::to_string(fov) + " far " + std::to_string(far));
                    checkEmptySceneCamera(base, eye, heading, fov, far);
                    if (testing::Test::HasFatalFailure()) return;
                    ++cameras;
                }
            }
        }
    }
    EXPECT_EQ(cameras, 9 * 24 * 9 * 3);
}

TEST(RgvcTraversal, WithOccludersEachVoxelAtMostOnceAndNoneSkippedBeforeTheEnd) {
    for (uint64_t seed = 1; seed <= 200; ++seed) {
        const Scene scene = test::rgvcRandomScene(seed);
        RgvcCuller rgvc;
        rgvc.setDebugCapture(true);
        rgvc.reset(scene);
        FrameResult out;
        for (int frame = 0; frame < test::kRgvcFrames; ++frame) {
            const double t = scene.timeOfFrame(frame);
            const Camera camera = cameraAt(scene, t);
            rgvc.cull(scene, camera, t, out);
            const RgvcSnapshot& snap = rgvc.snapshot();
            SCOPED_TRACE("seed " + std::to_string(seed) + " frame " + std::to_string(frame));
            const auto want = bruteForceFrustum(scene.grid, camera, snap.viewer_voxel, false);
            std::map<std::pair<int, int>, int> times;
            int64_t last_layer = -1;
            for (const RgvcVisit& visit : snap.visits) {
                ASSERT_EQ(++times[std::make_pair(visit.voxel.x, visit.voxel.y)], 1);
                ASSERT_GE(visit.layer, last_layer);
                last_layer = visit.layer;
            }
            for (const auto& entry : want) {
                if (entry.second <= snap.last_layer) {
                    ASSERT_EQ(times[entry.first], 1);
                }
            }
            if (!snap.terminated_early) {
                for (const auto& entry : want) ASSERT_EQ(times[entry.first], 1);
            }
        }
    }
}

}  // namespace
}  // namespace gridcull
