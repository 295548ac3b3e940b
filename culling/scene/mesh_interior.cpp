// Batagelo & Wu, section 5.1: the conservative interior of a closed mesh, from
// which alone regular-grid culling takes opaque voxels. mesh_interior.h gives the
// method and where it departs from the paper.
#include "culling/scene/mesh_interior.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <queue>
#include <utility>

#include <glm/geometric.hpp>

namespace gridcull {
namespace {

using glm::dvec3;
using Cell = std::array<int, 3>;

// Margins in units of the mesh's scale: its largest extent or coordinate magnitude,
// whichever is larger, because rounding grows with the coordinates. The geometric
// tests below round by a few 1e-16 of the scale per step, and a short edge can
// amplify that by the ratio of the scale to its length, which stays below 1e7 in
// meshes read as float (as the OBJ loader does); 1e-7 is far above that product
// and far below a cell (about 1/64 of the extent at the finest lattice) for a mesh
// near its own origin.
constexpr double kTouchMargin = 1e-7;  // a triangle this close to a cell touches it
constexpr double kRayMargin = 1e-7;    // a ray this close to an edge or vertex is unsure
// Points tried per component before it is given up on (treated as outside); each
// try that is unsure moves to another cell and another point in it.
constexpr int kRayAttempts = 8;

struct Lattice {
    Cell n{};
    std::array<std::vector<double>, 3> planes;  // n[a] + 1 coordinates along axis a

