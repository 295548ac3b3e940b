// The local BSP tree of an object: Kovalčík & Sochor, "Fast rendering of
// complex dynamic scenes", section 3.1. object_bsp.h says where it departs from
// the paper (the plane at the median of centroids on the longest axis, the
// progress rule and the piece budget, the translation passed to queries).
#include "culling/bsp_oq/object_bsp.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include <glm/geometric.hpp>

namespace gridcull {

namespace {

// The axes by decreasing extent, ties in axis order (no allocation, unlike
// std::stable_sort).
void axesByExtent(const glm::dvec3& e, int order[3]) {
    for (int i = 1; i < 3; ++i)
        for (int j = i; j > 0 && e[order[j]] > e[order[j - 1]]; --j)
            std::swap(order[j], order[j - 1]);
}

Aabb pieceBox(const BspTrianglePiece& p) {
    Aabb box{p.v[0], p.v[0]};
    box.merge({p.v[1], p.v[1]});
    box.merge({p.v[2], p.v[2]});
    return box;
}

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Which side of x[axis] = split the piece goes to without clipping:
// -1 low (all <= split), +1 high (all >= split, not all on it), 0 straddles.
int sideOf(const BspTrianglePiece& p, int axis, double split) {
    double lo = p.v[0][axis], hi = lo;
    for (int k = 1; k < 3; ++k) {
        lo = std::min(lo, p.v[k][axis]);
        hi = std::max(hi, p.v[k][axis]);
    }
    if (hi <= split) return -1;
    if (lo >= split) return 1;
    return 0;
}

void emitFan(const glm::dvec3* poly, int n, int source, std::vector<BspTrianglePiece>& out) {
    for (int k = 1; k + 1 < n; ++k) out.push_back({{poly[0], poly[k], poly[k + 1]}, source});
}

}  // namespace

double triangleArea(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

void clipTriangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, int source,
                  int axis, double split, std::vector<BspTrianglePiece>& low,
                  std::vector<BspTrianglePiece>& high) {
    assert(axis >= 0 && axis < 3);
    const glm::dvec3 v[3] = {a, b, c};
    int side[3];
    bool any_low = false, any_high = false;
    for (int k = 0; k < 3; ++k) {
        side[k] = v[k][axis] < split ? -1 : (v[k][axis] > split ? 1 : 0);
        any_low |= side[k] < 0;
        any_high |= side[k] > 0;
    }
    if (!any_high) {
        low.push_back({{a, b, c}, source});
        return;
    }
    if (!any_low) {
        high.push_back({{a, b, c}, source});
        return;
    }
    // The crossing point of each edge k -> k+1 whose ends lie strictly apart.
    glm::dvec3 cross_point[3];
    bool crosses[3];
    for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3;
        crosses[k] = side[k] * side[j] < 0;
        if (!crosses[k]) continue;
        const glm::dvec3& p = v[k];
        const glm::dvec3& q = v[j];
        const double t = (split - p[axis]) / (q[axis] - p[axis]);
        glm::dvec3 x = p + t * (q - p);
        x = glm::clamp(x, glm::min(p, q), glm::max(p, q));
        x[axis] = split;
        cross_point[k] = x;
    }
    glm::dvec3 poly_low[4], poly_high[4];
    int n_low = 0, n_high = 0;
    for (int k = 0; k < 3; ++k) {
        if (side[k] <= 0) poly_low[n_low++] = v[k];
        if (side[k] >= 0) poly_high[n_high++] = v[k];
        if (crosses[k]) {
            poly_low[n_low++] = cross_point[k];
            poly_high[n_high++] = cross_point[k];
        }
    }
    assert(n_low >= 3 && n_low <= 4 && n_high >= 3 && n_high <= 4);
    emitFan(poly_low, n_low, source, low);
    emitFan(poly_high, n_high, source, high);
}

struct ObjectBsp::BuildState {
    std::vector<double> keys;  // centroids on the tried axis
    long long extra_pieces = 0;
    long long extra_budget = 0;
};

