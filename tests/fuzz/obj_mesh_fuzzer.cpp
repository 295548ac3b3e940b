// libFuzzer target over the OBJ mesh reader (culling/io/mesh_loader.h), which
// reads the files that scene objects and mesh_crowd generators name: any byte
// string is handed to parseObjMesh. Properties, beyond "no crash, no sanitizer
// report, no leak, no hang": a mesh xor an error; a mesh has triangles, every
// index names a vertex, vertices and bounds are finite, the bounds contain
// every used vertex.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "culling/io/mesh_loader.h"

namespace {

void check(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "obj_mesh_fuzzer: property violated: %s\n", what);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace gridcull;
    const std::string text(reinterpret_cast<const char*>(data), size);
    const MeshLoadResult result = parseObjMesh(text, "fuzz.obj", 1.5, {10.0, 20.0, 30.0});
    check(bool(result.mesh) == result.error.empty(), "mesh xor error");
    if (!result.mesh) return 0;
    const TriangleMesh& mesh = *result.mesh;
    check(!mesh.indices.empty() && mesh.indices.size() % 3 == 0, "whole triangles");
    for (const glm::dvec3& v : mesh.vertices)
        check(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z), "finite vertices");
    for (const uint32_t i : mesh.indices) {
        check(i < mesh.vertices.size(), "index names a vertex");
        check(mesh.bounds.contains(mesh.vertices[i]), "bounds contain the used vertices");
    }
    return 0;
}