    size_t cellCount() const { return size_t(n[0]) * size_t(n[1]) * size_t(n[2]); }
    size_t index(const Cell& c) const {
        return (size_t(c[2]) * size_t(n[1]) + size_t(c[1])) * size_t(n[0]) + size_t(c[0]);
    }
    Cell cellOf(size_t index) const {
        const size_t row = index / size_t(n[0]);
        return {int(index % size_t(n[0])), int(row % size_t(n[1])), int(row / size_t(n[1]))};
    }
    // The cells along axis a whose closed extent meets [lo, hi]: first..last.
    void range(int a, double lo, double hi, int& first, int& last) const {
        const std::vector<double>& p = planes[size_t(a)];
        first = int(std::lower_bound(p.begin() + 1, p.end(), lo) - (p.begin() + 1));
        last = int(std::upper_bound(p.begin(), p.end() - 1, hi) - p.begin()) - 1;
    }
    bool onOuterLayer(const Cell& c) const {
        for (int a = 0; a < 3; ++a)
            if (c[size_t(a)] == 0 || c[size_t(a)] == n[size_t(a)] - 1) return true;
        return false;
    }
};

// Triangle-box separating-axis test (Akenine-Moller): false only when one of the 13
// axes separates them strictly, so touching counts. A degenerate triangle yields
// zero axes, which never separate, and its edge axes still decide.
bool triangleTouchesBox(const dvec3& v0, const dvec3& v1, const dvec3& v2, const dvec3& center,
                        const dvec3& half) {
    const dvec3 a = v0 - center, b = v1 - center, c = v2 - center;
    for (int k = 0; k < 3; ++k) {
        if (std::min({a[k], b[k], c[k]}) > half[k] || std::max({a[k], b[k], c[k]}) < -half[k])
            return false;
    }
    auto separates = [&](const dvec3& axis) {
        const double pa = glm::dot(axis, a), pb = glm::dot(axis, b), pc = glm::dot(axis, c);
        const double r =
            half.x * std::abs(axis.x) + half.y * std::abs(axis.y) + half.z * std::abs(axis.z);
        return std::min({pa, pb, pc}) > r || std::max({pa, pb, pc}) < -r;
    };
    const dvec3 edges[3] = {b - a, c - b, a - c};
    if (separates(glm::cross(edges[0], edges[1]))) return false;
    for (const dvec3& e : edges) {
        if (separates({0.0, -e.z, e.y}) || separates({e.z, 0.0, -e.x}) ||
            separates({-e.y, e.x, 0.0}))
            return false;
    }
    return true;
}

// Distance from the origin to the 2D segment [p, q].
double distanceToSegment2d(double px, double py, double qx, double qy) {
    const double dx = qx - px, dy = qy - py;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0.0 ? -(px * dx + py * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(px + t * dx, py + t * dy);
}

enum class Crossing { Miss, Hit, Unsure };

// Does the ray from p along +axis a cross the triangle? Decided in the plane of the
// other two axes, where the ray is the point p: Hit when p lies inside the projected
// triangle by more than `margin` and the triangle is ahead of p; Unsure when p is
// within `margin` of a projected edge or vertex, or the triangle is thinner than
// that as seen along the ray (the ray runs along its plane).
Crossing crossAxisRay(const dvec3& v0, const dvec3& v1, const dvec3& v2, const dvec3& p, int a,
                      double margin) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const double x[3] = {v0[b] - p[b], v1[b] - p[b], v2[b] - p[b]};
    const double y[3] = {v0[c] - p[c], v1[c] - p[c], v2[c] - p[c]};
    if (std::min({x[0], x[1], x[2]}) > margin || std::max({x[0], x[1], x[2]}) < -margin ||
        std::min({y[0], y[1], y[2]}) > margin || std::max({y[0], y[1], y[2]}) < -margin)
        return Crossing::Miss;
    double edge_fn[3], length[3];  // edge_fn[i]: twice the area of (v_i, v_i+1, p)
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        edge_fn[i] = x[i] * y[j] - x[j] * y[i];
        length[i] = std::hypot(x[j] - x[i], y[j] - y[i]);
    }
    const double area2 = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if (std::abs(area2) <= margin * (length[0] + length[1] + length[2])) {
        // Inradius below the margin: no point is farther than it inside, so p is
        // outside when it is farther than the margin from every edge.
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3;
            if (distanceToSegment2d(x[i], y[i], x[j], y[j]) <= margin) return Crossing::Unsure;
        }
        return Crossing::Miss;
    }
    const double sign = area2 > 0.0 ? 1.0 : -1.0;
    bool near_edge = false;
    for (int i = 0; i < 3; ++i) {
        const double inside_by = sign * edge_fn[i] / length[i];
        if (inside_by < -margin) return Crossing::Miss;
        if (inside_by <= margin) near_edge = true;
    }
    if (near_edge) return Crossing::Unsure;
    // Barycentric interpolation: edge_fn[i] weighs the vertex opposite edge i.
    const double hit = (edge_fn[1] * v0[a] + edge_fn[2] * v1[a] + edge_fn[0] * v2[a]) / area2;
    if (std::abs(hit - p[a]) <= margin) return Crossing::Unsure;
    return hit > p[a] ? Crossing::Hit : Crossing::Miss;
}

// The triangles that touch each cell, as offsets into one list (CSR).
struct Bins {
    std::vector<uint32_t> offsets;  // cellCount() + 1
    std::vector<uint32_t> triangles;
    bool empty(size_t cell) const { return offsets[cell] == offsets[cell + 1]; }
};

