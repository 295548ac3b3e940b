// Triangles for every shape the renderer draws, built once on the CPU: unit
// shapes that instances scale and move, and the scene's own meshes and polygons.
// Object space; every list is a plain triangle list (three vertices each) unless
// an index list is given.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/scene/scene.h"

namespace gridcull {

struct ShadedVertex {
    glm::vec3 position;
    glm::vec3 normal;
};

// Unit sphere (radius 1) as a latitude-longitude grid, smooth normals, indexed.
void buildUnitSphere(int slices, int stacks, std::vector<ShadedVertex>& vertices,
                     std::vector<uint32_t>& indices);
// Axis-aligned cube [-0.5, 0.5]^3 with flat face normals: 36 vertices.
void appendUnitCube(std::vector<ShadedVertex>& out);
// Disc of radius 1 in the z = 0 plane facing +z, `segments` triangles.
void appendUnitDisc(int segments, std::vector<ShadedVertex>& out);
// Square [-0.5, 0.5]^2 in the z = 0 plane facing +z: 6 vertices.
void appendUnitSquare(std::vector<ShadedVertex>& out);
// A scene mesh with flat normals, vertices relative to the object's position.
void appendMesh(const TriangleMesh& mesh, std::vector<ShadedVertex>& out);
// A 2D polygon object triangulated by ear clipping, relative to its anchor at
// t = 0, facing +z. Returns false when the outline could not be triangulated
// fully (the triangles found are still appended).
bool appendPolygon(const SceneObject& object, std::vector<ShadedVertex>& out);

}  // namespace gridcull
