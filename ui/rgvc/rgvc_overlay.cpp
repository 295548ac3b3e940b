#include "ui/rgvc/rgvc_overlay.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "ui/rgvc/rgvc_history.h"

namespace gridcull {

namespace {

constexpr float kThinWidth = kFineLine;    // line of sight
constexpr float kThickWidth = kHeavyLine;  // the seed box, the picked occluder and its polygons
constexpr double kIdMarkFraction = 0.5;    // side of an I mark, in voxels
constexpr int kDashes = 120;               // over the line of sight's length

// Mask values of the traversal: what the voxel's visit looks like.
constexpr uint8_t kMaskNone = 0, kMaskVisited = 1, kMaskCurrent = 2;

// Voxel-corner coordinates to world x-y.
struct VoxelSpace {
    glm::dvec2 origin;
    glm::dvec2 size;
    double x(double vx) const { return origin.x + vx * size.x; }
    double y(double vy) const { return origin.y + vy * size.y; }
};

// A rectangle of voxel space [x0, x1] x [y0, y1] (voxel corner coordinates).
void fillVoxels(DebugDraw& draw, const VoxelSpace& s, double x0, double y0, double x1, double y1,
                Paint paint) {
    draw.fillRect(DrawSpace::World, s.x(x0), s.y(y0), s.x(x1), s.y(y1), paint);
}

void outlineVoxels(DebugDraw& draw, const VoxelSpace& s, double x0, double y0, double x1, double y1,
                   Paint paint) {
    draw.outlineRect(DrawSpace::World, s.x(x0), s.y(y0), s.x(x1), s.y(y1), paint, kThickWidth);
}

// One rectangle per run of voxels for which `on(x, y)` holds, row by row.
template <typename On>
void fillRuns(DebugDraw& draw, const VoxelSpace& s, int width, int height, Paint paint, On&& on) {
    for (int y = 0; y < height; ++y) {
        int x = 0;
        while (x < width) {
            if (!on(x, y)) {
                ++x;
                continue;
            }
            const int start = x;
            while (x < width && on(x, y)) ++x;
            fillVoxels(draw, s, start, y, x, y + 1, paint);
        }
    }
}

void drawTraversal(const RgvcSnapshot& snap, const RgvcViewState& view, int64_t shown,
                   const VoxelSpace& s, DebugDraw& draw, std::vector<uint8_t>& mask) {
    const int w = snap.grid.resolution.x, h = snap.grid.resolution.y;
    mask.assign(size_t(w) * size_t(h), kMaskNone);
    for (const RgvcVisit& v : snap.visits) {
        if (v.layer > shown || v.voxel.x < 0 || v.voxel.y < 0 || v.voxel.x >= w || v.voxel.y >= h)
            continue;
        mask[size_t(v.voxel.y) * size_t(w) + size_t(v.voxel.x)] =
            v.layer == shown ? kMaskCurrent : kMaskVisited;
    }
    const auto maskAt = [&](int x, int y) { return mask[size_t(y) * size_t(w) + size_t(x)]; };
    if (view.shown(RgvcLayer::Visited))
        fillRuns(draw, s, w, h, rgvcLayerPaint(RgvcLayer::Visited),
                 [&](int x, int y) { return maskAt(x, y) == kMaskVisited; });
    if (view.shown(RgvcLayer::CurrentLayer))
        fillRuns(draw, s, w, h, rgvcLayerPaint(RgvcLayer::CurrentLayer),
                 [&](int x, int y) { return maskAt(x, y) == kMaskCurrent; });
}

void drawSeed(const RgvcSnapshot& snap, int64_t shown, const VoxelSpace& s, DebugDraw& draw) {
    for (const RgvcSeed& seed : snap.seeds) {
        if (seed.layer != shown) continue;
        const double x = double(seed.voxel.x), y = double(seed.voxel.y);
        const Paint white = rgvcLayerPaint(RgvcLayer::Seed);
        fillVoxels(draw, s, x, y, x + 1, y + 1, white);
        // A box two voxels out, so the seed is findable when a voxel is 3 pixels.
        outlineVoxels(draw, s, x - 2, y - 2, x + 3, y + 3, white);
    }
}

void drawLineOfSight(const RgvcSnapshot& snap, DebugDraw& draw) {
    const Aabb& w = snap.grid.world;
    const glm::dvec2 extent(w.max.x - w.min.x, w.max.y - w.min.y);
    const double length = std::min(snap.far, 1.5 * glm::length(extent));
    const glm::dvec2 dir = glm::normalize(glm::dvec2(snap.forward.x, snap.forward.y));
    const glm::dvec2 from(snap.viewpoint.x, snap.viewpoint.y);
    const double dash = length / kDashes;
    const Paint paint = rgvcLayerPaint(RgvcLayer::LineOfSight);
    for (int k = 0; k < kDashes; k += 2) {
        const glm::dvec2 a = from + dir * (dash * k), b = from + dir * (dash * (k + 1));
        draw.line(DrawSpace::World, {a.x, a.y, 0.0}, {b.x, b.y, 0.0}, paint, kThinWidth);
    }
}

// The picked extended occluder (a convex L, or a staircase of two Ls): its
// occlusion polygons, then its initial voxel and each extension step's voxels,
// boxed and numbered 1 to 4 in the paper's order (a staircase's step 4 starts at
// the end of step 3, not at the initial voxel).
void drawOccluder(const RgvcSnapshot& snap, const RgvcViewState& view, const VoxelSpace& s,
                  DebugDraw& draw) {
    const RgvcOccluderView& picked = snap.occluders[size_t(view.occluder)];
    const RgvcExtendedOccluder& occ = picked.occluder;
    if (view.shown(RgvcLayer::Polygon)) {
        // Every polygon of every L (up to four for a staircase), each convex; where
        // they overlap (behind an L's corner voxel, behind a staircase's initial
        // voxel) the veils add up.
        const Aabb& w = snap.grid.world;
        const double reach = 2.0 * glm::length(glm::dvec2(w.max.x - w.min.x, w.max.y - w.min.y));
        const Paint fill = rgvcLayerPaint(RgvcLayer::Polygon);
        const Paint edge{fill.swatch, 1.0f};
        for (int p = 0; p < picked.polygon_count; ++p) {
            const RgvcOcclusionPolygon& poly = picked.polygons[size_t(p)];
            if (poly.outline_count < 2) continue;
            // The outline, then out to `reach` along the rays from the apex: a
            // convex polygon, so a fan from its first corner fills it.
            glm::dvec3 corners[5];
            size_t n = 0;
            const glm::dvec2 first = poly.outline[0],
                             last = poly.outline[size_t(poly.outline_count - 1)];
            const auto v3 = [](glm::dvec2 p2) { return glm::dvec3(p2.x, p2.y, 0.0); };
            corners[n++] = v3(first + glm::normalize(first - poly.apex) * reach);
            for (int k = 0; k < poly.outline_count; ++k) corners[n++] = v3(poly.outline[size_t(k)]);
            corners[n++] = v3(last + glm::normalize(last - poly.apex) * reach);
            draw.fillConvexPolygon(DrawSpace::World, corners, n, fill);
            draw.polyline(DrawSpace::World, corners, n, edge, kThickWidth);
        }
    }
    if (view.shown(RgvcLayer::PickedOccluder)) {
        const Paint paint = rgvcLayerPaint(RgvcLayer::PickedOccluder);
        fillVoxels(draw, s, occ.initial.x, occ.initial.y, occ.initial.x + 1, occ.initial.y + 1,
                   Paint{paint.swatch, 0.85f});
        outlineVoxels(draw, s, occ.initial.x - 1, occ.initial.y - 1, occ.initial.x + 2,
                      occ.initial.y + 2, paint);
        for (size_t i = 0; i < occ.steps.size(); ++i) {
            const RgvcExtensionStep& step = occ.steps[i];
            if (!step.run || step.count == 0) continue;
            // The step's voxels, and a box around them from its start.
            for (int k = 1; k <= step.count; ++k) {
                const glm::ivec2 v = step.from + step.direction * k;
                fillVoxels(draw, s, v.x, v.y, v.x + 1, v.y + 1, Paint{paint.swatch, 0.6f});
            }
            // Boxed one voxel out: a one-voxel leg is a few pixels wide at full view.
            const glm::ivec2 a = step.from + step.direction,
                             b = step.from + step.direction * step.count;
            outlineVoxels(draw, s, std::min(a.x, b.x) - 1, std::min(a.y, b.y) - 1,
                          std::max(a.x, b.x) + 2, std::max(a.y, b.y) + 2, paint);
            // Its number in the voxel beyond its last one (the label's top left
            // near that voxel's top left).
            constexpr const char* kStepNames[4] = {"1", "2", "3", "4"};
            const glm::ivec2 c = b + step.direction;
            draw.text(DrawSpace::World, {s.x(c.x + 0.25), s.y(c.y + 0.75), 0.0}, kStepNames[i],
                      paint);
        }
    }
}

}  // namespace

void drawRgvcOverlay(const RgvcSnapshot& snap, const RgvcViewState& view, DebugDraw& draw,
                     std::vector<uint8_t>& scratch) {
    if (!snap.valid || !snap.occluder) return;
    const int w = snap.grid.resolution.x, h = snap.grid.resolution.y;
    const glm::dvec3 size = snap.grid.voxelSize();
    const VoxelSpace s{{snap.grid.world.min.x, snap.grid.world.min.y}, {size.x, size.y}};

    // Back to front: the traversal under the matrices, so O and H read as in the paper.
    const int64_t shown = rgvcShownLayer(snap, view.layer);
    if (shown >= 0) drawTraversal(snap, view, shown, s, draw, scratch);
    // O, H, I and T as they stood after the shown layer (ui/rgvc/rgvc_history.h).
    if (view.shown(RgvcLayer::Occlusion) && snap.occlusion)
        fillRuns(draw, s, w, h, rgvcLayerPaint(RgvcLayer::Occlusion),
                 [&](int x, int y) { return rgvcHAt(snap, x, y, 0, shown); });
    if (view.shown(RgvcLayer::Occluder))
        fillRuns(draw, s, w, h, rgvcLayerPaint(RgvcLayer::Occluder),
                 [&](int x, int y) { return rgvcOAt(snap, x, y, 0, shown); });
    if (view.shown(RgvcLayer::Tbv) && snap.tbvs) {
        fillRuns(draw, s, w, h, rgvcLayerPaint(RgvcLayer::Tbv),
                 [&](int x, int y) { return !snap.tbvs->empty(x, y); });
        // The TBVs the traversal revealed after the layer were still in T.
        for (const RgvcRevealView& r : snap.reveals)
            if (r.layer > shown)
                rgvcForEachTbvVoxel(snap, r.tbv, [&](int x, int y, int) {
                    fillVoxels(draw, s, x, y, x + 1, y + 1, rgvcLayerPaint(RgvcLayer::Tbv));
                });
    }
    if (view.shown(RgvcLayer::Identifiers)) {
        const Paint paint = rgvcLayerPaint(RgvcLayer::Identifiers);
        const double m = 0.5 * (1.0 - kIdMarkFraction);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                bool has = false;
                rgvcForEachIdAt(snap, x, y, 0, shown, [&](int32_t) { has = true; });
                if (has) fillVoxels(draw, s, x + m, y + m, x + 1 - m, y + 1 - m, paint);
            }
    }
    if (shown >= 0 && view.shown(RgvcLayer::Seed)) drawSeed(snap, shown, s, draw);
    if (view.shown(RgvcLayer::LineOfSight)) drawLineOfSight(snap, draw);
    if (view.occluder >= 0 && size_t(view.occluder) < snap.occluders.size())
        drawOccluder(snap, view, s, draw);
}

}  // namespace gridcull
