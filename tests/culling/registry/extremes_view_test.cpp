// Extremes of the view, every algorithm against the exact
// oracle (extremes_harness.h): fields of view of 0.01, 1, 90 and 179 degrees in
// 3D and from 0.01 up to 360 in 2D; a tiny near plane; a far plane far beyond the
// world, and one that cuts the scene. Also 1e-6 and 179.999 degrees, which
// the loader accepts. And what the loader rejects, with the
// message it gives: fov 0, negative, >= 180 in 3D (> 360 in 2D), NaN and
// infinite values, near <= 0, near >= far.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/culling/registry/extremes_harness.h"
#include "tests/culling/registry/extremes_scenes.h"

namespace gridcull {
namespace {

using test::ExtremeCase;
using test::makeCamera;

// The lattice scene plus markers: one straight ahead far away (on the view
// axis, seen at any fov), one far off the axis (about 80 degrees, seen only by
// the widest views).
Scene viewScene(int dims) {
    Scene scene = test::latticeScene(dims);
    const double z = dims == 3 ? 45.0 : 0.0;
    test::addSphere(scene, 1000, {45, 500, z}, 2.0);       // ahead, beyond the world
    test::addSphere(scene, 1001, {45 + 11.3, 2, z}, 0.5);  // ~80 degrees to the side
    return scene;
}

TEST(ExtremesView, FieldsOfView3d) {
    const glm::dvec3 eye{45, 0.5, 45};
    const glm::dvec3 ahead{45, 100, 45};
    for (const double fov : {1e-6, 0.01, 1.0, 90.0, 179.0, 179.999}) {
        ExtremeCase c{"3d fov " + std::to_string(fov), viewScene(3), {}, {}};
        // The far marker is straight ahead, in the clear between lattice objects
        // (x = z = 45 misses every lattice sphere and box).
        // At 179 degrees a pixel spans 0.4 in the image plane (tan units), the
        // far marker 0.004: it falls between the oracle's samples, so it is
        // required only at narrower fovs (exact_oracle.h, "Exactness").
        const std::vector<int> see = fov < 100.0 ? std::vector<int>{1000} : std::vector<int>{};
        for (int f = 0; f < 3; ++f)
            c.frames.push_back(
                {f * test::kDt, makeCamera(3, eye, ahead, fov, 16.0 / 9.0), see, {}});
        // At 179.999 degrees the image plane spans +-114591 (tan units) over 576
        // rows: even the pixel centres next to the middle look 89.7 degrees off
        // the axis, so the oracle sees next to nothing (the last frame's PVS is
        // empty) and the check against it says little. A perspective image
        // cannot sample a view that close to 180 degrees; docs/LIMITS.md.
        if (fov == 179.0) c.frames.back().must_see.push_back(1001);
        test::adoptCamera(c.scene, c.frames.front().camera);
        c.scene.finalize();
        test::runExtremeCase(c);
    }
}

TEST(ExtremesView, FieldsOfView2d) {
    const glm::dvec3 eye{45, 0.5, 0};
    const glm::dvec3 ahead{45, 100, 0};
    for (const double fov : {1e-6, 0.01, 1.0, 90.0, 179.0, 180.0, 181.0, 270.0, 359.99, 360.0}) {
        ExtremeCase c{"2d fov " + std::to_string(fov), viewScene(2), {}, {}};
        for (int f = 0; f < 3; ++f)
            c.frames.push_back({f * test::kDt, makeCamera(2, eye, ahead, fov), {1000}, {}});
        if (fov >= 170.0) c.frames.back().must_see.push_back(1001);
        test::adoptCamera(c.scene, c.frames.front().camera);
        c.scene.finalize();
        test::runExtremeCase(c);
    }
}

TEST(ExtremesView, TinyNearPlaneAndFarPlanes) {
    for (const int dims : {2, 3}) {
        const std::string d = dims == 3 ? "3d " : "2d ";
        const double z = dims == 3 ? 45.0 : 0.0;
        const glm::dvec3 eye{45, 0.5, z};
        const glm::dvec3 ahead{45, 100, z};
        const double fov = dims == 3 ? 60.0 : 90.0;
        struct Planes {
            const char* name;
            double near, far;
            std::vector<int> see, hide;
        };
        const Planes planes[] = {
            {"near 1e-9, far 1e7", 1e-9, 1e7, {1000}, {}},
            {"near 1e-6 with an object 1e-5 ahead", 1e-6, 1000, {1002}, {1000}},
            {"far 1e6 beyond the world", 0.1, 1e6, {1000}, {}},
            {"far 30 cutting the grid", 0.1, 30, {}, {1000}},
        };
        for (const Planes& p : planes) {
            Scene scene = viewScene(dims);
            if (p.see == std::vector<int>{1002}) {
                // A tiny sphere right in front of the eye fills the view.
                test::addSphere(scene, 1002, eye + glm::dvec3(0, 2e-5, 0), 1e-5);
            }
            ExtremeCase c{d + p.name, scene, {}, {}};
            for (int f = 0; f < 3; ++f)
                c.frames.push_back({f * test::kDt,
                                    makeCamera(dims, eye, ahead, fov, 1.0, p.near, p.far), p.see,
                                    p.hide});
            test::adoptCamera(c.scene, c.frames.front().camera);
            c.scene.finalize();
            test::runExtremeCase(c);
        }
    }
}

// A valid scene file around one camera; `camera` is the text of the camera
// object's fields before "path".
std::string sceneText(int dims, const std::string& camera) {
    const std::string v0 = dims == 3 ? "[0, 0, 0]" : "[0, 0]";
    const std::string v1 = dims == 3 ? "[100, 100, 100]" : "[100, 100]";
    const std::string v2 = dims == 3 ? "[50, 50, 50]" : "[50, 50]";
    return R"({ "format": "gridcull-scene/1", "dimensions": )" + std::to_string(dims) +
           R"(, "world": { "min": )" + v0 + R"(, "max": )" + v1 + R"( },
  "camera": { )" +
           camera + R"( "path": [ { "t": 0, "position": )" + v0 + R"(, "target": )" + v2 +
           R"( } ] },
  "objects": [ { "shape": "sphere", "center": )" +
           v2 + R"(, "radius": 1 } ] })";
}

TEST(ExtremesView, LoaderAcceptsTheExtremeFieldsOfView) {
    for (const char* fov : {"0.01", "1e-6", "1", "90", "179", "179.999"})
        EXPECT_EQ(test::loadErrors(sceneText(3, std::string(R"("fov_deg": )") + fov + ",")), "")
            << "3D fov " << fov;
    for (const char* fov : {"0.01", "1", "179", "180", "181", "359.99", "360"})
        EXPECT_EQ(test::loadErrors(sceneText(2, std::string(R"("fov_deg": )") + fov + ",")), "")
            << "2D fov " << fov;
    EXPECT_EQ(test::loadErrors(sceneText(3, R"("near": 1e-9, "far": 1e7,)")), "");
}

TEST(ExtremesView, LoaderRejectsFieldsOfViewOutOfRangeWithAClearMessage) {
    const std::string in3d =
        "extreme.json: camera.fov_deg: must be a number of degrees in (0, 180)";
    const std::string in2d =
        "extreme.json: camera.fov_deg: must be a number of degrees in (0, 360]";
    struct Bad {
        int dims;
        const char* fov;
        std::string message;
    };
    const Bad bad[] = {
        {3, "0", in3d + ", got 0"},
        {3, "-0.0", in3d + ", got -0.0"},
        {3, "-30", in3d + ", got -30"},
        {3, "180", in3d + ", got 180"},
        {3, "180.0001", in3d + ", got 180.0001"},
        {3, "360", in3d + ", got 360"},
        {3, "1e7", in3d + ", got 10000000.0"},
        {3, "\"60\"", in3d + ", got \"60\""},
        {3, "null", in3d + ", got null"},
        {2, "0", in2d + ", got 0"},
        {2, "-1", in2d + ", got -1"},
        {2, "360.01", in2d + ", got 360.01"},
        {2, "720", in2d + ", got 720"},
        // Beyond a double: nlohmann reports it while parsing, we name the number.
        {3, "1e999", "number 1e999 is out of range: must be a finite number"},
        {2, "-1e999", "number -1e999 is out of range: must be a finite number"},
        // JSON has no NaN or Infinity: they are syntax errors with a position
        // and the path of the value being read.
        {3, "NaN",
         "parse error in camera.fov_deg: syntax error while parsing value - invalid literal"},
        {3, "Infinity",
         "parse error in camera.fov_deg: syntax error while parsing value - invalid literal"},
        {2, "-Infinity",
         "parse error in camera.fov_deg: syntax error while parsing value - invalid number"},
    };
    for (const Bad& b : bad) {
        const std::string errors =
            test::loadErrors(sceneText(b.dims, std::string(R"("fov_deg": )") + b.fov + ","));
        EXPECT_NE(errors.find(b.message), std::string::npos)
            << b.dims << "D fov " << b.fov << ": got\n"
            << errors;
    }
}

TEST(ExtremesView, LoaderRejectsBadNearAndFarWithAClearMessage) {
    struct Bad {
        const char* camera;
        const char* message;
    };
    const Bad bad[] = {
        {R"("near": 0,)", "camera.near: must be a finite number > 0, got 0"},
        {R"("near": -1,)", "camera.near: must be a finite number > 0, got -1"},
        {R"("near": 5, "far": 5,)", "camera.near: must be less than camera.far = 5, got 5"},
        {R"("near": 10, "far": 1,)", "camera.near: must be less than camera.far = 1, got 10"},
        {R"("far": 1e8,)",
         "camera.far: must be at most 10000000 in magnitude (the scene size limit), got "
         "100000000.0"},
        {R"("aspect": 0,)", "camera.aspect: must be a finite number > 0, got 0"},
    };
    for (const Bad& b : bad) {
        const std::string errors = test::loadErrors(sceneText(3, b.camera));
        EXPECT_NE(errors.find(b.message), std::string::npos) << b.camera << ": got\n" << errors;
    }
}

}  // namespace
}  // namespace gridcull
