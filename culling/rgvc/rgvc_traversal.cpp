// View-frustum traversal of regular-grid culling (Batagelo & Wu, section 4.2),
// with occluder extension and occlusion computation (sections 4.3, 4.4) run
// from each non-occluded opaque voxel it reaches. rgvc_culler.h says where this
// departs from the paper.
//
// Layer k is the chess ring at distance k from the viewer's voxel
// (grid/chess_ring.h). Its seed voxel is the k-th voxel of the Bresenham line of
// sight, which lies on ring k; from the seed the walk goes counter-clockwise to
// one end of the ring's frustum run (rgvc_frustum.h) and then clockwise from the
// seed to the other end: the two directions of the paper's six rules. Stretches
// of the ring outside the grid are skipped in O(1); every ring position is
// reached at most once, so every frustum voxel is visited at most once and
// layers come in increasing chess distance.
#include <algorithm>
#include <cmath>

#include "culling/rgvc/rgvc_culler.h"
#include "culling/rgvc/rgvc_occlusion.h"
#include "grid/chess_ring.h"

namespace gridcull {

namespace {

int64_t positiveMod(int64_t a, int64_t n) {
    const int64_t m = a % n;
    return m < 0 ? m + n : m;
}

// Side s of ring k: the offset of its first position and the step along it.
void ringSide(int64_t k, int64_t side, glm::i64vec2& base, glm::i64vec2& step) {
    switch (side) {
        case 0:
            base = {k, -k}, step = {0, 1};
            return;
        case 1:
            base = {k, k}, step = {-1, 0};
            return;
        case 2:
            base = {-k, k}, step = {0, -1};
            return;
        default:
            base = {-k, -k}, step = {1, 0};
            return;
    }
}

// The range [lo, hi] of u for which c0 + u * st lies in [0, limit), st = +-1.
void axisRange(int64_t c0, int64_t st, int64_t limit, int64_t& lo, int64_t& hi) {
    if (st > 0) {
        lo = -c0;
        hi = limit - 1 - c0;
    } else {
        lo = c0 - (limit - 1);
        hi = c0;
    }
}

}  // namespace

void RgvcCuller::traverse(const Scene& scene) {
    const int64_t w = grid_.resolution.x, h = grid_.resolution.y;
    const int64_t gap_x = std::max({int64_t(0), -viewer_.x, viewer_.x - (w - 1)});
    const int64_t gap_y = std::max({int64_t(0), -viewer_.y, viewer_.y - (h - 1)});
    const int64_t first = std::max(gap_x, gap_y);
    int64_t last = std::max({std::abs(viewer_.x), std::abs(viewer_.x - (w - 1)),
                             std::abs(viewer_.y), std::abs(viewer_.y - (h - 1))});
    // A voxel of layer k is at least (k - 1) voxel sides from the viewpoint.
    const double side = std::min(voxel_size_.x, voxel_size_.y);
    const double far_layers = std::floor(wedge_.far() / side) + 2.0;
    if (far_layers < double(last)) last = int64_t(far_layers);
    if (snapshot_enabled_) snapshot_.first_layer = first;
    for (int64_t k = first; k <= last; ++k) {
        current_layer_ = k;
        layer_visited_ = 0;
        layer_all_occluded_ = true;
        layer_leaves_grid_ = false;
        visitLayer(scene, k);
        if (snapshot_enabled_) snapshot_.last_layer = k;
        // Early termination: every ray that goes further crosses this layer
        // inside the frustum and inside the grid, in an occluded voxel.
        if (layer_visited_ > 0 && layer_all_occluded_ && !layer_leaves_grid_) {
            if (snapshot_enabled_) snapshot_.terminated_early = true;
            break;
        }
    }
}

void RgvcCuller::visitLayer(const Scene& scene, int64_t k) {
    const RingRun run = wedge_.layerRun(grid_, viewer_, k);
    const int64_t n = ringSize(k);
    int64_t seed = k == 0 ? 0 : ringIndex(line_of_sight_.at(k));
    int64_t offset = positiveMod(seed - run.start, n);
    bool moved = false;
    if (offset >= run.length) {
        // The line of sight's voxel misses the frustum (possible near the viewer
        // with a narrow wedge): start at the nearer end of the run.
        moved = true;
        const int64_t end = run.start + run.length - 1;
        const int64_t to_start = positiveMod(run.start - seed, n);
        const int64_t to_end = positiveMod(seed - end, n);
        seed = positiveMod(to_start <= to_end ? run.start : end, n);
        offset = positiveMod(seed - run.start, n);
    }
    if (snapshot_enabled_) {
        RgvcSeed s;
        s.voxel = viewer_ + ringOffset(k, seed);
        s.layer = k;
        s.moved = moved;
        snapshot_.seeds.push_back(s);
    }
    const bool within_far = wedge_.layerWithinFar(grid_, viewer_, k);
    visitArc(scene, k, run, within_far, seed, run.length - offset, +1);
    visitArc(scene, k, run, within_far, seed - 1, offset, -1);
}

void RgvcCuller::visitArc(const Scene& scene, int64_t k, const RingRun& run, bool within_far,
                          int64_t from, int64_t count, int dir) {
    if (count <= 0) return;
    const int64_t w = grid_.resolution.x, h = grid_.resolution.y;
    const glm::dvec3& o = grid_.world.min;
    const glm::dvec3& d = voxel_size_;
    if (k == 0) {
        if (grid_.inside({int(viewer_.x), int(viewer_.y), 0})) {
            if (wedge_.touchesVoxel(grid_, viewer_))
                visitVoxel(scene, int(viewer_.x), int(viewer_.y), 0);
        } else if (wedge_.touchesVoxel(grid_, viewer_)) {
            layer_leaves_grid_ = true;
        }
        return;
    }
    const int64_t n = ringSize(k), side_len = 2 * k;
    int64_t p = positiveMod(from, n);
    while (count > 0) {
        const int64_t side = p / side_len, side_start = side * side_len;
        const int64_t piece = dir > 0 ? std::min(count, side_start + side_len - p)
                                      : std::min(count, p - side_start + 1);
        // Positions p, p + dir, ... on this side, as u = position - side_start.
        const int64_t u_a = p - side_start, u_b = u_a + dir * (piece - 1);
        const int64_t u_lo = std::min(u_a, u_b), u_hi = std::max(u_a, u_b);
        glm::i64vec2 base, step;
        ringSide(k, side, base, step);
        const glm::i64vec2 origin = viewer_ + base;
        // The side's grid range of u: the fixed coordinate must be inside, the
        // moving one inside its limit.
        int64_t g_lo, g_hi;
        if (step.x == 0) {
            axisRange(origin.y, step.y, h, g_lo, g_hi);
            if (origin.x < 0 || origin.x >= w) g_lo = 1, g_hi = 0;
        } else {
            axisRange(origin.x, step.x, w, g_lo, g_hi);
            if (origin.y < 0 || origin.y >= h) g_lo = 1, g_hi = 0;
        }
        const int64_t in_lo = std::max(u_lo, g_lo), in_hi = std::min(u_hi, g_hi);
        // Parts of the piece outside the grid: does any of their voxels touch the
        // frustum? (One box test per part.)
        auto outside_part = [&](int64_t a, int64_t b) {
            if (a > b || layer_leaves_grid_) return;
            const glm::i64vec2 va = origin + step * a, vb = origin + step * b;
            const glm::i64vec2 lo = glm::min(va, vb), hi = glm::max(va, vb);
            if (wedge_.touchesBox(o.x + double(lo.x) * d.x, o.y + double(lo.y) * d.y,
                                  o.x + double(hi.x + 1) * d.x, o.y + double(hi.y + 1) * d.y))
                layer_leaves_grid_ = true;
        };
        if (in_lo > in_hi) {
            outside_part(u_lo, u_hi);
        } else {
            outside_part(u_lo, in_lo - 1);
            outside_part(in_hi + 1, u_hi);
            const int64_t first = dir > 0 ? in_lo : in_hi;
            const int64_t count_in = in_hi - in_lo + 1;
            for (int64_t i = 0; i < count_in; ++i) {
                const int64_t u = first + dir * i;
                const glm::i64vec2 v = origin + step * u;
                // Voxels of the run's inner part lie in the wedge; within far too
                // when the whole layer does.
                const bool surely_in = within_far && positiveMod(side_start + u - run.inner_start,
                                                                 n) < run.inner_length;
                if (surely_in || wedge_.touchesVoxel(grid_, v))
                    visitVoxel(scene, int(v.x), int(v.y), k);
            }
        }
        p = positiveMod(p + dir * piece, n);
        count -= piece;
    }
}

void RgvcCuller::visitVoxel(const Scene& scene, int x, int y, int64_t k) {
    ++voxels_visited_;
    ++layer_visited_;
    const bool occluded = occlusion_.get(x, y);
    if (snapshot_enabled_) snapshot_.visits.push_back(RgvcVisit{{x, y}, 0, int32_t(k), occluded});
    if (occluded) return;
    layer_all_occluded_ = false;
    open_.set(x, y);
    identifiers_static_.forEach(x, y, [&](int32_t index) { addToPvs(index); });
    identifiers_dynamic_.forEach(x, y, [&](int32_t index) { addToPvs(index); });
    if (has_dynamic_ && !tbv_matrix_.empty(x, y)) {
        // A visible TBV voxel: its objects may be visible; put them into O and I
        // now so that the rest of the traversal decides (s4.2).
        reveal_scratch_.clear();
        tbv_matrix_.forEach(x, y, [&](int32_t index) { reveal_scratch_.push_back(index); });
        for (const int index : reveal_scratch_)
            if (hasTbv(index)) revealTbv(scene, index, true);
    }
    if (occluder_.get(x, y)) occludeFrom(x, y, k);
}

void RgvcCuller::occludeFrom(int x, int y, int64_t k) {
    const RgvcExtendedOccluder occ = extendOccluder(
        {x, y}, viewer_, grid_.resolution.x, grid_.resolution.y, RgvcExtension(options_.extension),
        [&](int a, int b) { return occluder_.get(a, b) || occlusion_.get(a, b); });
    RgvcOcclusionPolygons polygons;
    const int count = occlusionPolygons(occ, grid_, wedge_.apex(), polygons);
    int64_t marked = 0;
    for (int i = 0; i < count; ++i)
        marked += rasterizeOcclusionPolygon(
            polygons[size_t(i)], grid_, clip_x0_, clip_x1_, clip_y0_, clip_y1_,
            [&](int row, int x0, int x1) {
                if (snapshot_enabled_)
                    for (int x = x0; x <= x1; ++x)
                        noteOccluded(x, row, int32_t(snapshot_.occluders.size()));
                occlusion_.setRun(row, x0, x1);
            });
    if (snapshot_enabled_) {
        RgvcOccluderView view;
        view.layer = k;
        view.occluder = occ;
        view.polygon_count = count;
        view.polygons = polygons;
        view.voxels_occluded = marked;
        snapshot_.occluders.push_back(view);
    }
}

}  // namespace gridcull
