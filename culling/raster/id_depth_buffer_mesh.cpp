// Triangle meshes in the shared ID-and-depth buffer (id_depth_buffer.h):
// near-plane clipping, an edge-ownership fill rule, perspective-correct depth,
// and the parity fill that keeps a closed mesh solid where the near plane cuts it.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "culling/raster/id_depth_buffer.h"
#include "culling/raster/pixel_range.h"

namespace gridcull {

namespace {

// Twice the signed area of (p, q, r) in pixel coordinates; > 0 for the winding
// rasterTriangle normalizes to.
double edgeFunction(double px, double py, double qx, double qy, double rx, double ry) {
    return (qx - px) * (ry - py) - (qy - py) * (rx - px);
}

// Edge ownership: a pixel centre exactly on an edge belongs to the triangle only
// when the edge runs this way. An edge and its reverse never both qualify, so of
// two triangles sharing an edge exactly one owns the centre, which keeps both the
// ID buffer and the crossing parity free of double counts. With rows counted
// from the top, this gives a triangle the centres on its right and bottom edges
// as the image is shown: the top-left rule mirrored, and just as consistent
// (tests/culling/raster/id_depth_buffer_mesh_test.cpp checks both).
bool ownsEdge(double dx, double dy) {
    return dy > 0.0 || (dy == 0.0 && dx < 0.0);
}

}  // namespace

bool IdDepthBuffer::drawMesh(int index, const TriangleMesh& mesh, const glm::dvec3& offset) {
    if (mesh.vertices.empty() || mesh.indices.size() < 3) return false;
    const Aabb bounds = mesh.bounds.translated(offset);
    const double z_min = minDepthOfBox(bounds);
    const double z_max = 2.0 * glm::dot(bounds.center() - eye_, forward_) - z_min;
    if (z_min > far_ || z_max < near_) return false;

    // Grows only when a larger mesh comes along; the oracle reserves the largest.
    view_vertices_.resize(mesh.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
        view_vertices_[i] = toView(mesh.vertices[i] + offset);

    const size_t triangles = mesh.indices.size() / 3;
    auto triangle = [&](size_t t, glm::dvec3 tri[3]) {
        for (int corner = 0; corner < 3; ++corner)
            tri[corner] = view_vertices_[mesh.indices[3 * t + size_t(corner)]];
    };

    // A closed mesh that the near plane may cut: pixels whose near-plane point is
    // inside (an odd number of surface crossings behind it) see the solid at near.
    if (mesh.closed && z_min <= near_ && z_max >= near_) {
        std::fill(parity_.begin(), parity_.end(), uint8_t(0));
        glm::dvec3 tri[3];
        for (size_t t = 0; t < triangles; ++t) {
            triangle(t, tri);
            clipAndRaster(index, tri, true);
        }
        for (size_t p = 0; p < parity_.size(); ++p) {
            if (parity_[p] && near_ < depth_[p]) {
                depth_[p] = near_;
                if (write_ids_) index_[p] = index;
            }
        }
        markAllDirty();
        refreshTiles();
    }
    // The near-plane pass above may have written anywhere; the triangles below
    // only their bounds. The draw's rectangle is both.
    const ScreenRange near_cols = last_cols_, near_rows = last_rows_;
    const bool near_pass = mesh.closed && z_min <= near_ && z_max >= near_;
    glm::dvec3 tri[3];
    for (size_t t = 0; t < triangles; ++t) {
        triangle(t, tri);
        if (tri[0].z > far_ && tri[1].z > far_ && tri[2].z > far_) continue;
        clipAndRaster(index, tri, false);
    }
    refreshTiles();
    if (near_pass && !near_cols.empty() && !near_rows.empty()) {
        if (last_cols_.empty() || last_rows_.empty()) {
            last_cols_ = near_cols;
            last_rows_ = near_rows;
        } else {
            last_cols_ = {std::min(last_cols_.lo, near_cols.lo),
                          std::max(last_cols_.hi, near_cols.hi)};
            last_rows_ = {std::min(last_rows_.lo, near_rows.lo),
                          std::max(last_rows_.hi, near_rows.hi)};
        }
    }
    return true;
}

bool IdDepthBuffer::drawTriangles(int index, const glm::dvec3* corners, size_t triangles,
                                  const glm::dvec3& offset) {
    if (triangles == 0) return false;
    Aabb bounds{corners[0], corners[0]};
    for (size_t k = 1; k < 3 * triangles; ++k) bounds.merge({corners[k], corners[k]});
    bounds = bounds.translated(offset);
    const double z_min = minDepthOfBox(bounds);
    const double z_max = 2.0 * glm::dot(bounds.center() - eye_, forward_) - z_min;
    if (z_min > far_ || z_max < near_) return false;
    glm::dvec3 tri[3];
    for (size_t t = 0; t < triangles; ++t) {
        for (int corner = 0; corner < 3; ++corner)
            tri[corner] = toView(corners[3 * t + size_t(corner)] + offset);
        if (tri[0].z > far_ && tri[1].z > far_ && tri[2].z > far_) continue;
        clipAndRaster(index, tri, false);
    }
    refreshTiles();
    return true;
}

void IdDepthBuffer::clipAndRaster(int index, const glm::dvec3 tri[3], bool parity) {
    glm::dvec3 poly[4];
    int count = 0;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3& cur = tri[i];
        const glm::dvec3& next = tri[(i + 1) % 3];
        const bool cur_in = cur.z >= near_;
        const bool next_in = next.z >= near_;
        if (cur_in) poly[count++] = cur;
        if (cur_in != next_in) {
            // Always interpolate from the inside vertex, so the two triangles that
            // share this edge compute bit-identical cut points.
            const glm::dvec3& in = cur_in ? cur : next;
            const glm::dvec3& out = cur_in ? next : cur;
            glm::dvec3 cut = in + (out - in) * ((near_ - in.z) / (out.z - in.z));
            cut.z = near_;
            poly[count++] = cut;
        }
    }
    if (count < 3) return;
    rasterTriangle(index, poly[0], poly[1], poly[2], parity);
    if (count == 4) rasterTriangle(index, poly[0], poly[2], poly[3], parity);
}

void IdDepthBuffer::rasterTriangle(int index, const glm::dvec3& a, const glm::dvec3& b,
                                   const glm::dvec3& c, bool parity) {
    // Continuous pixel coordinates: the centre of pixel (px, py) is (px + 0.5, py + 0.5).
    auto project = [&](const glm::dvec3& p) {
        return ScreenVertex{columnOf(p.x / p.z) + 0.5, rowOf(p.y / p.z) + 0.5, 1.0 / p.z};
    };
    ScreenVertex v0 = project(a), v1 = project(b), v2 = project(c);
    double area = edgeFunction(v0.x, v0.y, v1.x, v1.y, v2.x, v2.y);
    if (!(area != 0.0) || !std::isfinite(area)) return;  // covers no pixel centre
    if (area < 0.0) {
        std::swap(v1, v2);
        area = -area;
    }
    const ScreenRange cols =
        pixelRange(std::min({v0.x, v1.x, v2.x}) - 0.5, std::max({v0.x, v1.x, v2.x}) - 0.5, width_);
    const ScreenRange rows =
        pixelRange(std::min({v0.y, v1.y, v2.y}) - 0.5, std::max({v0.y, v1.y, v2.y}) - 0.5, height_);
    if (cols.empty() || rows.empty()) return;
    const bool own0 = ownsEdge(v2.x - v1.x, v2.y - v1.y);  // edge opposite v0
    const bool own1 = ownsEdge(v0.x - v2.x, v0.y - v2.y);
    const bool own2 = ownsEdge(v1.x - v0.x, v1.y - v0.y);
    const double z_min = 1.0 / std::max({v0.inv_z, v1.inv_z, v2.inv_z});
    if (!parity && !mayBeNearer(cols, rows, z_min)) return;  // hidden whole
    const double inv_area = 1.0 / area;
    for (int py = rows.lo; py <= rows.hi; ++py) {
        const double y = py + 0.5;
        const size_t row = size_t(py) * size_t(width_);
        for (int px = cols.lo; px <= cols.hi; ++px) {
            const size_t p = row + size_t(px);
            if (!parity && depth_[p] <= z_min) continue;
            const double x = px + 0.5;
            const double w0 = edgeFunction(v1.x, v1.y, v2.x, v2.y, x, y);
            const double w1 = edgeFunction(v2.x, v2.y, v0.x, v0.y, x, y);
            const double w2 = edgeFunction(v0.x, v0.y, v1.x, v1.y, x, y);
            if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
            if ((w0 == 0.0 && !own0) || (w1 == 0.0 && !own1) || (w2 == 0.0 && !own2)) continue;
            if (parity) {
                parity_[p] ^= 1u;
                continue;
            }
            // 1 / depth is affine in screen space under a perspective projection.
            const double inv_z = (w0 * v0.inv_z + w1 * v1.inv_z + w2 * v2.inv_z) * inv_area;
            const double depth = std::max(1.0 / inv_z, near_);
            if (depth > far_ || !(depth < depth_[p])) continue;
            depth_[p] = depth;
            if (write_ids_) index_[p] = index;
            markDirty(px, py);
        }
    }
}

}  // namespace gridcull
