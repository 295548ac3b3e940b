#include "ui/rgvc/rgvc_cap3d.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include <glm/geometric.hpp>

#include "culling/rgvc/rgvc_occlusion3d.h"
#include "ui/rgvc/rgvc_history.h"

namespace gridcull {

namespace {

// The hatch: one diagonal per filled pixel whose diagonal index is a multiple of this.
constexpr int kHatchEvery = 3;

// Where the ray from `eye` through `p` (inside the world box or on it) leaves the box.
glm::dvec3 exitPoint(const Aabb& box, const glm::dvec3& eye, const glm::dvec3& p) {
    const glm::dvec3 d = p - eye;
    double t = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (d[a] > 0.0) t = std::min(t, (box.max[a] - eye[a]) / d[a]);
        if (d[a] < 0.0) t = std::min(t, (box.min[a] - eye[a]) / d[a]);
    }
    if (!std::isfinite(t) || t < 1.0) t = 1.0;
    return eye + d * t;
}

// The four corners of a direction-map cell where their rays meet the plane
// x_axis = plane; false unless all four meet it ahead of the eye.
bool cellCorners(const DirectionCell& cell, const glm::dvec3& eye, int axis, double plane,
                 glm::dvec3 out[4]) {
    const int fa = cell.face / 2, fb = (fa + 1) % 3, fc = (fa + 2) % 3;
    const double s = cell.face % 2 == 0 ? 1.0 : -1.0;
    const double us[4] = {cell.u0, cell.u1, cell.u1, cell.u0};
    const double vs[4] = {cell.v0, cell.v0, cell.v1, cell.v1};
    for (int k = 0; k < 4; ++k) {
        glm::dvec3 r;
        r[fa] = s;
        r[fb] = us[k];
        r[fc] = vs[k];
        if (r[axis] == 0.0) return false;
        const double t = (plane - eye[axis]) / r[axis];
        if (!(t > 0.0)) return false;
        out[k] = eye + r * t;
    }
    return true;
}

}  // namespace

bool rgvcLoopHolds(const glm::ivec2* corners, int count, double x, double y) {
    bool inside = false;
    for (int k = 0, j = count - 1; k < count; j = k++) {
        const glm::dvec2 a(corners[k]), b(corners[j]);
        if ((a.y > y) != (b.y > y) && x < a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y))
            inside = !inside;
    }
    return inside;
}

bool rgvcBlocksAtLayer(const RgvcSnapshot& s, double near, int x, int y, int z, int64_t layer) {
    if (rgvcHAt(s, x, y, z, layer)) return true;
    if (!rgvcOAt(s, x, y, z, layer)) return false;
    const Aabb box = s.grid.voxelBounds({x, y, z});
    double depth = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 8; ++k)
        depth = std::min(depth, glm::dot(box.corner(k) - s.viewpoint, s.forward));
    return depth >= near;
}

glm::dvec3 RgvcCap3d::world(const RgvcSnapshot& s, double u, double w) const {
    const glm::dvec3 d = s.grid.voxelSize();
    glm::dvec3 p;
    p[axis] = plane;
    p[b] = s.grid.world.min[b] + (b0 + u) * d[b];
    p[c] = s.grid.world.min[c] + (c0 + w) * d[c];
    return p;
}

void buildRgvcCap3d(const RgvcSnapshot& s, double near, int index, RgvcCap3d& cap) {
    const RgvcSnapshotStamp stamp = RgvcSnapshotStamp::of(s);
    if (cap.built_from == stamp && cap.occluder == index) return;
    cap.built_from = stamp;
    cap.valid = false;
    cap.occluder = index;
    cap.cells.clear();
    if (!s.valid || s.dimensions != 3 || index < 0 || size_t(index) >= s.occluders3d.size()) return;
    const RgvcOccluder3d& occ = s.occluders3d[size_t(index)];
    const glm::i64vec3 eye(s.viewer_voxel.x, s.viewer_voxel.y, s.viewer_voxel_z);
    const int64_t k = occ.layer;
    cap.layer = occ.layer;
    cap.axis = -1;
    for (int a = 0; a < 3 && cap.axis < 0; ++a)
        if (std::llabs(int64_t(occ.voxel[a]) - eye[a]) == k) cap.axis = a;
    if (cap.axis < 0 || k == 0) return;
    const int a = cap.axis;
    cap.sign = occ.voxel[a] > eye[a] ? 1 : -1;
    cap.fixed = occ.voxel[a];
    const glm::dvec3 d = s.grid.voxelSize();
    cap.plane = s.grid.world.min[a] + double(cap.sign > 0 ? cap.fixed + 1 : cap.fixed) * d[a];
    cap.b = (a + 1) % 3;
    cap.c = (a + 2) % 3;
    const glm::ivec3 res = s.grid.resolution;
    cap.b0 = int(std::max<int64_t>(eye[cap.b] - k, 0));
    cap.c0 = int(std::max<int64_t>(eye[cap.c] - k, 0));
    cap.width = int(std::min<int64_t>(eye[cap.b] + k, res[cap.b] - 1)) - cap.b0 + 1;
    cap.height = int(std::min<int64_t>(eye[cap.c] + k, res[cap.c] - 1)) - cap.c0 + 1;
    if (cap.width <= 0 || cap.height <= 0) return;
    cap.blocking = 0;
    cap.filled.assign(size_t(cap.width) * size_t(cap.height), 0);
    cap.vectorizer.vectorize(cap.width, cap.height, [&](int u, int w) {
        glm::ivec3 v;
        v[a] = cap.fixed;
        v[cap.b] = cap.b0 + u;
        v[cap.c] = cap.c0 + w;
        const bool blocks = rgvcBlocksAtLayer(s, near, v.x, v.y, v.z, k);
        cap.blocking += blocks ? 1 : 0;
        cap.filled[size_t(w) * size_t(cap.width) + size_t(u)] = blocks ? 1 : 0;
        return blocks;
    });
    cap.holes = 0;
    for (const BitmapLoop& loop : cap.vectorizer.loops()) cap.holes += loop.hole ? 1 : 0;
    // The polygon of the occluder's pixel: the smallest outer loop around its centre.
    cap.component = -1;
    const double pu = occ.voxel[cap.b] - cap.b0 + 0.5, pw = occ.voxel[cap.c] - cap.c0 + 0.5;
    int64_t smallest = INT64_MAX;
    const std::vector<BitmapLoop>& loops = cap.vectorizer.loops();
    for (size_t i = 0; i < loops.size(); ++i) {
        if (loops[i].hole) continue;
        const glm::ivec2* p = cap.vectorizer.corners(loops[i]);
        if (!rgvcLoopHolds(p, loops[i].count, pu, pw)) continue;
        const int64_t area = signedDoubleArea(p, loops[i].count);
        if (area < smallest) smallest = area, cap.component = int(i);
    }
    for (size_t i = 0; i < s.direction_cause.size(); ++i)
        if (s.direction_cause[i] == index) cap.cells.push_back(int32_t(i));
    cap.valid = true;
}