void ObjectBsp::build(const TriangleMesh& mesh, const ObjectBspParams& params) {
    assert(params.max_leaf_triangles >= 1);
    assert(params.max_depth >= 0 && params.max_depth <= kMaxObjectBspDepth);
    assert(params.max_extra_pieces_ratio >= 0.0);
    assert(mesh.indices.size() % 3 == 0);
    assert(mesh.indices.size() / 3 <= size_t(INT_MAX / 8));  // pieces stay within int
    params_ = params;
    nodes_.clear();
    pieces_.clear();
    leaf_count_ = 0;
    height_ = 0;
    source_triangles_ = int(mesh.indices.size() / 3);

    std::vector<BspTrianglePiece> work;
    work.reserve(size_t(source_triangles_));
    Aabb cell{glm::dvec3(0.0), glm::dvec3(0.0)};
    for (int t = 0; t < source_triangles_; ++t) {
        BspTrianglePiece p;
        for (int k = 0; k < 3; ++k) {
            const uint32_t index = mesh.indices[3 * size_t(t) + size_t(k)];
            assert(index < mesh.vertices.size());
            p.v[k] = mesh.vertices[index];
            assert(isFinite(p.v[k]));  // the mesh loader refuses non-finite vertices
        }
        p.source = t;
        if (t == 0)
            cell = pieceBox(p);
        else
            cell.merge(pieceBox(p));
        work.push_back(p);
    }

    BuildState state;
    state.keys.reserve(work.size());
    state.extra_budget = (long long)(params.max_extra_pieces_ratio * double(source_triangles_));
    // Reserve from an estimate: a quarter more pieces than triangles, leaves half full.
    const size_t est_pieces = size_t(source_triangles_) + size_t(source_triangles_) / 4;
    const size_t est_leaves = 2 * est_pieces / size_t(params.max_leaf_triangles) + 1;
    pieces_.reserve(est_pieces);
    nodes_.reserve(2 * est_leaves + 1);
    buildNode(state, work, cell, 0);
    assert(pieceCount() == nodes_[kRoot].piece_count);
    assert(size_t(pieceCount()) <= size_t(INT_MAX));
}

int ObjectBsp::buildNode(BuildState& state, std::vector<BspTrianglePiece>& work, const Aabb& cell,
                         int depth) {
    const int index = nodeCount();
    nodes_.emplace_back();
    height_ = std::max(height_, depth);
    const int n = int(work.size());
    Aabb bounds{cell.center(), cell.center()};
    if (n > 0) bounds = pieceBox(work[0]);
    for (int k = 1; k < n; ++k) bounds.merge(pieceBox(work[size_t(k)]));

    BspLeafReason reason = BspLeafReason::Inner;
    int axis = -1;
    double split = 0.0;
    if (n <= params_.max_leaf_triangles) {
        reason = BspLeafReason::Threshold;
    } else if (depth >= params_.max_depth) {
        reason = BspLeafReason::Depth;
    } else if (state.extra_pieces > state.extra_budget) {
        reason = BspLeafReason::Budget;
    } else {
        // Axes by decreasing extent of the pieces' bounds; the first whose median
        // plane leaves each side with fewer pieces than the node has.
        const glm::dvec3 e = bounds.extent();
        int order[3] = {0, 1, 2};
        axesByExtent(e, order);
        reason = BspLeafReason::Unsplittable;
        for (int a : order) {
            state.keys.clear();
            for (const BspTrianglePiece& p : work)
                state.keys.push_back((p.v[0][a] + p.v[1][a] + p.v[2][a]) / 3.0);
            auto mid = state.keys.begin() + ptrdiff_t(n / 2);
            std::nth_element(state.keys.begin(), mid, state.keys.end());
            const double s = *mid;
            int n_low = 0, n_high = 0;
            for (const BspTrianglePiece& p : work) {
                const int side = sideOf(p, a, s);
                n_low += side <= 0;
                n_high += side >= 0;
            }
            if (n_low < n && n_high < n) {
                axis = a;
                split = s;
                reason = BspLeafReason::Inner;
                break;
            }
        }
    }

    ObjectBspNode& node = nodes_[size_t(index)];
    node.cell = cell;
    node.bounds = bounds;
    node.depth = depth;
    node.reason = reason;
    node.first_piece = pieceCount();
    if (reason != BspLeafReason::Inner) {
        pieces_.insert(pieces_.end(), work.begin(), work.end());
        node.piece_count = n;
        ++leaf_count_;
        std::vector<BspTrianglePiece>().swap(work);
        return index;
    }
    node.axis = axis;
    node.split = split;

    std::vector<BspTrianglePiece> low, high;
    low.reserve(size_t(n));
    high.reserve(size_t(n));
    for (const BspTrianglePiece& p : work)
        clipTriangle(p.v[0], p.v[1], p.v[2], p.source, axis, split, low, high);
    state.extra_pieces += (long long)(low.size() + high.size()) - n;
    std::vector<BspTrianglePiece>().swap(work);

    Aabb low_cell = cell, high_cell = cell;
    low_cell.max[axis] = split;
    high_cell.min[axis] = split;
    const int first = pieceCount();
    const int low_child = buildNode(state, low, low_cell, depth + 1);
    const int high_child = buildNode(state, high, high_cell, depth + 1);
    ObjectBspNode& again = nodes_[size_t(index)];  // nodes_ may have grown
    again.low = low_child;
    again.high = high_child;
    again.first_piece = first;
    again.piece_count = pieceCount() - first;
    return index;
}

}  // namespace gridcull
