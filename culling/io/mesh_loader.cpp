#include "culling/io/mesh_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include <tiny_obj_loader.h>
#include <glm/geometric.hpp>

namespace gridcull {

namespace {

// Row-major 3x3 rotation Rz * Ry * Rx from degrees.
struct Rotation {
    glm::dvec3 row[3];
};

Rotation eulerRotation(const glm::dvec3& degrees) {
    const glm::dvec3 r = degrees * (3.14159265358979323846 / 180.0);
    const double cx = std::cos(r.x), sx = std::sin(r.x);
    const double cy = std::cos(r.y), sy = std::sin(r.y);
    const double cz = std::cos(r.z), sz = std::sin(r.z);
    Rotation m;
    m.row[0] = {cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx};
    m.row[1] = {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx};
    m.row[2] = {-sy, cy * sx, cy * cx};
    return m;
}

// Maps each vertex to the first vertex at exactly the same position.
std::vector<uint32_t> weldedIds(const std::vector<glm::dvec3>& vertices) {
    std::vector<uint32_t> order(vertices.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = uint32_t(i);
    auto less = [&](uint32_t a, uint32_t b) {
        const glm::dvec3& p = vertices[a];
        const glm::dvec3& q = vertices[b];
        if (p.x != q.x) return p.x < q.x;
        if (p.y != q.y) return p.y < q.y;
        if (p.z != q.z) return p.z < q.z;
        return a < b;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<uint32_t> id(vertices.size());
    for (size_t i = 0; i < order.size(); ++i) {
        const bool same = i > 0 && vertices[order[i]] == vertices[order[i - 1]];
        id[order[i]] = same ? id[order[i - 1]] : order[i];
    }
    return id;
}

}  // namespace

bool isClosedMesh(const std::vector<glm::dvec3>& vertices, const std::vector<uint32_t>& indices) {
    if (indices.size() < 3) return false;
    const std::vector<uint32_t> id = weldedIds(vertices);
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    edges.reserve(indices.size());
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        for (int e = 0; e < 3; ++e) {
            uint32_t a = id[indices[t + size_t(e)]];
            uint32_t b = id[indices[t + size_t((e + 1) % 3)]];
            if (a > b) std::swap(a, b);
            edges.emplace_back(a, b);
        }
    }
    std::sort(edges.begin(), edges.end());
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i != 2) return false;
        i = j;
    }
    return true;
}

namespace {

MeshLoadResult buildMesh(const tinyobj::ObjReader& reader, const std::string& display_file,
                         double scale, const glm::dvec3& rotation_deg) {
    MeshLoadResult result;
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const size_t vertex_count = attrib.vertices.size() / 3;
    size_t corner_count = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes())
        corner_count += shape.mesh.indices.size();
    if (corner_count / 3 > kMaxMeshTriangles) {
        result.error = "has " + std::to_string(corner_count / 3) +
                       " triangles, more than the limit of " + std::to_string(kMaxMeshTriangles);
        return result;
    }
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->file = display_file;
    const Rotation rot = eulerRotation(rotation_deg);
    mesh->vertices.resize(vertex_count);
    for (size_t i = 0; i < vertex_count; ++i) {
        const glm::dvec3 p{attrib.vertices[3 * i], attrib.vertices[3 * i + 1],
                           attrib.vertices[3 * i + 2]};
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            result.error = "vertex " + std::to_string(i + 1) + " is not a finite position";
            return result;
        }
        const glm::dvec3 s = p * scale;
        mesh->vertices[i] = {glm::dot(rot.row[0], s), glm::dot(rot.row[1], s),
                             glm::dot(rot.row[2], s)};
    }
    mesh->indices.reserve(corner_count);
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const std::vector<tinyobj::index_t>& corners = shape.mesh.indices;
        for (size_t c = 0; c + 2 < corners.size(); c += 3) {
            uint32_t tri[3];
            for (int k = 0; k < 3; ++k) {
                const int v = corners[c + size_t(k)].vertex_index;
                if (v < 0 || size_t(v) >= vertex_count) {
                    result.error = "a face refers to vertex " + std::to_string(v + 1) +
                                   ", which does not exist";
                    return result;
                }
                tri[k] = uint32_t(v);
            }
            const glm::dvec3& a = mesh->vertices[tri[0]];
            const glm::dvec3& b = mesh->vertices[tri[1]];
            const glm::dvec3& d = mesh->vertices[tri[2]];
            if (a == b || b == d || a == d) continue;  // covers nothing
            mesh->indices.insert(mesh->indices.end(), tri, tri + 3);
        }
    }
    if (mesh->indices.empty()) {
        result.error = "contains no triangles";
        return result;
    }
    // Bounds over the vertices that triangles use: stray unused vertices must
    // not inflate the box a culler tests.
    bool first = true;
    for (uint32_t index : mesh->indices) {
        const glm::dvec3& p = mesh->vertices[index];
        if (first) {
            mesh->bounds = {p, p};
            first = false;
        }
        mesh->bounds.min = glm::min(mesh->bounds.min, p);
        mesh->bounds.max = glm::max(mesh->bounds.max, p);
    }
    mesh->closed = isClosedMesh(mesh->vertices, mesh->indices);
    result.mesh = std::move(mesh);
    return result;
}

tinyobj::ObjReaderConfig readerConfig() {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = "";  // materials are ignored: culling needs geometry only
    return config;
}

std::string firstLine(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    return line.empty() ? "unknown reason" : line;
}

}  // namespace

MeshLoadResult parseObjMesh(const std::string& obj_text, const std::string& display_file,
                            double scale, const glm::dvec3& rotation_deg) {
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(obj_text, "", readerConfig())) {
        MeshLoadResult result;
        result.error = "is not a readable OBJ file: " + firstLine(reader.Error());
        return result;
    }
    return buildMesh(reader, display_file, scale, rotation_deg);
}

MeshLoadResult loadObjMesh(const std::string& path, const std::string& display_file, double scale,
                           const glm::dvec3& rotation_deg) {
    MeshLoadResult result;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        result.error = std::filesystem::exists(path, ec)
                           ? "mesh file '" + path + "' is not a regular file"
                           : "mesh file '" + path + "' does not exist";
        return result;
    }
    // About 40 bytes of OBJ text per triangle, with room for comments and normals.
    constexpr uintmax_t kMaxObjBytes = uintmax_t(kMaxMeshTriangles) * 160;
    const uintmax_t bytes = std::filesystem::file_size(path, ec);
    if (!ec && bytes > kMaxObjBytes) {
        result.error = "mesh file '" + path + "' is larger than the limit of " +
                       std::to_string(kMaxObjBytes) + " bytes";
        return result;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        result.error = "cannot open mesh file '" + path + "'";
        return result;
    }
    // Read it ourselves (rather than ParseFromFile) so that a directory or an
    // unreadable file is reported as such, and so that `mtllib` lines cannot
    // make tinyobjloader open other files.
    std::ostringstream text;
    text << in.rdbuf();
    if (!in.good() && !in.eof()) {
        result.error = "cannot read mesh file '" + path + "'";
        return result;
    }
    const std::string obj = text.str();
    if (obj.empty()) {
        result.error = "mesh file '" + path + "' is empty";
        return result;
    }
    result = parseObjMesh(obj, display_file, scale, rotation_deg);
    if (!result.mesh && result.error.find(path) == std::string::npos)
        result.error = "mesh file '" + path + "' " + result.error;
    return result;
}

}  // namespace gridcull
