#include "app/rgvc_overlay.h"

#include <algorithm>
#include <cmath>

namespace gridcull {

namespace {

constexpr float kThickWidth = 3.0f;
constexpr double kIdMarkFraction = 0.5;  // side of an I mark, in voxels
constexpr int kDashes = 120;             // over the line of sight's length

// Mask values of the traversal: what the voxel's visit looks like.
constexpr uint8_t kMaskNone = 0, kMaskVisited = 1, kMaskCurrent = 2;

glm::vec4 layerColor(RgvcLayer layer) {
    return toRgba(rgvcLayerColor(layer), rgvcLayerAlpha(layer));
}

struct VoxelSpace {
    glm::dvec2 origin;
    glm::dvec2 size;
    glm::vec3 at(double x, double y) const {
        return glm::vec3(float(origin.x + x * size.x), float(origin.y + y * size.y), 0.0f);
    }
};

// A rectangle of voxel space [x0, x1] x [y0, y1] (voxel corner coordinates).
void appendQuad(std::vector<ColorVertex>& fill, const VoxelSpace& s, double x0, double y0,
                double x1, double y1, const glm::vec4& color) {
    const glm::vec3 a = s.at(x0, y0), b = s.at(x1, y0), c = s.at(x1, y1), d = s.at(x0, y1);
    for (const glm::vec3& p : {a, b, c, a, c, d}) fill.push_back({p, color});
}

void appendRect(std::vector<ColorVertex>& lines, const VoxelSpace& s, double x0, double y0,
                double x1, double y1, const glm::vec4& color) {
    const glm::vec3 p[4] = {s.at(x0, y0), s.at(x1, y0), s.at(x1, y1), s.at(x0, y1)};
    for (int k = 0; k < 4; ++k) {
        lines.push_back({p[k], color});
        lines.push_back({p[(k + 1) % 4], color});
    }
}

// One quad per run of voxels for which `on(x, y)` holds, row by row.
template <typename On>
void appendRuns(std::vector<ColorVertex>& fill, const VoxelSpace& s, int width, int height,
                const glm::vec4& color, On&& on) {
    for (int y = 0; y < height; ++y) {
        int x = 0;
        while (x < width) {
            if (!on(x, y)) {
                ++x;
                continue;
            }
            const int start = x;
            while (x < width && on(x, y)) ++x;
            appendQuad(fill, s, start, y, x, y + 1, color);
        }
    }
}

void appendTraversal(const RgvcSnapshot& snap, const RgvcViewState& view, int64_t shown,
                     const VoxelSpace& s, RgvcOverlayGeometry& out) {
    const int w = snap.grid.resolution.x, h = snap.grid.resolution.y;
    out.mask.assign(size_t(w) * size_t(h), kMaskNone);
    for (const RgvcVisit& v : snap.visits) {
        if (v.layer > shown || v.voxel.x < 0 || v.voxel.y < 0 || v.voxel.x >= w || v.voxel.y >= h)
            continue;
        out.mask[size_t(v.voxel.y) * size_t(w) + size_t(v.voxel.x)] =
            v.layer == shown ? kMaskCurrent : kMaskVisited;
    }
    const auto maskAt = [&](int x, int y) { return out.mask[size_t(y) * size_t(w) + size_t(x)]; };
    if (view.shown(RgvcLayer::Visited))
        appendRuns(out.fill, s, w, h, layerColor(RgvcLayer::Visited),
                   [&](int x, int y) { return maskAt(x, y) == kMaskVisited; });
    if (view.shown(RgvcLayer::CurrentLayer))
        appendRuns(out.fill, s, w, h, layerColor(RgvcLayer::CurrentLayer),
                   [&](int x, int y) { return maskAt(x, y) == kMaskCurrent; });
}

void appendSeed(const RgvcSnapshot& snap, int64_t shown, const VoxelSpace& s,
                RgvcOverlayGeometry& out) {
    for (const RgvcSeed& seed : snap.seeds) {
        if (seed.layer != shown) continue;
        const double x = double(seed.voxel.x), y = double(seed.voxel.y);
        const glm::vec4 white = layerColor(RgvcLayer::Seed);
        appendQuad(out.fill, s, x, y, x + 1, y + 1, white);
        // A box two voxels out, so the seed is findable when a voxel is 3 pixels.
        appendRect(out.thick_lines, s, x - 2, y - 2, x + 3, y + 3, white);
    }
}

void appendLineOfSight(const RgvcSnapshot& snap, RgvcOverlayGeometry& out) {
    const Aabb& w = snap.grid.world;
    const glm::dvec2 extent(w.max.x - w.min.x, w.max.y - w.min.y);
    const double length = std::min(snap.far, 1.5 * glm::length(extent));
    const glm::dvec2 dir = glm::normalize(glm::dvec2(snap.forward.x, snap.forward.y));
    const glm::dvec2 from(snap.viewpoint.x, snap.viewpoint.y);
    const double dash = length / kDashes;
    const glm::vec4 color = layerColor(RgvcLayer::LineOfSight);
    for (int k = 0; k < kDashes; k += 2) {
        const glm::dvec2 a = from + dir * (dash * k), b = from + dir * (dash * (k + 1));
        out.lines.push_back({glm::vec3(float(a.x), float(a.y), 0.0f), color});
        out.lines.push_back({glm::vec3(float(b.x), float(b.y), 0.0f), color});
    }
}

void appendOccluder(const RgvcSnapshot& snap, const RgvcViewState& view, const VoxelSpace& s,
                    RgvcOverlayGeometry& out) {
    const RgvcOccluderView& picked = snap.occluders[size_t(view.occluder)];
    const RgvcExtendedOccluder& occ = picked.occluder;
    if (view.shown(RgvcLayer::Polygon)) {
        const Aabb& w = snap.grid.world;
        const double reach = 2.0 * glm::length(glm::dvec2(w.max.x - w.min.x, w.max.y - w.min.y));
        const glm::vec4 fill = layerColor(RgvcLayer::Polygon);
        const glm::vec4 edge = toRgba(rgvcLayerColor(RgvcLayer::Polygon));
        for (int p = 0; p < picked.polygon_count; ++p) {
            const RgvcOcclusionPolygon& poly = picked.polygons[size_t(p)];
            if (poly.outline_count < 2) continue;
            // The outline, then out to `reach` along the rays from the apex: a
            // convex polygon, so a fan from its first corner fills it.
            glm::dvec2 corners[5];
            int n = 0;
            const glm::dvec2 first = poly.outline[0],
                             last = poly.outline[size_t(poly.outline_count - 1)];
            corners[n++] = first + glm::normalize(first - poly.apex) * reach;
            for (int k = 0; k < poly.outline_count; ++k) corners[n++] = poly.outline[size_t(k)];
            corners[n++] = last + glm::normalize(last - poly.apex) * reach;
            const auto v3 = [](glm::dvec2 p2) { return glm::vec3(float(p2.x), float(p2.y), 0.0f); };
            for (int k = 1; k + 1 < n; ++k)
                for (const glm::dvec2& c : {corners[0], corners[k], corners[k + 1]})
                    out.fill.push_back({v3(c), fill});
            for (int k = 0; k + 1 < n; ++k) {
                out.thick_lines.push_back({v3(corners[k]), edge});
                out.thick_lines.push_back({v3(corners[k + 1]), edge});
            }
        }
    }
    if (view.shown(RgvcLayer::PickedOccluder)) {
        const glm::vec4 color = layerColor(RgvcLayer::PickedOccluder);
        const glm::vec4 solid(glm::vec3(color), 0.85f);
        appendQuad(out.fill, s, occ.initial.x, occ.initial.y, occ.initial.x + 1, occ.initial.y + 1,
                   solid);
        appendRect(out.thick_lines, s, occ.initial.x - 1, occ.initial.y - 1, occ.initial.x + 2,
                   occ.initial.y + 2, color);
        for (const RgvcExtensionStep& step : occ.steps) {
            if (!step.run || step.count == 0) continue;
            // The step's voxels, and a line through their centres from its start.
            for (int k = 1; k <= step.count; ++k) {
                const glm::ivec2 v = step.from + step.direction * k;
                appendQuad(out.fill, s, v.x, v.y, v.x + 1, v.y + 1,
                           glm::vec4(glm::vec3(color), 0.6f));
            }
            // Boxed one voxel out: a one-voxel leg is a few pixels wide at full view.
            const glm::ivec2 a = step.from + step.direction,
                             b = step.from + step.direction * step.count;
            appendRect(out.thick_lines, s, std::min(a.x, b.x) - 1, std::min(a.y, b.y) - 1,
                       std::max(a.x, b.x) + 2, std::max(a.y, b.y) + 2, color);
        }
    }
}

}  // namespace

void buildRgvcOverlay(const RgvcSnapshot& snap, const RgvcViewState& view,
                      RgvcOverlayGeometry& out) {
    out.fill.clear();
    out.lines.clear();
    out.thick_lines.clear();
    if (!snap.valid || !snap.occluder) return;
    const int w = snap.grid.resolution.x, h = snap.grid.resolution.y;
    const glm::dvec3 size = snap.grid.voxelSize();
    const VoxelSpace s{{snap.grid.world.min.x, snap.grid.world.min.y}, {size.x, size.y}};

    // Back to front: the traversal under the matrices, so O and H read as in the paper.
    const int64_t shown = rgvcShownLayer(snap, view.layer);
    if (shown >= 0) appendTraversal(snap, view, shown, s, out);
    if (view.shown(RgvcLayer::Occlusion) && snap.occlusion)
        appendRuns(out.fill, s, w, h, layerColor(RgvcLayer::Occlusion),
                   [&](int x, int y) { return snap.occlusion->get(x, y); });
    if (view.shown(RgvcLayer::Occluder))
        appendRuns(out.fill, s, w, h, layerColor(RgvcLayer::Occluder),
                   [&](int x, int y) { return snap.occluder->get(x, y); });
    if (view.shown(RgvcLayer::Tbv) && snap.tbvs)
        appendRuns(out.fill, s, w, h, layerColor(RgvcLayer::Tbv),
                   [&](int x, int y) { return !snap.tbvs->empty(x, y); });
    if (view.shown(RgvcLayer::Identifiers)) {
        const glm::vec4 color = layerColor(RgvcLayer::Identifiers);
        const double m = 0.5 * (1.0 - kIdMarkFraction);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const bool has =
                    (snap.identifiers_static && !snap.identifiers_static->empty(x, y)) ||
                    (snap.identifiers_dynamic && !snap.identifiers_dynamic->empty(x, y));
                if (has) appendQuad(out.fill, s, x + m, y + m, x + 1 - m, y + 1 - m, color);
            }
    }
    if (shown >= 0 && view.shown(RgvcLayer::Seed)) appendSeed(snap, shown, s, out);
    if (view.shown(RgvcLayer::LineOfSight)) appendLineOfSight(snap, out);
    if (view.occluder >= 0 && size_t(view.occluder) < snap.occluders.size())
        appendOccluder(snap, view, s, out);
}

void RgvcOverlay::draw(const RgvcSnapshot& snapshot, const RgvcViewState& view,
                       const glm::mat4& view_projection) {
    buildRgvcOverlay(snapshot, view, geometry_);
    if (!geometry_.fill.empty())
        line_renderer_.draw(geometry_.fill, GL_TRIANGLES, view_projection, 1.0f, false);
    if (!geometry_.lines.empty())
        line_renderer_.draw(geometry_.lines, GL_LINES, view_projection, 1.5f, false);
    if (!geometry_.thick_lines.empty())
        line_renderer_.draw(geometry_.thick_lines, GL_LINES, view_projection, kThickWidth, false);
}

}  // namespace gridcull