Bins binTriangles(const TriangleMesh& mesh, const Lattice& lattice, double margin) {
    std::vector<std::pair<uint32_t, uint32_t>> touches;  // (cell, triangle)
    const size_t triangle_count = mesh.indices.size() / 3;
    for (size_t t = 0; t < triangle_count; ++t) {
        const dvec3& v0 = mesh.vertices[mesh.indices[3 * t]];
        const dvec3& v1 = mesh.vertices[mesh.indices[3 * t + 1]];
        const dvec3& v2 = mesh.vertices[mesh.indices[3 * t + 2]];
        const dvec3 lo = glm::min(glm::min(v0, v1), v2) - margin;
        const dvec3 hi = glm::max(glm::max(v0, v1), v2) + margin;
        Cell first, last;
        for (int a = 0; a < 3; ++a)
            lattice.range(a, lo[a], hi[a], first[size_t(a)], last[size_t(a)]);
        Cell c;
        for (c[2] = first[2]; c[2] <= last[2]; ++c[2]) {
            for (c[1] = first[1]; c[1] <= last[1]; ++c[1]) {
                for (c[0] = first[0]; c[0] <= last[0]; ++c[0]) {
                    dvec3 center, half;
                    for (size_t a = 0; a < 3; ++a) {
                        const double c0 = lattice.planes[a][size_t(c[a])];
                        const double c1 = lattice.planes[a][size_t(c[a]) + 1];
                        center[int(a)] = 0.5 * (c0 + c1);
                        half[int(a)] = 0.5 * (c1 - c0) + margin;
                    }
                    if (triangleTouchesBox(v0, v1, v2, center, half))
                        touches.emplace_back(uint32_t(lattice.index(c)), uint32_t(t));
                }
            }
        }
    }
    Bins bins;
    bins.offsets.assign(lattice.cellCount() + 1, 0);
    for (const auto& [cell, t] : touches) ++bins.offsets[cell + 1];
    for (size_t i = 1; i < bins.offsets.size(); ++i) bins.offsets[i] += bins.offsets[i - 1];
    bins.triangles.resize(touches.size());
    std::vector<uint32_t> cursor(bins.offsets.begin(), bins.offsets.end() - 1);
    for (const auto& [cell, t] : touches) bins.triangles[cursor[cell]++] = t;
    return bins;
}

// Ray parity along +axis a from p in the free cell `from`: the ray stays in the
// lattice row of `from`, and every triangle it crosses is binned in a cell of that
// row ahead of `from`, so only those are tested, each once (`stamp` remembers the
// last ray that tested a triangle).
Crossing parityAlongAxis(const TriangleMesh& mesh, const Lattice& lattice, const Bins& bins,
                         const dvec3& p, const Cell& from, int a, double margin,
                         std::vector<uint32_t>& stamp, uint32_t ray_id) {
    bool odd = false;
    Cell c = from;
    for (c[size_t(a)] = from[size_t(a)] + 1; c[size_t(a)] < lattice.n[size_t(a)]; ++c[size_t(a)]) {
        const size_t cell = lattice.index(c);
        for (uint32_t k = bins.offsets[cell]; k < bins.offsets[cell + 1]; ++k) {
            const uint32_t t = bins.triangles[k];
            if (stamp[t] == ray_id) continue;
            stamp[t] = ray_id;
            const Crossing crossing =
                crossAxisRay(mesh.vertices[mesh.indices[3 * size_t(t)]],
                             mesh.vertices[mesh.indices[3 * size_t(t) + 1]],
                             mesh.vertices[mesh.indices[3 * size_t(t) + 2]], p, a, margin);
            if (crossing == Crossing::Unsure) return Crossing::Unsure;
            if (crossing == Crossing::Hit) odd = !odd;
        }
    }
    return odd ? Crossing::Hit : Crossing::Miss;  // Hit: inside
}

