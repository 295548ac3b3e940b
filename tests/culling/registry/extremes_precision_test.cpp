// Far from the origin: the same scene and camera path shifted
// by 1e4, 1e6 and 1e7 on every axis. Every algorithm must stay free of false
// culls against the oracle on the shifted scene (extremes_harness.h); results
// may only get looser. The oracle computes in doubles (about 2e-9 apart at
// 1e7), so its PVS must still equal the unshifted one for a scene whose details
// are 0.1 units and larger: a difference is printed and fails the test.
// The loader's limit is kMaxSceneCoordinate = 1e7 on every number in a file; a
// file shifted past it is rejected with a message that names the value.
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/culling/registry/extremes_harness.h"
#include "tests/culling/registry/extremes_scenes.h"

namespace gridcull {
namespace {

using test::ExtremeCase;
using test::makeCamera;

// Moves the scene and every frame's camera by `offset`.
ExtremeCase shifted(const ExtremeCase& base, const glm::dvec3& offset, const std::string& name) {
    ExtremeCase c = base;
    c.name = name;
    c.scene.grid.world = c.scene.grid.world.translated(offset);
    for (SceneObject& o : c.scene.objects) {
        o.center += offset;
        o.box = o.box.translated(offset);
        for (glm::dvec3& p : o.points) p += offset;
        o.anchor += offset;
        o.bounds = o.bounds.translated(offset);
        for (PositionKey& k : o.motion.keys) k.position += offset;
    }
    for (CameraKey& k : c.scene.camera.path) {
        k.position += offset;
        k.target += offset;
    }
    for (test::ExtremeFrame& f : c.frames) {
        f.camera.position += offset;
        f.camera.target += offset;
    }
    c.scene.finalize();
    return c;
}

// A wall with a narrow gap, random objects (a third moving), the camera walking
// and turning through the grid.
ExtremeCase precisionBase(int dims) {
    Scene scene = dims == 3 ? test::scene3d() : test::scene2d();
    test::addWallWithHole(scene, 0, 40, 42, {48.5, 48.5, 0}, {51.5, 51.5, 0});
    SeededRandom rng(11);
    test::addRandomObjects(scene, rng, 40);
    // Seen only through the gap (ids after the random ones).
    const int through_id = int(scene.objects.size());
    test::addSphere(scene, through_id, dims == 3 ? glm::dvec3(50, 50, 80) : glm::dvec3(50, 80, 0),
                    0.5);
    ExtremeCase c{"", scene, {}, {}};
    for (int f = 0; f < 6; ++f) {
        const double s = f / 5.0;
        const glm::dvec3 eye =
            dims == 3 ? glm::dvec3(50 + 10 * s, 50, 5) : glm::dvec3(50 + 10 * s, 5, 0);
        const glm::dvec3 target =
            dims == 3 ? glm::dvec3(50, 50 + 40 * s, 100) : glm::dvec3(50 - 60 * s, 100, 0);
        c.frames.push_back({f * test::kDt,
                            makeCamera(dims, eye, target, dims == 3 ? 60 : 100, 16.0 / 9.0),
                            {},
                            {}});
    }
    test::adoptCamera(c.scene, c.frames.front().camera);
    c.scene.finalize();
    return c;
}

std::vector<std::vector<int>> exactPvs(const ExtremeCase& c) {
    ExactOracle oracle{oracleOptions(c.knobs)};
    oracle.reset(c.scene);
    std::vector<std::vector<int>> pvs;
    FrameResult out;
    for (const test::ExtremeFrame& f : c.frames) {
        oracle.cull(c.scene, f.camera, f.t, out);
        pvs.push_back(out.pvs);
    }
    return pvs;
}

TEST(ExtremesPrecision, SceneAndCameraShiftedFarFromTheOrigin) {
    for (const int dims : {2, 3}) {
        const ExtremeCase base = precisionBase(dims);
        const std::vector<std::vector<int>> reference = exactPvs(base);
        for (const double shift : {0.0, 1e4, 1e6, 1e7}) {
            const glm::dvec3 offset = dims == 3 ? glm::dvec3(shift) : glm::dvec3(shift, shift, 0);
            char name[64];
            std::snprintf(name, sizeof name, "%dd shifted by %g", dims, shift);
            const ExtremeCase c = shifted(base, offset, name);
            test::runExtremeCase(c);
            const std::vector<std::vector<int>> moved = exactPvs(c);
            int differing = 0;
            for (size_t f = 0; f < moved.size(); ++f) {
                differing += moved[f] != reference[f] ? 1 : 0;
                EXPECT_EQ(moved[f], reference[f]) << name << " frame " << f;
            }
            std::printf(
                "[precision] %s | exact PVS differs from the unshifted one in %d of %zu frames\n",
                name, differing, moved.size());
        }
    }
}

// A small grid (voxels of 1/256 unit) with objects up to 1e7 units, about 2.6e9
// voxels, away from it: voxel indices of such objects do not fit an int, and a
// grid culler must clamp them rather than let the conversion overflow (UBSan's
// float-cast-overflow reports it; unchecked, x86 turns it into INT_MIN and a row
// of the grid can turn opaque). The camera inside the grid sees the near ones.
TEST(ExtremesPrecision, ObjectsBillionsOfVoxelsFromTheGrid) {
    for (const int dims : {2, 3}) {
        Scene scene = dims == 3 ? test::makeScene(3, Aabb{{0, 0, 0}, {1, 1, 1}}, {40, 40, 40})
                                : test::makeScene(2, Aabb{{0, 0, 0}, {1, 1, 0}}, {256, 256, 1});
        const double z = dims == 3 ? 0.5 : 0.0;
        test::addSphere(scene, 0, {0.8, 0.8, z}, 0.05);
        test::addBox(scene, 1, {0.3, 0.6, dims == 3 ? 0.3 : 0.0},
                     {0.4, 0.7, dims == 3 ? 0.4 : 0.0});
        int id = 2;
        for (const double far : {10.0, 1e4, 1e6, 9999990.0}) {
            test::addSphere(scene, id++, {far, 0.5, z}, 1.0);
            test::addSphere(scene, id++, {0.5, -far, z}, 1.0);
            test::addBox(scene, id++, {-far - 1, 0.2, dims == 3 ? 0.2 : 0.0},
                         {-far, 0.9, dims == 3 ? 0.9 : 0.0});
        }
        ExtremeCase c{
            std::string(dims == 3 ? "3d" : "2d") + " objects up to 2.6e9 voxels from a small grid",
            scene,
            {},
            {}};
        const glm::dvec3 eye{0.1, 0.1, z};
        const glm::dvec3 targets[] = {{1, 1, z}, {-1, 0.1, z}, {0.1, -1, z}};
        for (int f = 0; f < 3; ++f)
            c.frames.push_back(
                {f * test::kDt,
                 makeCamera(dims, eye, targets[f], dims == 3 ? 90 : 360, 1.0, 0.01, 1e7),
                 f == 0 ? std::vector<int>{0} : std::vector<int>{},
                 {}});
        test::adoptCamera(c.scene, c.frames.front().camera);
        c.scene.finalize();
        test::runExtremeCase(c);
    }
}

// The same scene as a file: within the limit it loads, past it the loader names
// the first number beyond 1e7.
TEST(ExtremesPrecision, LoaderRejectsCoordinatesBeyondTheLimit) {
    auto text = [](double shift) {
        auto v = [&](double x, double y, double z) {
            char buffer[160];
            std::snprintf(buffer, sizeof buffer, "[%.17g, %.17g, %.17g]", x + shift, y + shift,
                          z + shift);
            return std::string(buffer);
        };
        return R"({ "format": "gridcull-scene/1", "dimensions": 3,
  "world": { "min": )" +
               v(0, 0, 0) + R"(, "max": )" + v(100, 100, 100) + R"( },
  "camera": { "path": [ { "t": 0, "position": )" +
               v(50, 50, 5) + R"(, "target": )" + v(50, 50, 100) + R"( } ] },
  "objects": [ { "shape": "sphere", "center": )" +
               v(50, 50, 50) + R"(, "radius": 1 } ] })";
    };
    EXPECT_EQ(test::loadErrors(text(1e4)), "");
    EXPECT_EQ(test::loadErrors(text(1e6)), "");
    EXPECT_EQ(test::loadErrors(text(1e7 - 100)), "");  // the largest corner is exactly 1e7
    const std::string errors = test::loadErrors(text(1e7));
    EXPECT_NE(errors.find("extreme.json: world.max[0]: must be at most 10000000 in magnitude (the "
                          "scene size limit), got 10000100"),
              std::string::npos)
        << errors;
    EXPECT_NE(errors.find("camera.path[0].position[0]: must be at most 10000000 in magnitude"),
              std::string::npos)
        << errors;
    const std::string negative = test::loadErrors(text(-1e7 - 1));
    EXPECT_NE(negative.find("world.min[0]: must be at most 10000000 in magnitude (the scene size "
                            "limit), got -10000001"),
              std::string::npos)
        << negative;
}

}  // namespace
}  // namespace gridcull