void drawRgvcCap3d(const RgvcSnapshot& s, const RgvcViewState& view, const RgvcCap3d& cap,
                   DebugDraw& draw) {
    if (!cap.valid) return;
    const RgvcOccluder3d& occ = s.occluders3d[size_t(cap.occluder)];
    const glm::dvec3 eye = s.viewpoint;
    if (view.shown(RgvcLayer::PickedOccluder)) {
        const Paint paint{rgvcLayerSwatch(RgvcLayer::PickedOccluder), 1.0f};
        const Aabb box = s.grid.voxelBounds(occ.voxel);
        draw.wireBox(box.min, box.max, paint, kHeavyLine);
        const glm::dvec3 d = s.grid.voxelSize();
        draw.wireBox(box.min - d, box.max + d, paint, kFineLine);
        const RgvcDirectionMap* map = s.direction_map;
        if (map && map->resolution() > 0) {
            const size_t r = size_t(map->resolution());
            glm::dvec3 q[4];
            for (const int32_t index : cap.cells) {
                const size_t i = size_t(index) % r, j = (size_t(index) / r) % r,
                             face = size_t(index) / (r * r);
                const DirectionCell cell = map->cell(int(face), int(i), int(j));
                if (cellCorners(cell, eye, cap.axis, cap.plane, q))
                    draw.outlinePolygon(DrawSpace::World, q, 4, paint, kHairline);
            }
        }
    }
    if (!view.shown(RgvcLayer::Polygon)) return;
    const Paint paint{rgvcLayerSwatch(RgvcLayer::Polygon), 1.0f};
    // The shell face's square in the grid, then the cap: its hatch, its loops
    // and the rays of its extrusion.
    const glm::dvec3 square[4] = {cap.world(s, 0, 0), cap.world(s, cap.width, 0),
                                  cap.world(s, cap.width, cap.height), cap.world(s, 0, cap.height)};
    draw.outlinePolygon(DrawSpace::World, square, 4, Paint{Swatch::LineGrey, 1.0f}, kFineLine);
    const BitmapVectorizer& vec = cap.vectorizer;
    for (int w = 0; w < cap.height; ++w)
        for (int u = 0; u < cap.width; ++u) {
            if (((u - w) % kHatchEvery + kHatchEvery) % kHatchEvery != 0) continue;
            if (!cap.filled[size_t(w) * size_t(cap.width) + size_t(u)]) continue;
            draw.line(DrawSpace::World, cap.world(s, u, w), cap.world(s, u + 1, w + 1), paint,
                      kHairline);
        }
    // The extrusion of the occluder's polygon: its outer loop and its holes.
    int corners = 0;
    for (const BitmapLoop& loop : vec.loops())
        corners += loop.outer == cap.component ? loop.count : 0;
    const int every = std::max(1, (corners + kRgvcMaxExtrusionRays - 1) / kRgvcMaxExtrusionRays);
    int n = 0;
    for (const BitmapLoop& loop : vec.loops()) {
        const glm::ivec2* p = vec.corners(loop);
        for (int k = 0; k < loop.count; ++k) {
            const glm::ivec2 a = p[k], b = p[(k + 1) % loop.count];
            draw.line(DrawSpace::World, cap.world(s, a.x, a.y), cap.world(s, b.x, b.y), paint,
                      kHeavyLine);
            if (loop.outer != cap.component || n++ % every != 0) continue;
            const glm::dvec3 corner = cap.world(s, a.x, a.y);
            draw.line(DrawSpace::World, eye, exitPoint(s.grid.world, eye, corner), paint,
                      kHairline);
        }
    }
}

}  // namespace gridcull
