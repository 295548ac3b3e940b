// The scene writer (culling/io/scene_writer.h) against the loader: a written
// random scene of every kind the sweep makes loads as the same objects,
// motions, camera, grid and time; written and loaded once more it is
// identical, field by field; and the oracle and every conservative culler give
// the same PVS on both at every frame, so a written failure replays.
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"
#include "culling/io/scene_writer.h"
#include "culling/registry/registry.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/common/test_seeds.h"
#include "tests/sweep/sweep_check.h"
#include "tests/sweep/sweep_scenes.h"

namespace gridcull {
namespace {

// Mesh vertices are rounded to floats before writing (sweep::snapMeshes), as
// the loader's OBJ reader reads them: relative error at most 2^-24.
constexpr double kFloatRelative = 0x1p-24;
// The loader's own allowance for a declared speed below the real one
// (culling/io/scene_loader_objects.cpp), relative.
constexpr double kSpeedTolerance = 1e-9;

std::string tempFile(const std::string& name) {
    const std::string dir = ::testing::TempDir() + "scene-writer-" + std::to_string(::getpid());
    std::filesystem::create_directories(dir);
    return dir + "/" + name;
}

// Every field a culler reads. `exact`: mesh vertices and max speeds equal,
// else within a float's rounding and the loader's speed allowance.
void expectSameScene(const Scene& a, const Scene& b, bool exact, bool random_walks) {
    EXPECT_EQ(a.dimensions, b.dimensions);
    EXPECT_EQ(a.grid.world.min, b.grid.world.min);
    EXPECT_EQ(a.grid.world.max, b.grid.world.max);
    EXPECT_EQ(a.grid.resolution, b.grid.resolution);
    EXPECT_EQ(a.frames, b.frames);
    EXPECT_EQ(a.dt, b.dt);
    EXPECT_EQ(a.seed, b.seed);
    EXPECT_EQ(a.camera.fov_deg, b.camera.fov_deg);
    EXPECT_EQ(a.camera.aspect, b.camera.aspect);
    EXPECT_EQ(a.camera.near, b.camera.near);
    EXPECT_EQ(a.camera.far, b.camera.far);
    ASSERT_EQ(a.camera.path.size(), b.camera.path.size());
    for (size_t k = 0; k < a.camera.path.size(); ++k) {
        EXPECT_EQ(a.camera.path[k].t, b.camera.path[k].t) << "camera key " << k;
        EXPECT_EQ(a.camera.path[k].position, b.camera.path[k].position) << "camera key " << k;
        EXPECT_EQ(a.camera.path[k].target, b.camera.path[k].target) << "camera key " << k;
        if (a.dimensions == 3) {
            EXPECT_EQ(a.camera.path[k].up, b.camera.path[k].up);
        }
    }
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (size_t i = 0; i < a.objects.size(); ++i) {
        const SceneObject& p = a.objects[i];
        const SceneObject& q = b.objects[i];
        SCOPED_TRACE("object id " + std::to_string(p.id));
        ASSERT_EQ(p.id, q.id);
        ASSERT_EQ(p.shape, q.shape);
        EXPECT_EQ(p.anchor, q.anchor);
        switch (p.shape) {
            case ShapeKind::Sphere:
                EXPECT_EQ(p.center, q.center);
                EXPECT_EQ(p.radius, q.radius);
                break;
            case ShapeKind::Box:
                EXPECT_EQ(p.box.min, q.box.min);
                EXPECT_EQ(p.box.max, q.box.max);
                break;
            case ShapeKind::Polygon:
                EXPECT_EQ(p.points, q.points);
                break;
            case ShapeKind::Mesh:
                ASSERT_EQ(p.mesh->vertices.size(), q.mesh->vertices.size());
                EXPECT_EQ(p.mesh->indices, q.mesh->indices);
                EXPECT_EQ(p.mesh->closed, q.mesh->closed);
                for (size_t v = 0; v < p.mesh->vertices.size(); ++v)
                    for (int c = 0; c < 3; ++c)
                        ASSERT_NEAR(
                            p.mesh->vertices[v][c], q.mesh->vertices[v][c],
                            exact ? 0.0 : kFloatRelative * std::fabs(p.mesh->vertices[v][c]))
                            << "vertex " << v;
                break;
        }
        if (exact) {
            EXPECT_EQ(p.bounds.min, q.bounds.min);
            EXPECT_EQ(p.bounds.max, q.bounds.max);
        }
        const Motion& m = p.motion;
        const Motion& n = q.motion;
        ASSERT_EQ(m.kind, n.kind);
        if (exact) {
            EXPECT_EQ(m.max_speed, n.max_speed);
        } else {
            // The loader keeps the larger of the declared and the real speed,
            // which its own rounding may put a few ulps above the declared.
            EXPECT_NEAR(m.max_speed, n.max_speed, kSpeedTolerance * std::max(1.0, m.max_speed));
        }
        EXPECT_EQ(m.velocity, n.velocity);
        ASSERT_EQ(m.keys.size(), n.keys.size());
        for (size_t k = 0; k < m.keys.size(); ++k) {
            EXPECT_EQ(m.keys[k].t, n.keys[k].t);
            EXPECT_EQ(m.keys[k].position, n.keys[k].position);
        }
        if (random_walks) {
            EXPECT_EQ(m.segment_seconds, n.segment_seconds);
            EXPECT_EQ(m.segment_velocities, n.segment_velocities);
        }
    }
}

// The scenes the sweep checks: two of each kind (2D, 3D, meshes, rooms, the
// edges). GRIDCULL_SEED=N checks one.
TEST(SceneWriter, WrittenRandomScenesLoadAsTheSameScene) {
    for (const uint64_t seed : test::seedsToRun(7000, 2 * sweep::kSceneKinds)) {
        test::withSeed(seed, [&] {
            Scene generated = sweep::generatedScene(seed);
            sweep::snapMeshes(generated);
            const std::string file = tempFile("first.json");
            std::string error;
            ASSERT_TRUE(writeSceneFile(generated, file, error)) << error;
            const SceneLoadResult first = loadSceneFile(file);
            ASSERT_TRUE(first.scene) << first.errors.front();
            // As generated (random walks are the loader's own) ...
            expectSameScene(generated, *first.scene, false, false);

            // ... and a loaded scene comes back bit for bit.
            const std::string again = tempFile("second.json");
            ASSERT_TRUE(writeSceneFile(*first.scene, again, error)) << error;
            const SceneLoadResult second = loadSceneFile(again);
            ASSERT_TRUE(second.scene) << second.errors.front();
            expectSameScene(*first.scene, *second.scene, true, true);
        });
    }
}

// Every culler and the oracle give the same PVS on `a` and `b` at every frame.
void expectSamePvs(const Scene& a, const Scene& b, const KnobValues& knobs) {
    std::vector<std::string> names = {referenceAlgorithm()};
    for (const sweep::SweepAlgorithm& algo : sweep::conservativeAlgorithms())
        names.push_back(algo.name);
    for (const std::string& name : names) {
        std::string why;
        if (!algorithmFits(name, a, why)) continue;
        auto on_a = test::makeOrDie(name, knobs);
        auto on_b = test::makeOrDie(name, knobs);
        on_a->reset(a);
        on_b->reset(b);
        FrameResult ra, rb;
        for (int f = 0; f < a.frames; ++f) {
            const double t = a.timeOfFrame(f);
            on_a->cull(a, cameraAt(a, t), t, ra);
            on_b->cull(b, cameraAt(b, t), t, rb);
            ASSERT_EQ(ra.pvs, rb.pvs) << name << " frame " << f;
        }
    }
}

// The replay: the scene the sweep checks (written and loaded once) gives every
// culler and the oracle the PVS it gave the scene as generated (unless that
// has random walks, which the loader rebuilds its own way), and the file it
// writes of it gives the same PVS again, frame by frame.
TEST(SceneWriter, ReloadedSceneGivesTheSamePvsEveryFrame) {
    KnobValues knobs;
    knobs.set("oracle-res", 64);
    for (const uint64_t seed : test::seedsToRun(7100, sweep::kSceneKinds)) {
        test::withSeed(seed, [&] {
            Scene generated = sweep::generatedScene(seed);
            sweep::snapMeshes(generated);
            Scene checked;
            std::string error;
            ASSERT_TRUE(sweep::replayable(generated, tempFile("a.json"), checked, error)) << error;
            const bool walks = std::any_of(
                generated.objects.begin(), generated.objects.end(),
                [](const SceneObject& o) { return o.motion.kind == MotionKind::Random; });
            if (!walks) expectSamePvs(generated, checked, knobs);
            ASSERT_TRUE(writeSceneFile(checked, tempFile("b.json"), error)) << error;
            const SceneLoadResult reloaded = loadSceneFile(tempFile("b.json"));
            ASSERT_TRUE(reloaded.scene) << reloaded.errors.front();
            expectSamePvs(checked, *reloaded.scene, knobs);
        });
    }
}

// Mesh coordinates that are floats come back exactly; others come back as
// the nearest float, as any OBJ file does through the loader.
TEST(SceneWriter, MeshVerticesComeBackAsFloats) {
    Scene scene = test::scene3d();
    test::setCamera(scene, {50, 50, -20}, {50, 50, 50}, 60.0);
    test::addMesh(scene, 0, {50, 50, 50}, test::cubeMesh(double(0.1f)));
    test::addMesh(scene, 1, {20, 50, 50}, test::tetrahedronMesh(double(-3.3e-7f)));
    test::addMesh(scene, 2, {20, 50, 50}, test::quadMesh(0.1));
    scene.finalize();
    std::string error;
    ASSERT_TRUE(writeSceneFile(scene, tempFile("meshes.json"), error)) << error;
    const SceneLoadResult loaded = loadSceneFile(tempFile("meshes.json"));
    ASSERT_TRUE(loaded.scene) << loaded.errors.front();
    EXPECT_EQ(loaded.scene->objects[0].mesh->vertices, scene.objects[0].mesh->vertices);
    EXPECT_EQ(loaded.scene->objects[1].mesh->vertices, scene.objects[1].mesh->vertices);
    EXPECT_EQ(loaded.scene->objects[2].mesh->vertices[2],
              glm::dvec3(double(0.1f), double(0.1f), 0));
}

// A file that cannot be written is named in the error, and nothing throws.
TEST(SceneWriter, UnwritablePathIsNamed) {
    Scene scene = test::sphereWallScene();
    std::string error;
    EXPECT_FALSE(writeSceneFile(scene, "/nonexistent-dir/x.json", error));
    EXPECT_NE(error.find("/nonexistent-dir/x.json"), std::string::npos) << error;
}

}  // namespace
}  // namespace gridcull
