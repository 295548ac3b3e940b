// Scenes built in code for the oracle, vfc and baseline tests: small builders
// that fill Scene fields the way the loader does (shape, anchor, bounds) so that
// each test can state its geometry in a few lines.
#pragma once
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/api/culler.h"
#include "culling/registry/registry.h"
#include "culling/scene/camera.h"
#include "culling/scene/scene.h"

namespace gridcull::test {

// A scene with no objects over `world` cut into `resolution` voxels. 2D: pass a
// world with z min == max == 0; resolution.z is forced to 1.
inline Scene makeScene(int dimensions, const Aabb& world, glm::ivec3 resolution) {
    Scene scene;
    scene.name = "test";
    scene.dimensions = dimensions;
    scene.grid.dimensions = dimensions;
    scene.grid.world = world;
    if (dimensions == 2) resolution.z = 1;
    scene.grid.resolution = resolution;
    return scene;
}

// The usual 3D test world: [0, 100]^3 in 10^3 voxels (a voxel is 10 units).
inline Scene scene3d() {
    return makeScene(3, Aabb{{0, 0, 0}, {100, 100, 100}}, {10, 10, 10});
}
// The usual 2D test world: [0, 100]^2 in 10 x 10 voxels.
inline Scene scene2d() {
    return makeScene(2, Aabb{{0, 0, 0}, {100, 100, 0}}, {10, 10, 1});
}

inline void addSphere(Scene& scene, int id, const glm::dvec3& center, double radius) {
    SceneObject o;
    o.id = id;
    o.shape = ShapeKind::Sphere;
    o.center = center;
    o.radius = radius;
    o.anchor = center;
    const glm::dvec3 r = scene.dimensions == 2 ? glm::dvec3(radius, radius, 0) : glm::dvec3(radius);
    o.bounds = Aabb{center - r, center + r};
    scene.objects.push_back(o);
}

inline void addBox(Scene& scene, int id, const glm::dvec3& min, const glm::dvec3& max) {
    SceneObject o;
    o.id = id;
    o.shape = ShapeKind::Box;
    o.box = Aabb{min, max};
    o.bounds = o.box;
    o.anchor = o.box.center();
    scene.objects.push_back(o);
}

// 2D: a simple polygon, counter-clockwise.
inline void addPolygon(Scene& scene, int id, const std::vector<glm::dvec3>& points) {
    SceneObject o;
    o.id = id;
    o.shape = ShapeKind::Polygon;
    o.points = points;
    o.bounds = Aabb{points.front(), points.front()};
    for (const glm::dvec3& p : points) o.bounds.merge(Aabb{p, p});
    o.anchor = o.bounds.center();
    scene.objects.push_back(o);
}

inline void addMesh(Scene& scene, int id, const glm::dvec3& position,
                    std::shared_ptr<const TriangleMesh> mesh) {
    SceneObject o;
    o.id = id;
    o.shape = ShapeKind::Mesh;
    o.center = position;
    o.anchor = position;
    o.bounds = mesh->bounds.translated(position);
    o.mesh = std::move(mesh);
    scene.objects.push_back(o);
}

inline std::shared_ptr<TriangleMesh> finishMesh(std::vector<glm::dvec3> vertices,
                                                std::vector<uint32_t> indices, bool closed) {
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->file = "test";
    mesh->vertices = std::move(vertices);
    mesh->indices = std::move(indices);
    mesh->closed = closed;
    mesh->bounds = Aabb{mesh->vertices.front(), mesh->vertices.front()};
    for (const glm::dvec3& v : mesh->vertices) mesh->bounds.merge(Aabb{v, v});
    return mesh;
}

// A closed cube of half-size h around the origin, 12 triangles.
inline std::shared_ptr<TriangleMesh> cubeMesh(double h) {
    std::vector<glm::dvec3> v;
    for (int i = 0; i < 8; ++i) v.push_back({(i & 1) ? h : -h, (i & 2) ? h : -h, (i & 4) ? h : -h});
    // Two triangles per face, outward winding.
    std::vector<uint32_t> idx = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    return finishMesh(v, idx, true);
}

// A closed tetrahedron with corners at distance ~s from the origin.
inline std::shared_ptr<TriangleMesh> tetrahedronMesh(double s) {
    std::vector<glm::dvec3> v = {{s, s, s}, {s, -s, -s}, {-s, s, -s}, {-s, -s, s}};
    std::vector<uint32_t> idx = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
    return finishMesh(v, idx, true);
}

// An open square of half-size h in the x-y plane (two triangles, not closed).
inline std::shared_ptr<TriangleMesh> quadMesh(double h) {
    std::vector<glm::dvec3> v = {{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}};
    return finishMesh(v, {0, 1, 2, 0, 2, 3}, false);
}

// One camera key; 3D fov is vertical, 2D fov is the wedge.
inline void setCamera(Scene& scene, const glm::dvec3& position, const glm::dvec3& target,
                      double fov_deg, double near = 0.1, double far = 1000.0) {
    scene.camera.fov_deg = fov_deg;
    scene.camera.near = near;
    scene.camera.far = far;
    scene.camera.path = {CameraKey{0.0, position, target, {0.0, 1.0, 0.0}}};
}

// A wall seen face on, five spheres hidden behind it, one peeking over its top
// edge, one beside it: an image-space culler keeps the wall and the two.
inline Scene sphereWallScene() {
    Scene scene = scene3d();
    setCamera(scene, {50, 20, 0}, {50, 20, 100}, 60.0);
    addBox(scene, 1, {30, 0, 30}, {70, 30, 31});
    for (int k = 0; k < 5; ++k) addSphere(scene, 10 + k, {35 + 7.5 * k, 15, 60}, 3);
    addSphere(scene, 20, {50, 38, 60}, 3.2);
    addSphere(scene, 21, {100, 15, 60}, 3);
    scene.finalize();
    return scene;
}

// Resets `culler` for the scene and returns its PVS at time t.
inline std::vector<int> cullIds(Culler& culler, const Scene& scene, double t = 0.0) {
    culler.reset(scene);
    FrameResult result;
    culler.cull(scene, cameraAt(scene, t), t, result);
    return result.pvs;
}

inline std::unique_ptr<Culler> makeOrDie(const std::string& name,
                                         const KnobValues& knobs = KnobValues{}) {
    std::string error;
    auto culler = makeCuller(name, knobs, error);
    if (!culler) std::abort();
    return culler;
}

inline bool isSubset(const std::vector<int>& sub, const std::vector<int>& super) {
    return std::includes(super.begin(), super.end(), sub.begin(), sub.end());
}

}  // namespace gridcull::test
