// Spheres, boxes and the buffer itself; meshes are in id_depth_buffer_mesh.cpp.
#include "culling/raster/id_depth_buffer.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "culling/raster/pixel_range.h"
#include "culling/scene/ray_intersect.h"

namespace gridcull {

void imageSizeForAspect(int long_side, double aspect, int& width, int& height) {
    const int resolution = std::clamp(long_side, 1, kMaxImageResolution);
    if (!(aspect > 0.0) || !std::isfinite(aspect)) aspect = 1.0;
    const double other = aspect >= 1.0 ? resolution / aspect : resolution * aspect;
    const int short_side = int(std::clamp(std::round(other), 1.0, double(resolution)));
    width = aspect >= 1.0 ? resolution : short_side;
    height = aspect >= 1.0 ? short_side : resolution;
}

void IdDepthBuffer::resize(int width, int height) {
    assert(width >= 1 && height >= 1);
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    const size_t pixels = size_t(width) * size_t(height);
    depth_.assign(pixels, 0.0);
    index_.assign(pixels, -1);
    parity_.assign(pixels, 0);
    column_u_.assign(size_t(width), 0.0);
    row_v_.assign(size_t(height), 0.0);
    tiles_x_ = (width + kTile - 1) / kTile;
    tiles_y_ = (height + kTile - 1) / kTile;
    tile_far_.assign(size_t(tiles_x_) * size_t(tiles_y_), 0.0);
}

void IdDepthBuffer::begin(const Camera& camera) {
    assert(width_ > 0 && height_ > 0 && "resize() before begin()");
    camera.basis(right_, up_, forward_);
    eye_ = camera.position;
    tan_y_ = std::tan(glm::radians(camera.fov_deg) * 0.5);
    tan_x_ = tan_y_ * camera.aspect;
    near_ = camera.near;
    far_ = camera.far;
    for (int px = 0; px < width_; ++px)
        column_u_[size_t(px)] = (2.0 * (px + 0.5) / width_ - 1.0) * tan_x_;
    for (int py = 0; py < height_; ++py)
        row_v_[size_t(py)] = (1.0 - 2.0 * (py + 0.5) / height_) * tan_y_;
    std::fill(depth_.begin(), depth_.end(), std::numeric_limits<double>::infinity());
    std::fill(index_.begin(), index_.end(), -1);
    std::fill(tile_far_.begin(), tile_far_.end(), std::numeric_limits<double>::infinity());
    dirty_cols_ = dirty_rows_ = last_cols_ = last_rows_ = ScreenRange{INT_MAX, -1};
}

void IdDepthBuffer::refreshTiles() {
    last_cols_ = dirty_cols_;
    last_rows_ = dirty_rows_;
    if (dirty_cols_.empty() || dirty_rows_.empty()) return;
    for (int ty = dirty_rows_.lo / kTile; ty <= dirty_rows_.hi / kTile; ++ty) {
        const int row_end = std::min(height_, (ty + 1) * kTile);
        for (int tx = dirty_cols_.lo / kTile; tx <= dirty_cols_.hi / kTile; ++tx) {
            const int col_end = std::min(width_, (tx + 1) * kTile);
            double farthest = 0.0;
            for (int py = ty * kTile; py < row_end; ++py) {
                const double* row = depth_.data() + size_t(py) * size_t(width_);
                for (int px = tx * kTile; px < col_end; ++px)
                    farthest = std::max(farthest, row[px]);
            }
            tile_far_[size_t(ty) * size_t(tiles_x_) + size_t(tx)] = farthest;
        }
    }
    dirty_cols_ = dirty_rows_ = ScreenRange{INT_MAX, -1};
}

bool IdDepthBuffer::mayBeNearer(const ScreenRange& cols, const ScreenRange& rows, double z) const {
    for (int ty = rows.lo / kTile; ty <= rows.hi / kTile; ++ty)
        for (int tx = cols.lo / kTile; tx <= cols.hi / kTile; ++tx)
            if (tile_far_[size_t(ty) * size_t(tiles_x_) + size_t(tx)] > z) return true;
    return false;
}

glm::dvec3 IdDepthBuffer::toView(const glm::dvec3& world) const {
    const glm::dvec3 rel = world - eye_;
    return {glm::dot(rel, right_), glm::dot(rel, up_), glm::dot(rel, forward_)};
}

double IdDepthBuffer::columnOf(double u) const {
    return (u / tan_x_ + 1.0) * 0.5 * width_ - 0.5;
}

double IdDepthBuffer::rowOf(double v) const {
    return (1.0 - v / tan_y_) * 0.5 * height_ - 0.5;
}

double IdDepthBuffer::minDepthOfSphere(const glm::dvec3& center, double radius) const {
    return glm::dot(center - eye_, forward_) - radius;
}

double IdDepthBuffer::minDepthOfBox(const Aabb& box) const {
    // Depth is linear, so its minimum over the box is at the corner that lies
    // furthest against the forward axis.
    const glm::dvec3 corner{forward_.x >= 0.0 ? box.min.x : box.max.x,
                            forward_.y >= 0.0 ? box.min.y : box.max.y,
                            forward_.z >= 0.0 ? box.min.z : box.max.z};
    return glm::dot(corner - eye_, forward_);
}

void IdDepthBuffer::fillNear(int index) {
    for (size_t p = 0; p < depth_.size(); ++p) {
        if (near_ < depth_[p]) {
            depth_[p] = near_;
            index_[p] = index;
        }
    }
    markAllDirty();
    refreshTiles();
}

bool IdDepthBuffer::drawSphere(int index, const glm::dvec3& center, double radius) {
    const glm::dvec3 c = toView(center);
    const double r = radius;
    const double k = glm::dot(c, c) - r * r;
    if (k <= 0.0) {
        fillNear(index);
        return true;
    }
    if (c.z - r > far_ || c.z + r < near_) return false;
    const double z_min = std::max(c.z - r, near_);

    // The candidate rectangle. A sphere wholly in front of the eye plane has a
    // bounded silhouette, bounded exactly by the tangent planes through the eye.
    // One that crosses the eye plane can only show its part at depth >= near,
    // which lies in the view-space box [c - r, c + r] cut at z >= near, whose
    // corners are all in front of the eye.
    ScreenRange rows, cols;
    if (c.z > r * (1.0 + 1e-9)) {
        const double den = c.z * c.z - r * r;
        const double spread_y = r * std::sqrt(c.y * c.y + den);
        const double spread_x = r * std::sqrt(c.x * c.x + den);
        rows = pixelRange(rowOf((c.y * c.z + spread_y) / den), rowOf((c.y * c.z - spread_y) / den),
                          height_);
        cols = pixelRange(columnOf((c.x * c.z - spread_x) / den),
                          columnOf((c.x * c.z + spread_x) / den), width_);
    } else {
        const double z_lo = std::max(near_, c.z - r), z_hi = c.z + r;
        const double u_lo = std::min((c.x - r) / z_lo, (c.x - r) / z_hi);
        const double u_hi = std::max((c.x + r) / z_lo, (c.x + r) / z_hi);
        const double v_lo = std::min((c.y - r) / z_lo, (c.y - r) / z_hi);
        const double v_hi = std::max((c.y + r) / z_lo, (c.y + r) / z_hi);
        rows = pixelRange(rowOf(v_hi), rowOf(v_lo), height_);
        cols = pixelRange(columnOf(u_lo), columnOf(u_hi), width_);
    }
    if (rows.empty() || cols.empty()) return false;
    if (!mayBeNearer(cols, rows, z_min)) return hiddenWhole();

    // Per row v the ray (u, v, 1) meets the sphere's line set where
    // qa u^2 + 2 qb u + qc >= 0. With qa < 0 (always so in front of the eye
    // plane) that is one interval of u, which narrows the row's columns.
    const double qa = r * r - c.y * c.y - c.z * c.z;
    for (int py = rows.lo; py <= rows.hi; ++py) {
        const double v = row_v_[size_t(py)];
        const double row_a = v * v + 1.0;
        const double row_b = v * c.y + c.z;
        int col_lo = cols.lo, col_hi = cols.hi;
        if (qa < 0.0) {
            const double qb = c.x * row_b;
            const double qc = row_b * row_b - row_a * k;
            const double disc = qb * qb - qa * qc;
            if (disc < 0.0) continue;
            const double root = std::sqrt(disc);
            const ScreenRange span =
                pixelRange(columnOf((-qb + root) / qa), columnOf((-qb - root) / qa), width_);
            col_lo = std::max(col_lo, span.lo);
            col_hi = std::min(col_hi, span.hi);
        }
        double* depth_row = depth_.data() + size_t(py) * size_t(width_);
        int32_t* index_row = index_.data() + size_t(py) * size_t(width_);
        forTileSegments(py, col_lo, col_hi, z_min, [&](int px) {
            if (depth_row[px] <= z_min) return;
            const double u = column_u_[size_t(px)];
            double s0, s1, s;
            if (!solveSphereQuadratic(u * u + row_a, u * c.x + row_b, k, s0, s1)) return;
            if (!solidEntry(s0, s1, near_, far_, s)) return;
            if (s < depth_row[px]) {
                depth_row[px] = s;
                index_row[px] = index;
                markDirty(px, py);
            }
        });
    }
    refreshTiles();
    return true;
}

bool IdDepthBuffer::boxCandidates(const Aabb& box, ScreenRange& cols, ScreenRange& rows,
                                  double& z_min) const {
    z_min = std::numeric_limits<double>::infinity();
    double z_max = -z_min;
    double u_lo = z_min, u_hi = z_max, v_lo = z_min, v_hi = z_max;
    glm::dvec3 corners[8];
    for (int i = 0; i < 8; ++i) {
        corners[i] = toView(box.corner(i));
        z_min = std::min(z_min, corners[i].z);
        z_max = std::max(z_max, corners[i].z);
    }
    if (z_min > far_ || z_max < near_) return false;
    // Only the part of the box at depth >= near can show. That part is convex and
    // in front of the eye, so its projection is bounded by the projections of its
    // vertices: the corners at depth >= near and the points where the box's edges
    // cross the near plane.
    auto extend = [&](const glm::dvec3& p) {
        u_lo = std::min(u_lo, p.x / p.z);
        u_hi = std::max(u_hi, p.x / p.z);
        v_lo = std::min(v_lo, p.y / p.z);
        v_hi = std::max(v_hi, p.y / p.z);
    };
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3& a = corners[i];
        if (a.z >= near_) extend(a);
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (i & bit) continue;
            const glm::dvec3& b = corners[i | bit];
            if ((a.z >= near_) == (b.z >= near_)) continue;
            glm::dvec3 cut = a + (b - a) * ((near_ - a.z) / (b.z - a.z));
            cut.z = near_;
            extend(cut);
        }
    }
    cols = pixelRange(columnOf(u_lo), columnOf(u_hi), width_);
    rows = pixelRange(rowOf(v_hi), rowOf(v_lo), height_);
    z_min = std::max(z_min, near_);
    return !cols.empty() && !rows.empty();
}

