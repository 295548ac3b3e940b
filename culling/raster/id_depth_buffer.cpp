// Spheres, boxes and the buffer itself; meshes are in id_depth_buffer_mesh.cpp.
#include "culling/raster/id_depth_buffer.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "culling/raster/level_box_run.h"
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
    column_inv_.assign(3 * size_t(width), 0.0);
    column_zero_.assign(size_t(width), 0);
    box_col_lo_.assign(size_t(width), 0.0);
    box_col_hi_.assign(size_t(width), 0.0);
    tiles_x_ = (width + kTile - 1) / kTile;
    tiles_y_ = (height + kTile - 1) / kTile;
    tile_far_.assign(size_t(tiles_x_) * size_t(tiles_y_), 0.0);
    clear_all_ = true;
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
    // The box slab test's reciprocals (forBoxHits). A ray direction component
    // forward[a] + v up[a] + u right[a] depends on the row alone when right[a]
    // is 0 and on the column alone when up[a] is 0 (both hold for x and z, and
    // right.y is 0, whenever the camera looks level): computed here once per frame
    // in the very arithmetic the per-pixel path uses.
    std::fill(column_zero_.begin(), column_zero_.end(), uint8_t(0));
    any_column_zero_ = false;
    for (int a = 0; a < 3; ++a) {
        axis_mode_[a] = right_[a] == 0.0 ? AxisMode::Row
                        : up_[a] == 0.0  ? AxisMode::Column
                                         : AxisMode::Pixel;
        if (axis_mode_[a] != AxisMode::Column) continue;
        double* inv = column_inv_.data() + size_t(a) * size_t(width_);
        for (int px = 0; px < width_; ++px) {
            // (forward[a] + v * 0) + u * right[a], as the per-pixel path has it.
            const double d = (forward_[a] + 0.0 * up_[a]) + column_u_[size_t(px)] * right_[a];
            if (d == 0.0) column_zero_[size_t(px)] = 1, any_column_zero_ = true;
            inv[px] = 1.0 / d;
        }
    }
    // Only the pixels written since the last clear hold anything: every write
    // is followed by refreshTiles(), which adds its rectangle to frame_cols_ x
    // frame_rows_. The whole buffer after resize() or when ids are turned on.
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (clear_all_ || (write_ids_ && !ids_cleared_)) {
        std::fill(depth_.begin(), depth_.end(), kInf);
        if (write_ids_) std::fill(index_.begin(), index_.end(), -1);
    } else if (!frame_cols_.empty() && !frame_rows_.empty()) {
        for (int py = frame_rows_.lo; py <= frame_rows_.hi; ++py) {
            const size_t row = size_t(py) * size_t(width_);
            std::fill(depth_.begin() + long(row + size_t(frame_cols_.lo)),
                      depth_.begin() + long(row + size_t(frame_cols_.hi) + 1), kInf);
            if (write_ids_)
                std::fill(index_.begin() + long(row + size_t(frame_cols_.lo)),
                          index_.begin() + long(row + size_t(frame_cols_.hi) + 1), -1);
        }
    }
    clear_all_ = false;
    ids_cleared_ = write_ids_;
    frame_cols_ = frame_rows_ = ScreenRange{INT_MAX, -1};
    std::fill(tile_far_.begin(), tile_far_.end(), std::numeric_limits<double>::infinity());
    dirty_cols_ = dirty_rows_ = last_cols_ = last_rows_ = ScreenRange{INT_MAX, -1};
}

namespace {

// The largest of `farthest` and row[lo..end). Depths are never NaN, so the
// order of the comparisons does not matter: SSE2 (every x86-64 CPU) takes four
// at a time in two independent chains, where one chain of scalar max would wait
// on each previous one.
double spanMax(const double* row, int lo, int end, double farthest) {
    int px = lo;
#if defined(__SSE2__)
    __m128d a = _mm_set1_pd(farthest), b = a;
    for (; px + 4 <= end; px += 4) {
        a = _mm_max_pd(a, _mm_loadu_pd(row + px));
        b = _mm_max_pd(b, _mm_loadu_pd(row + px + 2));
    }
    a = _mm_max_pd(a, b);
    farthest = std::max(_mm_cvtsd_f64(a), _mm_cvtsd_f64(_mm_unpackhi_pd(a, a)));
#endif
    for (; px < end; ++px) farthest = std::max(farthest, row[px]);
    return farthest;
}

}  // namespace

