#include "app/shape_geometry.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "grid/polygon_triangulate.h"

namespace gridcull {

namespace {

constexpr double kPi = 3.14159265358979323846;

void triangle(std::vector<ShadedVertex>& out, glm::vec3 a, glm::vec3 b, glm::vec3 c,
              glm::vec3 n) {
    out.push_back({a, n});
    out.push_back({b, n});
    out.push_back({c, n});
}

}  // namespace

void buildUnitSphere(int slices, int stacks, std::vector<ShadedVertex>& vertices,
                     std::vector<uint32_t>& indices) {
    vertices.clear();
    indices.clear();
    for (int j = 0; j <= stacks; ++j) {
        const double polar = kPi * j / stacks;
        for (int i = 0; i <= slices; ++i) {
            const double azimuth = 2.0 * kPi * i / slices;
            const glm::vec3 p(float(std::sin(polar) * std::cos(azimuth)), float(std::cos(polar)),
                              float(std::sin(polar) * std::sin(azimuth)));
            vertices.push_back({p, p});
        }
    }
    const uint32_t row = uint32_t(slices + 1);
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            const uint32_t a = uint32_t(j) * row + uint32_t(i);
            const uint32_t b = a + row;
            // Counter-clockwise seen from outside.
            indices.insert(indices.end(), {a, a + 1, b, a + 1, b + 1, b});
        }
    }
}

void appendUnitCube(std::vector<ShadedVertex>& out) {
    for (int axis = 0; axis < 3; ++axis) {
        for (int sign = -1; sign <= 1; sign += 2) {
            glm::vec3 n(0.0f);
            n[axis] = float(sign);
            // Two axes spanning the face, ordered so the face winds counter-clockwise
            // seen from outside.
            glm::vec3 u(0.0f), v(0.0f);
            u[(axis + 1) % 3] = 0.5f;
            v[(axis + 2) % 3] = 0.5f;
            if (sign < 0) std::swap(u, v);
            const glm::vec3 c = n * 0.5f;
            triangle(out, c - u - v, c + u - v, c + u + v, n);
            triangle(out, c - u - v, c + u + v, c - u + v, n);
        }
    }
}

void appendUnitDisc(int segments, std::vector<ShadedVertex>& out) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    for (int i = 0; i < segments; ++i) {
        const double a0 = 2.0 * kPi * i / segments;
        const double a1 = 2.0 * kPi * (i + 1) / segments;
        triangle(out, glm::vec3(0.0f),
                 glm::vec3(float(std::cos(a0)), float(std::sin(a0)), 0.0f),
                 glm::vec3(float(std::cos(a1)), float(std::sin(a1)), 0.0f), n);
    }
}

void appendUnitSquare(std::vector<ShadedVertex>& out) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    triangle(out, {-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 0.0f}, n);
    triangle(out, {-0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 0.0f}, {-0.5f, 0.5f, 0.0f}, n);
}

void appendMesh(const TriangleMesh& mesh, std::vector<ShadedVertex>& out) {
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const glm::vec3 a(mesh.vertices[mesh.indices[i]]);
        const glm::vec3 b(mesh.vertices[mesh.indices[i + 1]]);
        const glm::vec3 c(mesh.vertices[mesh.indices[i + 2]]);
        glm::vec3 n = glm::cross(b - a, c - a);
        const float length = glm::length(n);
        n = length > 0.0f ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
        triangle(out, a, b, c, n);
    }
}

bool appendPolygon(const SceneObject& object, std::vector<ShadedVertex>& out) {
    std::vector<uint32_t> indices;
    const bool complete = triangulatePolygon(object.points, indices);
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    for (size_t i = 0; i + 2 < indices.size(); i += 3) {
        auto at = [&](size_t k) {
            const glm::dvec3 p = object.points[indices[i + k]] - object.anchor;
            return glm::vec3(float(p.x), float(p.y), 0.0f);
        };
        triangle(out, at(0), at(1), at(2), n);
    }
    return complete;
}

}  // namespace gridcull
