#include "ui/debug_draw.h"

#include <algorithm>
#include <cmath>

namespace gridcull {

namespace {

glm::vec4 rgba(Paint paint) {
    const Rgb c = swatchColor(paint.swatch);
    return {c.r, c.g, c.b, paint.alpha};
}

glm::dvec3 at(double x, double y) {
    return {x, y, 0.0};
}

// One side as dashes from (x0, y0) to (x1, y1), axis-aligned.
void dashes(DebugDraw& draw, DrawSpace space, double x0, double y0, double x1, double y1,
            Paint paint, float width, double dash, double gap) {
    const double length = std::abs(x1 - x0) + std::abs(y1 - y0);
    if (length <= 0.0 || dash <= 0.0) return;
    const double dx = (x1 - x0) / length, dy = (y1 - y0) / length;
    for (double s = 0.0; s < length; s += dash + gap) {
        const double e = std::min(s + dash, length);
        draw.line(space, at(x0 + dx * s, y0 + dy * s), at(x0 + dx * e, y0 + dy * e), paint, width);
    }
}

}  // namespace

void DebugDraw::quad(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                     const glm::dvec3& d, Paint paint) {
    triangle(space, a, b, c, paint);
    triangle(space, a, c, d, paint);
}

void DebugDraw::fillRect(DrawSpace space, double x0, double y0, double x1, double y1, Paint paint) {
    quad(space, at(x0, y0), at(x1, y0), at(x1, y1), at(x0, y1), paint);
}

void DebugDraw::outlineRect(DrawSpace space, double x0, double y0, double x1, double y1,
                            Paint paint, float width) {
    line(space, at(x0, y0), at(x1, y0), paint, width);
    line(space, at(x1, y0), at(x1, y1), paint, width);
    line(space, at(x1, y1), at(x0, y1), paint, width);
    line(space, at(x0, y1), at(x0, y0), paint, width);
}

void DebugDraw::dashedRect(DrawSpace space, double x0, double y0, double x1, double y1, Paint paint,
                           float width, double dash, double gap) {
    dashes(*this, space, x0, y0, x1, y0, paint, width, dash, gap);
    dashes(*this, space, x1, y0, x1, y1, paint, width, dash, gap);
    dashes(*this, space, x1, y1, x0, y1, paint, width, dash, gap);
    dashes(*this, space, x0, y1, x0, y0, paint, width, dash, gap);
}

void DebugDraw::wireBox(const glm::dvec3& lo, const glm::dvec3& hi, Paint paint, float width) {
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (int k = 0; k < 4; ++k) {
            glm::dvec3 p = lo;
            p[b] = (k & 1) ? hi[b] : lo[b];
            p[c] = (k & 2) ? hi[c] : lo[c];
            glm::dvec3 q = p;
            q[a] = hi[a];
            line(DrawSpace::World, p, q, paint, width);
        }
    }
}

void DebugDraw::hatchRect(DrawSpace space, double x0, double y0, double x1, double y1, Paint paint,
                          float width, double spacing) {
    const double w = x1 - x0, h = y1 - y0;
    if (spacing <= 0.0) return;
    for (double d = spacing; d < w + h; d += spacing) {
        // From where x + y = x0 + y0 + d enters the rectangle to where it leaves.
        const double xa = x0 + std::max(0.0, d - h), xb = x0 + std::min(w, d);
        line(space, at(xa, y0 + d - (xa - x0)), at(xb, y0 + d - (xb - x0)), paint, width);
    }
}

void DebugDraw::fillConvexPolygon(DrawSpace space, const glm::dvec3* points, size_t count,
                                  Paint paint) {
    for (size_t k = 1; k + 1 < count; ++k)
        triangle(space, points[0], points[k], points[k + 1], paint);
}

void DebugDraw::polyline(DrawSpace space, const glm::dvec3* points, size_t count, Paint paint,
                         float width) {
    for (size_t k = 0; k + 1 < count; ++k) line(space, points[k], points[k + 1], paint, width);
}

void DebugDraw::outlinePolygon(DrawSpace space, const glm::dvec3* points, size_t count, Paint paint,
                               float width) {
    polyline(space, points, count, paint, width);
    if (count > 2) line(space, points[count - 1], points[0], paint, width);
}

void DebugDraw::fillVoxel(const RegularGrid& grid, int x, int y, Paint paint) {
    const glm::dvec3 size = grid.voxelSize();
    const double x0 = grid.world.min.x + x * size.x, y0 = grid.world.min.y + y * size.y;
    fillRect(DrawSpace::World, x0, y0, x0 + size.x, y0 + size.y, paint);
}

void DebugDrawBatch::clear() {
    for (Layer& layer : layers_) {
        layer.fill.clear();
        for (LineSet& set : layer.lines) set.vertices.clear();
        layer.labels.clear();
    }
    texts_.clear();
}

bool DebugDrawBatch::empty() const {
    for (const Layer& layer : layers_) {
        if (!layer.fill.empty() || !layer.labels.empty()) return false;
        for (const LineSet& set : layer.lines)
            if (!set.vertices.empty()) return false;
    }
    return true;
}

void DebugDrawBatch::triangle(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b,
                              const glm::dvec3& c, Paint paint) {
    std::vector<Vertex>& fill = layers_[int(space)].fill;
    const glm::vec4 color = rgba(paint);
    for (const glm::dvec3* p : {&a, &b, &c}) fill.push_back({glm::vec3(*p), color});
}

void DebugDrawBatch::line(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, Paint paint,
                          float width) {
    std::vector<LineSet>& sets = layers_[int(space)].lines;
    auto found = std::lower_bound(sets.begin(), sets.end(), width,
                                  [](const LineSet& s, float w) { return s.width < w; });
    if (found == sets.end() || found->width != width) {
        // A new width: rare (a handful per overlay), and kept for later frames.
        found = sets.insert(found, LineSet{width, {}});
    }
    const glm::vec4 color = rgba(paint);
    found->vertices.push_back({glm::vec3(a), color});
    found->vertices.push_back({glm::vec3(b), color});
}

void DebugDrawBatch::text(DrawSpace space, const glm::dvec3& at, const char* text, Paint paint,
                          float scale) {
    Label label;
    label.at = at;
    label.paint = paint;
    label.scale = scale;
    label.text_begin = texts_.size();
    texts_ += text;
    label.text_end = texts_.size();
    layers_[int(space)].labels.push_back(label);
}

}  // namespace gridcull