template <typename Visit>
void IdDepthBuffer::forBoxHits(const Aabb& box, double z_min, const ScreenRange& cols,
                               const ScreenRange& rows, Visit&& visit) const {
    for (int py = rows.lo; py <= rows.hi; ++py) {
        const glm::dvec3 row_dir = forward_ + row_v_[size_t(py)] * up_;
        const double* depth_row = depth_.data() + size_t(py) * size_t(width_);
        bool stop = false;
        forTileSegments(py, cols.lo, cols.hi, z_min, [&](int px) {
            if (stop || depth_row[px] <= z_min) return;
            const glm::dvec3 dir = row_dir + column_u_[size_t(px)] * right_;
            double s0, s1, s;
            if (!lineBox(eye_, dir, box, s0, s1)) return;
            if (!solidEntry(s0, s1, near_, far_, s)) return;
            if (s < depth_row[px]) stop = visit(px, py, s);
        });
        if (stop) return;
    }
}

bool IdDepthBuffer::drawBox(int index, const Aabb& box) {
    if (box.contains(eye_)) {
        fillNear(index);
        return true;
    }
    ScreenRange cols, rows;
    double z_min = 0.0;
    if (!boxCandidates(box, cols, rows, z_min)) return false;
    if (!mayBeNearer(cols, rows, z_min)) return hiddenWhole();
    forBoxHits(box, z_min, cols, rows, [&](int px, int py, double s) {
        const size_t p = size_t(py) * size_t(width_) + size_t(px);
        depth_[p] = s;
        index_[p] = index;
        markDirty(px, py);
        return false;
    });
    refreshTiles();
    return true;
}

bool IdDepthBuffer::boxPassesDepthTest(const Aabb& box) const {
    if (box.contains(eye_)) return true;
    ScreenRange cols, rows;
    double z_min = 0.0;
    if (!boxCandidates(box, cols, rows, z_min)) return false;
    if (!mayBeNearer(cols, rows, z_min)) return false;
    bool passed = false;
    forBoxHits(box, z_min, cols, rows, [&](int, int, double) { return passed = true; });
    return passed;
}

void IdDepthBuffer::markVisible(std::vector<char>& seen) const {
    for (const int32_t index : index_) {
        if (index < 0) continue;
        assert(size_t(index) < seen.size());
        seen[size_t(index)] = 1;
    }
}

bool IdDepthBuffer::drawObject(int index, const SceneObject& object, const glm::dvec3& shift) {
    switch (object.shape) {
        case ShapeKind::Sphere:
            return drawSphere(index, object.center + shift, object.radius);
        case ShapeKind::Box:
            return drawBox(index, object.box.translated(shift));
        case ShapeKind::Mesh:
            return object.mesh && drawMesh(index, *object.mesh, object.center + shift);
        case ShapeKind::Polygon:
            break;  // 2D only
    }
    return false;
}

}  // namespace gridcull