void IdDepthBuffer::refreshTiles() {
    last_cols_ = dirty_cols_;
    last_rows_ = dirty_rows_;
    if (dirty_cols_.empty() || dirty_rows_.empty()) return;
    frame_cols_ = {std::min(frame_cols_.lo, dirty_cols_.lo), std::max(frame_cols_.hi, dirty_cols_.hi)};
    frame_rows_ = {std::min(frame_rows_.lo, dirty_rows_.lo), std::max(frame_rows_.hi, dirty_rows_.hi)};
    for (int ty = dirty_rows_.lo / kTile; ty <= dirty_rows_.hi / kTile; ++ty) {
        const int row_end = std::min(height_, (ty + 1) * kTile);
        for (int tx = dirty_cols_.lo / kTile; tx <= dirty_cols_.hi / kTile; ++tx) {
            const int col_end = std::min(width_, (tx + 1) * kTile);
            // Draws only lower depths, so the new farthest is <= the old one: a
            // row that still reaches the old value ends the scan (an empty pixel
            // of a tile at +infinity at once).
            double& tile = tile_far_[size_t(ty) * size_t(tiles_x_) + size_t(tx)];
            const double old_far = tile;
            double farthest = 0.0;
            for (int py = ty * kTile; py < row_end && farthest < old_far; ++py)
                farthest = spanMax(depth_.data() + size_t(py) * size_t(width_), tx * kTile, col_end,
                                   farthest);
            tile = farthest;
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
            if (write_ids_) index_[p] = index;
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
        int32_t* index_row = write_ids_ ? index_.data() + size_t(py) * size_t(width_) : nullptr;
        const double* column_u = column_u_.data();
        // The row's written columns in locals, merged into the dirty rectangle once.
        int written_lo = INT_MAX, written_hi = -1;
        forTileSegments(py, col_lo, col_hi, z_min, [&](int px) {
            if (depth_row[px] <= z_min) return;
            // solveSphereQuadratic + solidEntry, term for term, except that the
            // far root is only computed when the near one is not already the
            // answer: s1 >= s0 always (root >= 0, a > 0, rounding is monotone),
            // so s0 >= near > 0 makes solidEntry return s0.
            const double u = column_u[px];
            const double a = u * u + row_a, b = u * c.x + row_b;
            if (!(a > 0.0)) return;
            const double disc = b * b - a * k;
            if (disc < 0.0) return;
            const double root = std::sqrt(disc);
            const double s0 = (b - root) / a;
            double s;
            if (s0 >= near_ && s0 > 0.0) {
                if (!(s0 <= far_)) return;
                s = s0;
            } else if (!solidEntry(s0, (b + root) / a, near_, far_, s)) {
                return;
            }
            if (s < depth_row[px]) {
                depth_row[px] = s;
                if (index_row) index_row[px] = index;
                written_lo = std::min(written_lo, px);
                written_hi = px;
            }
        });
        if (written_hi >= 0) {
            markDirty(written_lo, py);
            markDirty(written_hi, py);
        }
    }
    refreshTiles();
    return true;
}

bool IdDepthBuffer::screenBounds(const Aabb& box, ScreenRange& cols, ScreenRange& rows,
                                 double& z_min) const {
    if (box.contains(eye_)) {
        cols = {0, width_ - 1};
        rows = {0, height_ - 1};
        z_min = near_;
        return true;
    }
    return boxCandidates(box, cols, rows, z_min);
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

template <typename Visit, typename LevelRun>
void IdDepthBuffer::forBoxHits(const Aabb& box, double z_min, const ScreenRange& cols,
                               const ScreenRange& rows, Visit&& visit, LevelRun&& level_run) const {
    // The slab test of lineBox, term for term, with its reciprocals 1 / dir[a]
    // taken from the frame's tables where dir[a] depends on the row alone or on
    // the column alone (see begin()); only the remaining axes divide per pixel.
    // The arithmetic is that of lineBox + solidEntry, so every pixel gets the
    // same answer and the same depth, bit for bit. A zero direction component
    // (rare: one row or column at most) takes lineBox itself.
    const double b_lo[3] = {box.min.x - eye_.x, box.min.y - eye_.y, box.min.z - eye_.z};
    const double b_hi[3] = {box.max.x - eye_.x, box.max.y - eye_.y, box.max.z - eye_.z};
    // The common case, a level camera: every axis by column or by row (two and
    // one, or one and two when it looks along a world axis), no zero component
    // anywhere in the frame's tables.
    int column_axes[3], column_count = 0, row_axes[3], row_count = 0;
    bool pixel_axis = false;
    for (int a = 0; a < 3; ++a) {
        if (axis_mode_[a] == AxisMode::Column) column_axes[column_count++] = a;
        if (axis_mode_[a] == AxisMode::Row) row_axes[row_count++] = a;
        if (axis_mode_[a] == AxisMode::Pixel) pixel_axis = true;
    }
    const bool level = column_count >= 1 && !pixel_axis && !any_column_zero_;
    ScreenRange hit_cols{INT_MAX, -1};  // level: the columns that may hit
    if (level) {
        // The column axes' slabs depend on the column alone: one interval per
        // column, shared by every row of this box.
        for (int px = cols.lo; px <= cols.hi; ++px) {
            double lo = -std::numeric_limits<double>::infinity();
            double hi = std::numeric_limits<double>::infinity();
            for (int k = 0; k < column_count; ++k) {
                const int a = column_axes[k];
                const double inv = column_inv_[size_t(a) * size_t(width_) + size_t(px)];
                const double t0 = b_lo[a] * inv, t1 = b_hi[a] * inv;
                lo = std::max(lo, std::min(t0, t1));
                hi = std::min(hi, std::max(t0, t1));
            }
            box_col_lo_[size_t(px)] = lo;
            box_col_hi_[size_t(px)] = hi;
            // A pixel of a column whose interval is empty or wholly behind the
            // eye misses (lineBox false, or solidEntry false with s1 < 0 < near).
            if (lo <= hi && hi >= 0.0) {
                hit_cols.lo = std::min(hit_cols.lo, px);
                hit_cols.hi = px;
            }
        }
        if (hit_cols.empty()) return;
    }
    for (int py = rows.lo; py <= rows.hi; ++py) {
        const glm::dvec3 row_dir = forward_ + row_v_[size_t(py)] * up_;
        const double* depth_row = depth_.data() + size_t(py) * size_t(width_);
        // Per axis: a row constant, a column table, or neither (divide per pixel).
        double row_inv[3] = {0.0, 0.0, 0.0};
        bool row_zero = false;
        for (int a = 0; a < 3; ++a) {
            if (axis_mode_[a] != AxisMode::Row) continue;
            const double d = row_dir[a];
            row_zero = row_zero || d == 0.0;
            row_inv[a] = 1.0 / d;
        }
        if (level && !row_zero) {
            // The row axes' slabs are one interval for the whole row, the column
            // axes' one per column (above): the pixel's interval is their
            // intersection. Same products, same min / max as lineBox (in another
            // order, which max and min do not see).
            double row_lo = -std::numeric_limits<double>::infinity();
            double row_hi = std::numeric_limits<double>::infinity();
            for (int k = 0; k < row_count; ++k) {
                const int a = row_axes[k];
                const double r0 = b_lo[a] * row_inv[a], r1 = b_hi[a] * row_inv[a];
                row_lo = std::max(row_lo, std::min(r0, r1));
                row_hi = std::min(row_hi, std::max(r0, r1));
            }
            if (row_lo > row_hi) continue;
            bool stop = false;
            forTileSpans(py, hit_cols.lo, hit_cols.hi, z_min, [&](int lo, int hi) {
                return stop = level_run(py, lo, hi, row_lo, row_hi);
            });
            if (stop) return;
            continue;
        }
        bool stop = false;
        forTileSegments(py, cols.lo, cols.hi, z_min, [&](int px) {
            if (stop || depth_row[px] <= z_min) return;
            double lo = -std::numeric_limits<double>::infinity();
            double hi = std::numeric_limits<double>::infinity();
            if (row_zero || column_zero_[size_t(px)]) {
                const glm::dvec3 dir = row_dir + column_u_[size_t(px)] * right_;
                if (!lineBox(eye_, dir, box, lo, hi)) return;
            } else {
                const double u = column_u_[size_t(px)];
                for (int a = 0; a < 3; ++a) {
                    double inv;
                    if (axis_mode_[a] == AxisMode::Row) {
                        inv = row_inv[a];
                    } else if (axis_mode_[a] == AxisMode::Column) {
                        inv = column_inv_[size_t(a) * size_t(width_) + size_t(px)];
                    } else {
                        const double d = row_dir[a] + u * right_[a];
                        if (d == 0.0) {
                            const glm::dvec3 dir = row_dir + u * right_;
                            if (!lineBox(eye_, dir, box, lo, hi)) return;
                            break;
                        }
                        inv = 1.0 / d;
                    }
                    const double t0 = b_lo[a] * inv, t1 = b_hi[a] * inv;
                    lo = std::max(lo, std::min(t0, t1));
                    hi = std::min(hi, std::max(t0, t1));
                }
                if (lo > hi) return;
            }
            double s;
            if (!solidEntry(lo, hi, near_, far_, s)) return;
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
    // The written rectangle in locals (registers), merged into the dirty one once.
    int col_lo = INT_MAX, col_hi = -1, row_lo = INT_MAX, row_hi = -1;
    double* depth = depth_.data();
    int32_t* ids = write_ids_ ? index_.data() : nullptr;
    const size_t width = size_t(width_);
    auto pixel = [&](int px, int py, double s) {
        const size_t p = size_t(py) * width + size_t(px);
        depth[p] = s;
        if (ids) ids[p] = index;
        col_lo = std::min(col_lo, px);
        col_hi = std::max(col_hi, px);
        row_lo = std::min(row_lo, py);
        row_hi = py;
        return false;
    };
    auto level_run = [&](int py, int lo, int hi, double row_lo_s, double row_hi_s) {
        const LevelBoxRow run{row_lo_s, row_hi_s, box_col_lo_.data(), box_col_hi_.data(),
                              near_,    far_,     z_min};
        const WrittenSpan written = writeLevelBoxRun(run, lo, hi, depth + size_t(py) * width,
                                                     ids ? ids + size_t(py) * width : nullptr, index);
        if (written.hi < 0) return false;
        col_lo = std::min(col_lo, written.lo);
        col_hi = std::max(col_hi, written.hi);
        row_lo = std::min(row_lo, py);
        row_hi = py;
        return false;
    };
    forBoxHits(box, z_min, cols, rows, pixel, level_run);
    if (col_hi >= 0) {
        markDirty(col_lo, row_lo);
        markDirty(col_hi, row_hi);
    }
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
    auto level_run = [&](int py, int lo, int hi, double row_lo, double row_hi) {
        const LevelBoxRow run{row_lo, row_hi, box_col_lo_.data(), box_col_hi_.data(),
                              near_,  far_,   z_min};
        const double* depth_row = depthRow(py);
        double s;
        for (int px = lo; px <= hi; ++px)
            if (levelBoxWins(run, px, depth_row[px], s)) return passed = true;
        return false;
    };
    forBoxHits(box, z_min, cols, rows, [&](int, int, double) { return passed = true; }, level_run);
    return passed;
}

void IdDepthBuffer::markVisible(std::vector<char>& seen) const {
    assert(write_ids_ && "markVisible needs the ids: setWriteIds(true)");
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
