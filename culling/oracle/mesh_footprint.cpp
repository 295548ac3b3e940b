#include "culling/oracle/mesh_footprint.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcull {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The pixels whose square [p, p + 1] meets [from, to], within `range`; the
// margin keeps a pixel that rounding would put just outside.
ScreenRange touched(double from, double to, const ScreenRange& range) {
    if (std::isnan(from) || std::isnan(to)) return range;
    const double margin = 1e-9 * (std::abs(from) + std::abs(to) + 1.0);
    const double lo = std::clamp(std::floor(from - margin), double(range.lo), double(range.hi) + 1.0);
    const double hi = std::clamp(std::floor(to + margin), double(range.lo) - 1.0, double(range.hi));
    return {int(lo), int(hi)};
}

}  // namespace

bool MeshFootprint::build(const PixelView& view, const TriangleMesh& mesh,
                          const glm::dvec3& offset, const ScreenRange& cols,
                          const ScreenRange& rows) {
    if (cols.empty() || rows.empty() || mesh.indices.size() < 3) return false;
    if (mesh.closed) {
        double z_lo = kInfinity, z_hi = -kInfinity;
        for (int c = 0; c < 8; ++c) {
            const double z = view.toView(mesh.bounds.corner(c) + offset).z;
            z_lo = std::min(z_lo, z);
            z_hi = std::max(z_hi, z);
        }
        // With a margin: the rasterizer decides the cut on its own rounding.
        const double margin = 1e-9 * (std::abs(z_lo) + std::abs(z_hi) + view.near);
        if (z_lo <= view.near + margin && z_hi >= view.near - margin) return false;
    }
    cols_ = cols;
    rows_ = rows;
    const size_t width = size_t(cols.hi - cols.lo + 1), height = size_t(rows.hi - rows.lo + 1);
    least_.assign(width * height, kInfinity);
    const double budget = double(kMaxWork) * double(width) * double(height);
    double work = 0.0;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::dvec3 corner[3];
        for (int k = 0; k < 3; ++k) corner[k] = view.toView(mesh.vertices[mesh.indices[t + size_t(k)]] + offset);
        // The triangle cut to depth >= near: its corners there and where its
        // edges cross the near plane.
        double x_lo = kInfinity, x_hi = -kInfinity, y_lo = kInfinity, y_hi = -kInfinity;
        double least = kInfinity;
        auto extend = [&](const glm::dvec3& p) {
            const double x = view.columnOf(p), y = view.rowOf(p);
            x_lo = std::min(x_lo, x);
            x_hi = std::max(x_hi, x);
            y_lo = std::min(y_lo, y);
            y_hi = std::max(y_hi, y);
            least = std::min(least, p.z);
        };
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3& a = corner[k];
            const glm::dvec3& b = corner[(k + 1) % 3];
            if (a.z >= view.near) extend(a);
            if ((a.z >= view.near) != (b.z >= view.near)) {
                glm::dvec3 cut = a + (b - a) * ((view.near - a.z) / (b.z - a.z));
                cut.z = view.near;
                extend(cut);
            }
        }
        if (least == kInfinity) continue;  // wholly nearer than near
        const ScreenRange tx = touched(x_lo, x_hi, cols), ty = touched(y_lo, y_hi, rows);
        if (tx.empty() || ty.empty()) continue;
        work += double(tx.hi - tx.lo + 1) * double(ty.hi - ty.lo + 1);
        if (work > budget) return false;
        // Rounding of the view transform: keep the bound below the true depth.
        const double bound = least - 1e-9 * std::abs(least);
        for (int py = ty.lo; py <= ty.hi; ++py) {
            double* row = least_.data() + size_t(py - rows.lo) * width;
            for (int px = tx.lo; px <= tx.hi; ++px) {
                double& cell = row[px - cols.lo];
                cell = std::min(cell, bound);
            }
        }
    }
    return true;
}

}  // namespace gridcull
