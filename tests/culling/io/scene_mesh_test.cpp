// Mesh objects: OBJ loading, triangulation, scale and rotation, closedness
// (every edge shared by exactly two triangles), and sharing between objects.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "culling/io/mesh_loader.h"
#include "culling/io/scene_loader.h"

namespace gridcull {
namespace {

std::string sourcePath(const std::string& relative) {
    return std::string(GRIDCULL_SOURCE_DIR) + "/" + relative;
}

constexpr double kTolerance = 1e-9;

// The bunny's extent as its OBJ file states it (x, y, z min then max); the
// loader keeps positions in float (tinyobjloader), hence the 1e-5 below.
const glm::dvec3 kBunnyMin{-4.958475, -0.003149, -3.729833};
const glm::dvec3 kBunnyMax{4.94885, 9.654748, 3.810639};
constexpr double kFloatTolerance = 1e-5;

TEST(SceneMesh, BunnyIsClosedWithAllItsTriangles) {
    const MeshLoadResult r =
        loadObjMesh(sourcePath("scenes/meshes/bunny.obj"), "bunny.obj", 1.0, glm::dvec3(0.0));
    ASSERT_TRUE(r.mesh) << r.error;
    EXPECT_EQ(r.mesh->indices.size(), 3u * 3674u);
    EXPECT_EQ(r.mesh->vertices.size(), 1839u);
    EXPECT_TRUE(r.mesh->closed);
    EXPECT_EQ(r.mesh->file, "bunny.obj");
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(r.mesh->bounds.min[axis], kBunnyMin[axis], kFloatTolerance);
        EXPECT_NEAR(r.mesh->bounds.max[axis], kBunnyMax[axis], kFloatTolerance);
    }
}

TEST(SceneMesh, OpenMeshesAreNotClosed) {
    MeshLoadResult r = loadObjMesh(sourcePath("tests/scenes/meshes/open-box.obj"), "open-box.obj",
                                   1.0, glm::dvec3(0.0));
    ASSERT_TRUE(r.mesh) << r.error;
    EXPECT_EQ(r.mesh->indices.size(), 30u);
    EXPECT_FALSE(r.mesh->closed);
    // A quad is triangulated into two triangles.
    r = loadObjMesh(sourcePath("tests/scenes/meshes/quad.obj"), "quad.obj", 1.0, glm::dvec3(0.0));
    ASSERT_TRUE(r.mesh) << r.error;
    EXPECT_EQ(r.mesh->indices.size(), 6u);
    EXPECT_FALSE(r.mesh->closed);
}

TEST(SceneMesh, RepeatedPositionsAreWeldedForClosedness) {
    const MeshLoadResult r = loadObjMesh(sourcePath("tests/scenes/meshes/tetrahedron.obj"),
                                         "tetrahedron.obj", 1.0, glm::dvec3(0.0));
    ASSERT_TRUE(r.mesh) << r.error;
    EXPECT_TRUE(r.mesh->closed);
}

TEST(SceneMesh, IsClosedMeshCountsEdgeUses) {
    const std::vector<glm::dvec3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    EXPECT_FALSE(isClosedMesh(v, {0, 1, 2}));
    EXPECT_TRUE(isClosedMesh(v, {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3}));
    // A fin: three triangles on one edge.
    EXPECT_FALSE(isClosedMesh(v, {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3, 0, 1, 2}));
    EXPECT_FALSE(isClosedMesh(v, {}));
}

TEST(SceneMesh, ScaleThenRotateXYZ) {
    const std::string tri = "v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n";
    // 90 degrees about z takes +x to +y.
    MeshLoadResult r = parseObjMesh(tri, "t.obj", 2.0, glm::dvec3(0, 0, 90));
    ASSERT_TRUE(r.mesh) << r.error;
    EXPECT_NEAR(glm::length(r.mesh->vertices[0] - glm::dvec3(0, 2, 0)), 0.0, kTolerance);
    EXPECT_NEAR(glm::length(r.mesh->vertices[1] - glm::dvec3(-2, 0, 0)), 0.0, kTolerance);
    // x first, then y: +x -> +x -> -z; +y -> +z -> +x; +z -> -y -> -y.
    r = parseObjMesh(tri, "t.obj", 1.0, glm::dvec3(90, 90, 0));
    ASSERT_TRUE(r.mesh) << r.error;
    EXPECT_NEAR(glm::length(r.mesh->vertices[0] - glm::dvec3(0, 0, -1)), 0.0, kTolerance);
    EXPECT_NEAR(glm::length(r.mesh->vertices[1] - glm::dvec3(1, 0, 0)), 0.0, kTolerance);
    EXPECT_NEAR(glm::length(r.mesh->vertices[2] - glm::dvec3(0, -1, 0)), 0.0, kTolerance);
    EXPECT_NEAR(glm::length(r.mesh->bounds.max - glm::dvec3(1, 0, 0)), 0.0, kTolerance);
    EXPECT_NEAR(glm::length(r.mesh->bounds.min - glm::dvec3(0, -1, -1)), 0.0, kTolerance);
}

TEST(SceneMesh, BadObjContentIsAnError) {
    EXPECT_FALSE(parseObjMesh("v 0 0 0\nv 1 0 0\nf 1 2 7\n", "x.obj", 1.0, glm::dvec3(0)).mesh);
    EXPECT_FALSE(parseObjMesh("# nothing\n", "x.obj", 1.0, glm::dvec3(0)).mesh);
    // Degenerate faces cover nothing and are dropped; only they: no mesh.
    EXPECT_FALSE(parseObjMesh("v 0 0 0\nv 1 0 0\nf 1 2 2\n", "x.obj", 1.0, glm::dvec3(0)).mesh);
    const MeshLoadResult missing =
        loadObjMesh(sourcePath("tests/scenes/meshes/none.obj"), "none.obj", 1.0, glm::dvec3(0));
    EXPECT_FALSE(missing.mesh);
    EXPECT_NE(missing.error.find("does not exist"), std::string::npos) << missing.error;
}

TEST(SceneMesh, SceneMeshesArePlacedScaledRotatedAndShared) {
    const SceneLoadResult r = loadSceneFile(sourcePath("scenes/mesh-3d.json"));
    ASSERT_TRUE(r.scene.has_value()) << (r.errors.empty() ? "" : r.errors[0]);
    const Scene& s = *r.scene;
    const SceneObject& big = s.objects[size_t(s.indexOf(1))];
    const SceneObject& turned = s.objects[size_t(s.indexOf(2))];
    const SceneObject& walker = s.objects[size_t(s.indexOf(3))];
    ASSERT_EQ(big.shape, ShapeKind::Mesh);
    EXPECT_EQ(big.mesh->file, "meshes/bunny.obj");
    EXPECT_EQ(big.anchor, glm::dvec3(40, 0, 40));
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(big.bounds.min[axis], big.anchor[axis] + 1.5 * kBunnyMin[axis],
                    kFloatTolerance);
        EXPECT_NEAR(big.bounds.max[axis], big.anchor[axis] + 1.5 * kBunnyMax[axis],
                    kFloatTolerance);
    }
    // 90 degrees about y maps (x, z) to (z, -x).
    EXPECT_NEAR(turned.bounds.min.x - turned.anchor.x, kBunnyMin.z, kFloatTolerance);
    EXPECT_NEAR(turned.bounds.max.z - turned.anchor.z, -kBunnyMin.x, kFloatTolerance);
    EXPECT_TRUE(big.mesh->closed);
    // Same file, scale and rotation: one shared mesh.
    int sharing_walker = 0, crowd = 0;
    for (const SceneObject& o : s.objects) {
        if (o.shape != ShapeKind::Mesh) continue;
        if (o.mesh == walker.mesh) ++sharing_walker;
        if (o.id > 5) ++crowd;
    }
    EXPECT_GE(sharing_walker, 1);
    EXPECT_EQ(crowd, 20);
    EXPECT_NE(big.mesh, walker.mesh);
    EXPECT_EQ(walker.motion.kind, MotionKind::Keyframes);
    EXPECT_EQ(s.positionAt(3, 6.0), glm::dvec3(60, 0, 60));
}

}  // namespace
}  // namespace gridcull
