// View-frustum traversal of regular-grid culling in 3D (Batagelo & Wu, section
// 5.2), with the occluder extension and occlusion computation of section 5.3
// (rgvc_occlusion3d.h) after each layer. rgvc_culler.h says where this departs
// from the paper.
//
// Layer k is the cube shell of voxels at chess distance k from the viewer's
// voxel. Its seed voxel is the k-th voxel of the 3D Bresenham line of sight
// (grid/bresenham3d.h), which lies on the shell. The shell is swept as six
// disjoint faces (x = +-k whole; y = +-k without the x edges; z = +-k without
// the x and y edges), the seed's face first, row by row; each row is cut to the
// grid and to the frustum in O(1) (RgvcFrustum3::rowRange), so only frustum
// voxels are visited, each once. Within a layer the order does not change the
// result: a layer's voxels only occlude later layers.
#include <algorithm>
#include <cmath>

#include "culling/rgvc/rgvc_culler.h"

namespace gridcull {

namespace {

// The shell face f: axis a = f / 2 held at +-k (sign by f % 2); its voxels span
// [-k, k] on the other axes, less the edges that an earlier face owns.
struct ShellFace {
    int axis;
    int sign;
    int row_axis;    // the axis a row runs along (x unless the face is an x face)
    int other_axis;  // the third axis
};

ShellFace shellFace(int f) {
    ShellFace face;
    face.axis = f / 2;
    face.sign = f % 2 == 0 ? 1 : -1;
    face.row_axis = face.axis == 0 ? 1 : 0;
    face.other_axis = 3 - face.axis - face.row_axis;
    return face;
}

// How far face `owner_axis` trims axis `axis`: x faces own their y and z edges,
// y faces their z edges.
int64_t inset(int face_axis, int axis) {
    return axis < face_axis ? 1 : 0;
}

int faceOfOffset(const glm::i64vec3& d, int64_t k) {
    for (int a = 0; a < 3; ++a)
        if (std::llabs(d[a]) == k) return 2 * a + (d[a] > 0 ? 0 : 1);
    return 0;
}

}  // namespace

void RgvcCuller::traverse3d(const Scene& scene) {
    int64_t first = 0, last = 0;
    for (int a = 0; a < 3; ++a) {
        const int64_t top = grid_.resolution[a] - 1;
        first = std::max({first, -viewer3_[a], viewer3_[a] - top});
        last = std::max(
            {last, int64_t(std::llabs(viewer3_[a])), int64_t(std::llabs(viewer3_[a] - top))});
    }
    // No frustum voxel lies beyond the frustum's voxel box (far is a plane, so
    // a wide frustum reaches much further than `far` from the eye).
    glm::i64vec3 f_lo, f_hi;
    frustum3_.voxelBounds(f_lo, f_hi);
    int64_t reach = 0;
    for (int a = 0; a < 3; ++a)
        reach = std::max({reach, int64_t(std::llabs(f_lo[a] - viewer3_[a])),
                          int64_t(std::llabs(f_hi[a] - viewer3_[a]))});
    last = std::min(last, reach);
    if (snapshot_enabled_) snapshot_.first_layer = first;
    for (int64_t k = first; k <= last; ++k) {
        current_layer_ = k;
        layer_visited_ = 0;
        layer_all_occluded_ = true;
        layer_leaves_grid_ = false;
        layer_occluders_.clear();
        visitShell(scene, k);
        if (snapshot_enabled_) snapshot_.last_layer = k;
        occludeFromLayer3d(k);
        // Early termination: every ray of the frustum that goes further crosses
        // this layer inside the grid, in a voxel that blocks it.
        if (layer_visited_ > 0 && layer_all_occluded_ && !layer_leaves_grid_) {
            if (snapshot_enabled_) snapshot_.terminated_early = true;
            break;
        }
    }
}

void RgvcCuller::visitShell(const Scene& scene, int64_t k) {
    const glm::i64vec3 res(grid_.resolution);
    glm::i64vec3 f_lo, f_hi;
    frustum3_.voxelBounds(f_lo, f_hi);
    if (k == 0) {
        if (!frustum3_.touchesVoxel(viewer3_)) return;
        if (grid_.inside(glm::ivec3(viewer3_)))
            visitVoxel3d(scene, int(viewer3_.x), int(viewer3_.y), int(viewer3_.z), 0);
        else
            layer_leaves_grid_ = !eye_in_grid_;
        return;
    }
    const glm::i64vec3 seed_offset = line_of_sight3_.at(k);
    if (snapshot_enabled_) {
        RgvcSeed s;
        const glm::i64vec3 seed = viewer3_ + seed_offset;
        s.voxel = {seed.x, seed.y};
        s.z = seed.z;
        s.layer = k;
        snapshot_.seeds.push_back(s);
    }
    const int first_face = faceOfOffset(seed_offset, k);
    for (int n = 0; n < 6; ++n) {
        const int f = (first_face + n) % 6;
        const ShellFace face = shellFace(f);
        glm::i64vec3 at;
        at[face.axis] = viewer3_[face.axis] + face.sign * k;
        // The face's range on its two free axes, cut to the frustum's voxel box.
        int64_t lo[3], hi[3];
        bool empty = at[face.axis] < f_lo[face.axis] || at[face.axis] > f_hi[face.axis];
        for (const int a : {face.row_axis, face.other_axis}) {
            const int64_t trim = inset(face.axis, a);
            lo[a] = std::max(viewer3_[a] - k + trim, f_lo[a]);
            hi[a] = std::min(viewer3_[a] + k - trim, f_hi[a]);
            empty = empty || lo[a] > hi[a];
        }
        if (empty) continue;
        // Parts outside the grid: rays there may still enter it further out
        // when the eye is outside the grid's box.
        bool outside = at[face.axis] < 0 || at[face.axis] >= res[face.axis];
        for (const int a : {face.row_axis, face.other_axis})
            outside = outside || lo[a] < 0 || hi[a] >= res[a];
        if (outside && !eye_in_grid_) layer_leaves_grid_ = true;
        if (at[face.axis] < 0 || at[face.axis] >= res[face.axis]) continue;
        const int r = face.row_axis, q = face.other_axis;
        const int64_t q0 = std::max<int64_t>(lo[q], 0), q1 = std::min<int64_t>(hi[q], res[q] - 1);
        for (int64_t j = q0; j <= q1; ++j) {
            at[q] = j;
            at[r] = 0;
            int64_t i0 = std::max<int64_t>(lo[r], 0), i1 = std::min<int64_t>(hi[r], res[r] - 1);
            if (i0 > i1 || !frustum3_.rowRange(r, at, i0, i1)) continue;
            if (r == 0 && !snapshot_enabled_) {
                // Rows along x, by words: a stretch with nothing to do is visited
                // at once.
                for (int64_t c0 = i0; c0 <= i1;) {
                    const int64_t c1 = std::min(i1, c0 | 63);
                    if (!visitEmptyRun3d(int(c0), int(c1), int(at.y), int(at.z)))
                        for (int64_t i = c0; i <= c1; ++i)
                            visitVoxel3d(scene, int(i), int(at.y), int(at.z), k);
                    c0 = c1 + 1;
                }
                continue;
            }
            for (int64_t i = i0; i <= i1; ++i) {
                at[r] = i;
                visitVoxel3d(scene, int(at.x), int(at.y), int(at.z), k);
            }
        }
    }
}

void RgvcCuller::visitVoxel3d(const Scene& scene, int x, int y, int z, int64_t k) {
    ++voxels_visited_;
    ++layer_visited_;
    const int row = occlusion_.row(y, z);
    bool occluded = occlusion_.get(x, row);
    if (!occluded && direction_covered_) {
        // The cross-section test of s5.3 against every cap extruded so far.
        const glm::dvec3 lo = grid_.world.min + glm::dvec3(x, y, z) * voxel_size_;
        if (direction_map_.coversBox(lo, lo + voxel_size_)) {
            if (snapshot_enabled_) {
                int face, i, j;
                direction_map_.cellOfPoint(lo + 0.5 * voxel_size_, face, i, j);
                noteOccluded(x, row,
                             snapshot_.direction_cause[direction_map_.cellIndex(face, i, j)]);
            }
            occlusion_.set(x, row);
            occluded = true;
        }
    }
    if (snapshot_enabled_)
        snapshot_.visits.push_back(RgvcVisit{{x, y}, int32_t(z), int32_t(k), occluded});
    if (occluded) return;
    const bool blocks =
        occluder_.get(x, row) && frustum3_.minDepthOfVoxel({x, y, z}) >= frustum3_.near();
    if (!blocks) layer_all_occluded_ = false;
    open_.set(x, row);
    if (holds_static_.get(x, row))
        identifiers_static_.forEach(x, row, [&](int32_t index) { addToPvs(index); });
    if (holds_dynamic_.get(x, row))
        identifiers_dynamic_.forEach(x, row, [&](int32_t index) { addToPvs(index); });
    if (has_dynamic_) revealTbvsAt3d(scene, x, y, z);
    if (blocks) layer_occluders_.push_back({x, y, z});
}

bool RgvcCuller::visitEmptyRun3d(int x0, int x1, int y, int z) {
    // Empty: no voxel in H, O or I, none holding a TBV by the 2-of-3 test, and
    // none that the direction map could cover. Each such voxel would only be
    // counted and marked open, one by one, in visitVoxel3d.
    const int row = occlusion_.row(y, z);
    if (occlusion_.anySet(row, x0, x1) || occluder_.anySet(row, x0, x1) ||
        holds_static_.anySet(row, x0, x1) || holds_dynamic_.anySet(row, x0, x1))
        return false;
    if (has_dynamic_) {
        const bool yz = !tbv_yz_.empty(y, z);
        for (int x = x0; x <= x1; ++x)
            if (int(yz) + int(!tbv_matrix_.empty(x, y)) + int(!tbv_xz_.empty(x, z)) >= 2)
                return false;
    }
    if (direction_covered_) {
        const glm::dvec3 lo = grid_.world.min + glm::dvec3(x0, y, z) * voxel_size_;
        const glm::dvec3 hi = grid_.world.min + glm::dvec3(x1 + 1, y + 1, z + 1) * voxel_size_;
        if (direction_map_.mayCoverPartOf(lo, hi)) return false;
    }
    open_.setRun(row, x0, x1);
    const int64_t n = x1 - x0 + 1;
    voxels_visited_ += n;
    layer_visited_ += n;
    layer_all_occluded_ = false;
    return true;
}

void RgvcCuller::revealTbvsAt3d(const Scene& scene, int x, int y, int z) {
    const bool xy = !tbv_matrix_.empty(x, y), xz = !tbv_xz_.empty(x, z), yz = !tbv_yz_.empty(y, z);
    if (int(xy) + int(xz) + int(yz) < 2) return;
    // The 2-of-3 existence test of s5.2 in one pass over the three lists: a
    // stamp per object says "seen once" (once) or "already taken" (once + 1).
    tbv_test_ += 2;
    if (tbv_test_ < 2) {  // wrapped: old stamps could collide
        std::fill(tbv_seen_.begin(), tbv_seen_.end(), 0u);
        tbv_test_ = 2;
    }
    const uint32_t once = tbv_test_, taken = tbv_test_ + 1;
    reveal_scratch_.clear();
    auto see = [&](int32_t id) {
        uint32_t& s = tbv_seen_[size_t(id)];
        if (s == once) {
            s = taken;
            reveal_scratch_.push_back(id);
        } else if (s != taken) {
            s = once;
        }
    };
    tbv_matrix_.forEach(x, y, see);
    tbv_xz_.forEach(x, z, see);
    tbv_yz_.forEach(y, z, see);
    // A visible TBV voxel: its objects may be visible; put them into O and I now
    // so that the rest of the traversal decides (s4.2).
    for (const int index : reveal_scratch_)
        if (hasTbv(index)) revealTbv(scene, index, true);
}

bool RgvcCuller::blocksInLayer3d(int x, int y, int z) const {
    // A ray that leaves the layer's box outside the grid, from an eye inside the
    // grid's box, is outside that box for good: it reaches no voxel of the grid
    // any more (objects reaching outside the grid are kept by their own test),
    // so for the voxels it can hide it counts as blocked.
    if (x < 0 || y < 0 || z < 0 || x >= grid_.resolution.x || y >= grid_.resolution.y ||
        z >= grid_.resolution.z)
        return eye_in_grid_;
    const int row = occlusion_.row(y, z);
    if (occlusion_.get(x, row)) return true;
    return occluder_.get(x, row) && frustum3_.minDepthOfVoxel({x, y, z}) >= frustum3_.near();
}

void RgvcCuller::occludeFromLayer3d(int64_t k) {
    if (layer_occluders_.empty() || k == 0) return;
    ++direction_pass_;
    if (direction_pass_ == 0) direction_pass_ = direction_map_.restartPasses();
    const glm::dvec3& o = grid_.world.min;
    const glm::dvec3& eye = direction_map_.eye();
    // Is every ray of the cell blocked where it leaves the layer's outer box?
    // The rays of a cell on map face f leave mostly through the shell face of
    // the same axis and sign; through a side face only where they meet that
    // face's plane outside its square, on that side.
    auto faceBlocked = [&](int f, const DirectionCell& cell, bool& crosses, int64_t lo[2],
                           int64_t hi[2], bool& out_lo0, bool& out_hi0, bool& out_lo1,
                           bool& out_hi1) {
        const int a = f / 2;
        const int64_t s = f % 2 == 0 ? 1 : -1;
        const int64_t fixed = viewer3_[a] + s * k;
        const double plane = o[a] + double(s > 0 ? fixed + 1 : fixed) * voxel_size_[a];
        crosses = false;
        PlaneRect rect;
        if (!cellOnPlane(cell, eye, a, plane, rect)) return true;
        bool* out_lo[2] = {&out_lo0, &out_lo1};
        bool* out_hi[2] = {&out_hi0, &out_hi1};
        for (int n = 0; n < 2; ++n) {
            const int b = (a + 1 + n) % 3;
            // Voxel indices the rectangle meets, closed (a point on a voxel
            // boundary counts for both), cut to the face's square.
            const double u0 = (rect.lo[n] - o[b]) / voxel_size_[b] - 1e-9;
            const double u1 = (rect.hi[n] - o[b]) / voxel_size_[b] + 1e-9;
            const double sq0 = double(viewer3_[b] - k), sq1 = double(viewer3_[b] + k);
            *out_lo[n] = std::floor(u0) < sq0;
            *out_hi[n] = std::floor(u1) > sq1;
            lo[n] = int64_t(std::max(std::floor(u0), sq0));
            hi[n] = int64_t(std::min(std::floor(u1), sq1));
            if (lo[n] > hi[n]) return true;
        }
        crosses = true;
        glm::i64vec3 v;
        v[a] = fixed;
        for (int64_t i = lo[0]; i <= hi[0]; ++i)
            for (int64_t j = lo[1]; j <= hi[1]; ++j) {
                v[(a + 1) % 3] = i;
                v[(a + 2) % 3] = j;
                if (!blocksInLayer3d(int(v.x), int(v.y), int(v.z))) return false;
            }
        return true;
    };
    auto blocked = [&](const DirectionCell& cell) {
        const int a = cell.face / 2;
        int64_t lo[2], hi[2];
        bool crosses, side[4];
        if (!faceBlocked(cell.face, cell, crosses, lo, hi, side[0], side[1], side[2], side[3]))
            return false;
        bool any = crosses;
        bool unused[4];
        for (int n = 0; n < 2; ++n) {
            const int b = (a + 1 + n) % 3;
            for (int sgn = 0; sgn < 2; ++sgn) {
                // side[2n]: past the square's low end on axis b; side[2n + 1]: high end.
                if (crosses && !side[2 * n + sgn]) continue;
                const int f = 2 * b + (sgn == 0 ? 1 : 0);
                bool c;
                if (!faceBlocked(f, cell, c, lo, hi, unused[0], unused[1], unused[2], unused[3]))
                    return false;
                any = any || c;
            }
        }
        return any;
    };
    std::array<DirectionRect, 6> rects;
    const int last = direction_map_.resolution() - 1;
    // Cells outside the frustum matter only to voxels of later layers that
    // straddle its edge, whose footprints reach at most this many cells out: a
    // voxel of layer m > k lies (m - 1) d_min or more from the eye, its
    // directions span at most sqrt(3) d_max / ((m - 1) d_min) in the face's
    // coordinates, twice that at a face's edge, and a face has R / 2 cells per
    // unit.
    const double spread = std::sqrt(3.0) * std::max({voxel_size_.x, voxel_size_.y, voxel_size_.z}) /
                          std::min({voxel_size_.x, voxel_size_.y, voxel_size_.z});
    const int margin =
        int(std::min(double(last + 1), std::ceil(spread * (last + 1) / double(k)) + 1.0));
    for (const glm::ivec3& v : layer_occluders_) {
        const glm::dvec3 lo = o + glm::dvec3(v) * voxel_size_;
        const int n = direction_map_.footprint(lo, lo + voxel_size_, rects);
        int64_t covered = 0;
        for (int r = 0; r < n; ++r) {
            // One cell more on each side: cells straddling this voxel and its
            // blocking neighbours are where the caps fuse.
            DirectionRect rect = rects[size_t(r)];
            rect.i0 = std::max(rect.i0 - 1, 0), rect.i1 = std::min(rect.i1 + 1, last);
            rect.j0 = std::max(rect.j0 - 1, 0), rect.j1 = std::min(rect.j1 + 1, last);
            if (!direction_map_.clipToFrustum(rect, margin)) continue;
            if (!snapshot_enabled_) {
                covered += direction_map_.coverCells(rect, direction_pass_, blocked);
                continue;
            }
            const int32_t cause = int32_t(snapshot_.occluders3d.size());
            covered +=
                direction_map_.coverCells(rect, direction_pass_, [&](const DirectionCell& c) {
                    if (!blocked(c)) return false;
                    snapshot_.direction_cause[direction_map_.cellIndex(c.face, c.i, c.j)] = cause;
                    return true;
                });
        }
        direction_covered_ = direction_covered_ || covered > 0;
        if (snapshot_enabled_)
            snapshot_.occluders3d.push_back(RgvcOccluder3d{v, int32_t(k), covered});
    }
}

}  // namespace gridcull