// Labels the free cells by component (face neighbours), and says which components
// are inside. A component on the lattice's outer layer is outside: a point of its
// outer face lies on the bounds and off the surface, and the ray from it straight
// out of the bounds meets no triangle. The others vote with three axis rays.
std::vector<uint8_t> interiorCells(const TriangleMesh& mesh, const Lattice& lattice,
                                   const Bins& bins, double ray_margin) {
    const size_t cells = lattice.cellCount();
    std::vector<uint8_t> interior(cells, 0);
    std::vector<uint8_t> seen(cells, 0);
    std::vector<size_t> members;  // one component's cells, in breadth-first order
    std::vector<uint32_t> stamp(mesh.indices.size() / 3, 0);
    uint32_t ray_id = 0;
    // Fractions of a cell for the ray's start, irrational steps so that no two tries
    // and no axis-aligned face of a mesh on a round coordinate line up.
    const double kFractionStart[3] = {0.41421356237309505, 0.7320508075688772, 0.2360679774997897};
    constexpr double kFractionStep = 0.6180339887498949;
    for (size_t start = 0; start < cells; ++start) {
        if (seen[start] || !bins.empty(start)) continue;
        members.assign(1, start);
        seen[start] = 1;
        bool outer = false;
        for (size_t head = 0; head < members.size(); ++head) {
            const Cell c = lattice.cellOf(members[head]);
            outer = outer || lattice.onOuterLayer(c);
            for (size_t a = 0; a < 3; ++a) {
                for (int step : {-1, 1}) {
                    Cell d = c;
                    d[a] += step;
                    if (d[a] < 0 || d[a] >= lattice.n[a]) continue;
                    const size_t next = lattice.index(d);
                    if (seen[next] || !bins.empty(next)) continue;
                    seen[next] = 1;
                    members.push_back(next);
                }
            }
        }
        if (outer) continue;
        Crossing votes[3] = {Crossing::Unsure, Crossing::Unsure, Crossing::Unsure};
        for (int attempt = 0; attempt < kRayAttempts; ++attempt) {
            if (votes[0] != Crossing::Unsure && votes[1] != Crossing::Unsure &&
                votes[2] != Crossing::Unsure)
                break;
            const Cell c = lattice.cellOf(members[size_t(attempt) * members.size() / kRayAttempts]);
            dvec3 p;
            for (size_t a = 0; a < 3; ++a) {
                const double f = kFractionStart[a] + attempt * kFractionStep;
                const double lo = lattice.planes[a][size_t(c[a])];
                const double hi = lattice.planes[a][size_t(c[a]) + 1];
                p[int(a)] = lo + (hi - lo) * (0.15 + 0.7 * (f - std::floor(f)));
            }
            for (int a = 0; a < 3; ++a) {
                if (votes[a] != Crossing::Unsure) continue;
                votes[a] =
                    parityAlongAxis(mesh, lattice, bins, p, c, a, ray_margin, stamp, ++ray_id);
            }
        }
        const bool inside =
            votes[0] == Crossing::Hit && votes[1] == Crossing::Hit && votes[2] == Crossing::Hit;
        if (inside)
            for (size_t cell : members) interior[cell] = 1;
    }
    return interior;
}

// Summed-volume table of the cells still free for the merge: any box's count in O(1).
class FreeCount {
public:
    FreeCount(const Lattice& lattice, const std::vector<uint8_t>& free) : n_(lattice.n) {
        sums_.assign(size_t(n_[0] + 1) * size_t(n_[1] + 1) * size_t(n_[2] + 1), 0);
        for (int z = 1; z <= n_[2]; ++z)
            for (int y = 1; y <= n_[1]; ++y)
                for (int x = 1; x <= n_[0]; ++x) {
                    at(x, y, z) = int32_t(free[lattice.index({x - 1, y - 1, z - 1})]) +
                                  at(x - 1, y, z) + at(x, y - 1, z) + at(x, y, z - 1) -
                                  at(x - 1, y - 1, z) - at(x - 1, y, z - 1) - at(x, y - 1, z - 1) +
                                  at(x - 1, y - 1, z - 1);
                }
    }
    // Free cells in [lo, hi) (hi exclusive).
    int64_t count(const Cell& lo, const Cell& hi) const {
        return int64_t(at(hi[0], hi[1], hi[2])) - at(lo[0], hi[1], hi[2]) -
               at(hi[0], lo[1], hi[2]) - at(hi[0], hi[1], lo[2]) + at(lo[0], lo[1], hi[2]) +
               at(lo[0], hi[1], lo[2]) + at(hi[0], lo[1], lo[2]) - at(lo[0], lo[1], lo[2]);
    }
    // The cells of [lo, hi), all free, are taken: every sum over a corner region
    // loses its overlap with the box (only sums beyond lo change).
    void take(const Cell& lo, const Cell& hi) {
        for (int z = lo[2] + 1; z <= n_[2]; ++z) {
            const int oz = std::min(z, hi[2]) - lo[2];
            for (int y = lo[1] + 1; y <= n_[1]; ++y) {
                const int oyz = (std::min(y, hi[1]) - lo[1]) * oz;
                for (int x = lo[0] + 1; x <= n_[0]; ++x)
                    at(x, y, z) -= (std::min(x, hi[0]) - lo[0]) * oyz;
            }
        }
    }

private:
    int32_t& at(int x, int y, int z) {
        return sums_[(size_t(z) * size_t(n_[1] + 1) + size_t(y)) * size_t(n_[0] + 1) + size_t(x)];
    }
    int32_t at(int x, int y, int z) const {
        return sums_[(size_t(z) * size_t(n_[1] + 1) + size_t(y)) * size_t(n_[0] + 1) + size_t(x)];
    }
    Cell n_;
    std::vector<int32_t> sums_;
};

