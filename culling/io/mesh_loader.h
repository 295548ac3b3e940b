// Triangle meshes for `"shape": "mesh"` objects (scene-format.md, "Objects"):
// Wavefront OBJ read with tinyobjloader, triangulated, scaled and rotated into
// object space, with bounds and closedness. Used by the scene loader; also
// usable on its own (tests, tools).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/scene/scene.h"

namespace gridcull {

// Larger meshes are rejected before they are copied: a culling test scene has
// no use for them and each copy would cost hundreds of MiB.
constexpr size_t kMaxMeshTriangles = 4'000'000;

struct MeshLoadResult {
    std::shared_ptr<TriangleMesh> mesh;  // set on success
    std::string error;                   // why not, without file name prefix
};

// Reads an OBJ file. Faces with more than three corners are fan-triangulated by
// tinyobjloader; faces that collapse to a line or point are dropped. Every
// vertex is scaled by `scale` (> 0) about the origin, then rotated by
// rotation_deg.x about +x, then .y about +y, then .z about +z (right-handed,
// degrees; the matrix is Rz * Ry * Rx). `display_file` goes into TriangleMesh::file.
// Fails on an unreadable or empty file, a face that names a missing vertex,
// a non-finite coordinate, or more than kMaxMeshTriangles triangles.
// Cost: O(n log n) in the triangle count.
MeshLoadResult loadObjMesh(const std::string& path, const std::string& display_file, double scale,
                           const glm::dvec3& rotation_deg);

// The same from OBJ text already in memory.
MeshLoadResult parseObjMesh(const std::string& obj_text, const std::string& display_file,
                            double scale, const glm::dvec3& rotation_deg);

// True when every edge is shared by exactly two triangles, so the triangles
// enclose a solid. Vertices at exactly the same position count as one (OBJ
// files often repeat positions along seams). Cost: O(n log n).
bool isClosedMesh(const std::vector<glm::dvec3>& vertices, const std::vector<uint32_t>& indices);

}  // namespace gridcull