int64_t volumeOf(const Cell& lo, const Cell& hi) {
    return int64_t(hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
}

// The largest free box [lo, hi) found by growing from lo in +x, +y and +z in each
// of the six axis orders; each growth is a binary search, since a box that is all
// free stays so when it shrinks. Returns its cell count; lo must be free.
int64_t growBox(const Cell& lo, const Lattice& lattice, const FreeCount& free, Cell& best_hi) {
    static constexpr int kOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                          {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    int64_t best = 0;
    for (const auto& order : kOrders) {
        Cell hi = {lo[0] + 1, lo[1] + 1, lo[2] + 1};
        for (int a : order) {
            int good = hi[size_t(a)], bad = lattice.n[size_t(a)] + 1;
            while (bad - good > 1) {
                const int mid = (good + bad) / 2;
                Cell trial = hi;
                trial[size_t(a)] = mid;
                if (free.count(lo, trial) == volumeOf(lo, trial)) {
                    good = mid;
                } else {
                    bad = mid;
                }
            }
            hi[size_t(a)] = good;
        }
        if (volumeOf(lo, hi) > best) {
            best = volumeOf(lo, hi);
            best_hi = hi;
        }
    }
    return best;
}

struct CellBox {
    Cell lo{}, hi{};  // hi exclusive
    int64_t cells = 0;
};

// Greedy merge: the largest box still free, again and again. Lazily: every seed
// cell starts with an upper bound on the box it can grow (bounds only shrink as
// boxes are taken) and is grown only when that bound comes to the top of the
// heap; a grown box whose cells were taken meanwhile is grown again.
std::vector<CellBox> mergeCells(const Lattice& lattice, std::vector<uint8_t> free, int max_boxes) {
    struct Candidate {
        int64_t cells;  // exact: the grown box's; otherwise an upper bound
        uint32_t seed;
        bool exact;
    };
    auto smaller = [](const Candidate& p, const Candidate& q) {
        if (p.cells != q.cells) return p.cells < q.cells;
        if (p.exact != q.exact) return q.exact;
        return p.seed > q.seed;
    };
    std::vector<Candidate> heap;
    int64_t left = 0;  // free cells
    {
        // The bound: the largest free rectangle in the seed's z layer with its lowest
        // corner there (rows of free x runs stacked in +y) times the free z run.
        const size_t row = size_t(lattice.n[0]), layer = row * size_t(lattice.n[1]);
        std::vector<int32_t> run_x(free.size(), 0), run_z(free.size(), 0);
        for (size_t cell = free.size(); cell-- > 0;) {
            if (!free[cell]) continue;
            const Cell c = lattice.cellOf(cell);
            run_x[cell] = 1 + (c[0] + 1 < lattice.n[0] ? run_x[cell + 1] : 0);
            run_z[cell] = 1 + (c[2] + 1 < lattice.n[2] ? run_z[cell + layer] : 0);
            int64_t rectangle = 0;
            int32_t width = run_x[cell];
            for (int y = c[1]; y < lattice.n[1] && width > 0; ++y) {
                width = std::min(width, run_x[cell + size_t(y - c[1]) * row]);
                rectangle = std::max(rectangle, int64_t(width) * (y - c[1] + 1));
            }
            heap.push_back({rectangle * run_z[cell], uint32_t(cell), false});
            ++left;
        }
    }
    std::make_heap(heap.begin(), heap.end(), smaller);
    FreeCount count(lattice, free);
    std::vector<Cell> grown_hi(free.size());  // far corner of a seed's exact candidate
    std::vector<CellBox> taken;
    while (!heap.empty() && left > 0 && int(taken.size()) < max_boxes) {
        std::pop_heap(heap.begin(), heap.end(), smaller);
        const Candidate top = heap.back();
        heap.pop_back();
        if (!free[top.seed]) continue;
        const Cell lo = lattice.cellOf(top.seed);
        Cell& hi = grown_hi[top.seed];
        if (!top.exact || count.count(lo, hi) != top.cells) {
            heap.push_back({growBox(lo, lattice, count, hi), top.seed, true});
            std::push_heap(heap.begin(), heap.end(), smaller);
            continue;
        }
        Cell c;
        for (c[2] = lo[2]; c[2] < hi[2]; ++c[2])
            for (c[1] = lo[1]; c[1] < hi[1]; ++c[1])
                for (c[0] = lo[0]; c[0] < hi[0]; ++c[0]) free[lattice.index(c)] = 0;
        count.take(lo, hi);
        left -= top.cells;
        taken.push_back({lo, hi, top.cells});
    }
    // Regrown candidates can come out larger than earlier ones: sort once more.
    std::stable_sort(taken.begin(), taken.end(),
                     [](const CellBox& p, const CellBox& q) { return p.cells > q.cells; });
    return taken;
}

}  // namespace

std::vector<Aabb> meshInteriorBoxes(const TriangleMesh& mesh, const MeshInteriorOptions& options) {
    assert(options.resolution >= 1 && options.resolution <= kMaxMeshInteriorResolution);
    assert(options.max_boxes >= 0);
    assert(mesh.indices.size() % 3 == 0);
    if (!mesh.closed || mesh.indices.empty() || options.max_boxes == 0) return {};

    // Bounds and scale of the vertices that triangles use (not trusting `bounds`).
    for (uint32_t index : mesh.indices) assert(index < mesh.vertices.size());
    Aabb bounds{mesh.vertices[mesh.indices[0]], mesh.vertices[mesh.indices[0]]};
    for (uint32_t index : mesh.indices) bounds.merge({mesh.vertices[index], mesh.vertices[index]});
    const dvec3 extent = bounds.extent();
    const double longest = std::max({extent.x, extent.y, extent.z});
    double scale = longest;
    for (int a = 0; a < 3; ++a)
        scale = std::max({scale, std::abs(bounds.min[a]), std::abs(bounds.max[a])});
    const double touch_margin = kTouchMargin * scale;

    // Cells no longer than the longest axis's; an axis thinner than three cells, or
    // with cells within the margin, has no cell off the outer layer and cannot be proven.
    Lattice lattice;
    const double cell_size = longest / options.resolution;
    for (int a = 0; a < 3; ++a) {
        const int n = extent[a] == longest ? options.resolution
                                           : std::clamp(int(std::ceil(extent[a] / cell_size)), 1,
                                                        options.resolution);
        if (n < 3 || extent[a] / n <= 2.0 * touch_margin) return {};
        lattice.n[size_t(a)] = n;
        std::vector<double>& planes = lattice.planes[size_t(a)];
        planes.resize(size_t(n) + 1);
        for (int i = 0; i < n; ++i) planes[size_t(i)] = bounds.min[a] + extent[a] * i / n;
        planes[size_t(n)] = bounds.max[a];
    }

    const Bins bins = binTriangles(mesh, lattice, touch_margin);
    const std::vector<uint8_t> interior = interiorCells(mesh, lattice, bins, kRayMargin * scale);
    std::vector<Aabb> boxes;
    for (const CellBox& box : mergeCells(lattice, interior, options.max_boxes)) {
        Aabb b;
        for (size_t a = 0; a < 3; ++a) {
            b.min[int(a)] = lattice.planes[a][size_t(box.lo[a])];
            b.max[int(a)] = lattice.planes[a][size_t(box.hi[a])];
        }
        boxes.push_back(b);
    }
    return boxes;
}

}  // namespace gridcull
