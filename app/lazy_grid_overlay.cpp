#include "app/lazy_grid_overlay.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace gridcull {

namespace {

constexpr float kThickWidth = 2.0f;
constexpr float kGridAlpha = 0.35f;
constexpr float kTouchedFillAlpha = 0.30f;
// Touched outlines sit this many view pixels inside their cell, inside the
// cell's class outline, so neighbouring cells' outlines stay apart.
constexpr double kTouchedInset = 6.0;
constexpr double kMaxInset = 0.15;
constexpr double kDash = 5.0, kDashGap = 4.0;  // view pixels
constexpr double kCrossInset = 0.28;           // of the cell side, each end
constexpr double kProbabilityMark = 0.2;       // half side of its square, of the cell side
// zfar < zmax cells: the nearest drawn cells the densest, the farthest the faintest.
constexpr float kNearAlpha = 0.36f, kFarAlpha = 0.06f;
// Each cell's class outline, just inside the grid line; touched cells' outlines
// go further in so both show.
constexpr double kClassInset = 2.0;
constexpr float kClassEdgeAlpha = 0.85f;
constexpr float kFreeEdgeAlpha = 0.5f;         // free cells say the least: their outline recedes
constexpr double kThickOutlineMinCell = 40.0;  // view pixels
constexpr double kHatchSpacing = 7.0;          // view pixels
constexpr float kHatchAlpha = 0.45f;

glm::vec3 at(double x, double y) {
    return {float(x), float(y), 0.0f};
}

void appendQuad(std::vector<ColorVertex>& fill, const ViewRect& r, const glm::vec4& color) {
    const glm::vec3 a = at(r.x0, r.y0), b = at(r.x1, r.y0), c = at(r.x1, r.y1), d = at(r.x0, r.y1);
    for (const glm::vec3& p : {a, b, c, a, c, d}) fill.push_back({p, color});
}

void appendLine(std::vector<ColorVertex>& lines, double x0, double y0, double x1, double y1,
                const glm::vec4& color) {
    lines.push_back({at(x0, y0), color});
    lines.push_back({at(x1, y1), color});
}

void appendOutline(std::vector<ColorVertex>& lines, const ViewRect& r, const glm::vec4& color) {
    appendLine(lines, r.x0, r.y0, r.x1, r.y0, color);
    appendLine(lines, r.x1, r.y0, r.x1, r.y1, color);
    appendLine(lines, r.x1, r.y1, r.x0, r.y1, color);
    appendLine(lines, r.x0, r.y1, r.x0, r.y0, color);
}

// One edge as dashes from (x0, y0) to (x1, y1), axis-aligned.
void appendDashes(std::vector<ColorVertex>& lines, double x0, double y0, double x1, double y1,
                  const glm::vec4& color) {
    const double length = std::abs(x1 - x0) + std::abs(y1 - y0);
    if (length <= 0.0) return;
    const double dx = (x1 - x0) / length, dy = (y1 - y0) / length;
    for (double s = 0.0; s < length; s += kDash + kDashGap) {
        const double e = std::min(s + kDash, length);
        appendLine(lines, x0 + dx * s, y0 + dy * s, x0 + dx * e, y0 + dy * e, color);
    }
}

void appendDashedOutline(std::vector<ColorVertex>& lines, const ViewRect& r,
                         const glm::vec4& color) {
    appendDashes(lines, r.x0, r.y0, r.x1, r.y0, color);
    appendDashes(lines, r.x1, r.y0, r.x1, r.y1, color);
    appendDashes(lines, r.x1, r.y1, r.x0, r.y1, color);
    appendDashes(lines, r.x0, r.y1, r.x0, r.y0, color);
}

// `r` shrunk by `by` on each side, but by at most kMaxInset of its side, so small
// cells keep most of their area.
ViewRect inset(const ViewRect& r, double by) {
    const double x = std::min(by, kMaxInset * (r.x1 - r.x0));
    const double y = std::min(by, kMaxInset * (r.y1 - r.y0));
    return {r.x0 + x, r.y0 + y, r.x1 - x, r.y1 - y};
}

// A 1-pixel line on a pixel's centre, so it is one crisp pixel wide; kept
// inside [lo, hi) so the image's last row and column show their border.
double crisp(double v, double lo, double hi) {
    return std::clamp(std::floor(v) + 0.5, std::floor(lo) + 0.5, std::ceil(hi) - 0.5);
}

// Diagonal lines (x + y constant) across `r`, kHatchSpacing apart.
void appendHatch(std::vector<ColorVertex>& lines, const ViewRect& r, const glm::vec4& color) {
    const double w = r.x1 - r.x0, h = r.y1 - r.y0;
    for (double d = kHatchSpacing; d < w + h; d += kHatchSpacing) {
        // From where x + y = x0 + y0 + d enters the rectangle to where it leaves.
        const double xa = r.x0 + std::max(0.0, d - h), xb = r.x0 + std::min(w, d);
        appendLine(lines, xa, r.y0 + d - (xa - r.x0), xb, r.y0 + d - (xb - r.x0), color);
    }
}

void appendCells(const LazyGridSnapshot& s, const ImageFrame& frame, LazyGridOverlayGeometry& out) {
    double z_lo = std::numeric_limits<double>::infinity(), z_hi = -z_lo;
    for (const LazyGridCell& cell : s.cells)
        if (lazyCellClassOf(cell, s.variant) == LazyCellClass::ZfarFinite) {
            z_lo = std::min(z_lo, cell.zfar);
            z_hi = std::max(z_hi, cell.zfar);
        }
    for (int cy = 0; cy < s.cells_y; ++cy)
        for (int cx = 0; cx < s.cells_x; ++cx) {
            const LazyGridCell& cell = s.cells[size_t(cy) * size_t(s.cells_x) + size_t(cx)];
            const LazyCellClass c = lazyCellClassOf(cell, s.variant);
            const Rgb color = lazyCellClassColor(c);
            const bool free = c == LazyCellClass::CompletelyFree || c == LazyCellClass::ZfarAtZmax;
            float alpha = lazyCellClassFillAlpha(c);
            if (c == LazyCellClass::ZfarFinite) {
                const double t = z_hi > z_lo ? (cell.zfar - z_lo) / (z_hi - z_lo) : 0.0;
                alpha = kNearAlpha + float(t) * (kFarAlpha - kNearAlpha);
            }
            const ViewRect r = lazyCellInView(frame, s, cx, cy);
            if (alpha > 0.0f) appendQuad(out.fill, r, toRgba(color, alpha));
            const ViewRect edge = inset(r, kClassInset);
            if (lazyCellClassHatched(c)) appendHatch(out.lines, edge, toRgba(color, kHatchAlpha));
            // Thin outlines on small cells, which would otherwise be mostly outline.
            const bool small = std::min(r.x1 - r.x0, r.y1 - r.y0) < kThickOutlineMinCell;
            appendOutline(small ? out.lines : out.thick_lines, edge,
                          toRgba(color, free ? kFreeEdgeAlpha : kClassEdgeAlpha));
        }
}

void appendGridLines(const LazyGridSnapshot& s, const ImageFrame& frame,
                     LazyGridOverlayGeometry& out) {
    const glm::vec4 color = toRgba(lazyGridLayerColor(LazyGridLayer::GridLines), kGridAlpha);
    const ViewRect& a = frame.area;
    // Every cell boundary, the image's own edges included.
    for (int cx = 0; cx <= s.cells_x; ++cx) {
        const double x = crisp(frame.toView(std::min(cx * s.cell_size, s.width), 0).x, a.x0, a.x1);
        appendLine(out.lines, x, a.y0, x, a.y1, color);
    }
    for (int cy = 0; cy <= s.cells_y; ++cy) {
        const double y = crisp(frame.toView(0, std::min(cy * s.cell_size, s.height)).y, a.y0, a.y1);
        appendLine(out.lines, a.x0, y, a.x1, y, color);
    }
}

// The focused test's cells, merged per cell: a queued cell is touched a second
// time by its pixel query or the probability rule.
void collectTouched(const LazyGridSnapshot& s, const LazyGridTest& test,
                    LazyGridOverlayGeometry& out) {
    out.touched.clear();
    out.slot.assign(s.cells.size(), -1);
    const int32_t end = test.first_touch + test.touch_count;
    for (int32_t k = test.first_touch; k < end; ++k) {
        const CellTouch& touch = s.touches[size_t(k)];
        if (touch.cell < 0 || size_t(touch.cell) >= s.cells.size()) continue;
        int32_t& slot = out.slot[size_t(touch.cell)];
        if (slot < 0) {
            slot = int32_t(out.touched.size());
            out.touched.push_back({touch.cell, touch.role, false, false, false});
        }
        LazyGridOverlayGeometry::Touched& t = out.touched[size_t(slot)];
        t.free |= touch.free;
        t.queried |= touch.kind == CellTouchKind::PixelQuery;
        t.probability |= touch.kind == CellTouchKind::Probability;
    }
}

void appendTouched(const LazyGridSnapshot& s, const LazyGridViewState& view,
                   const ImageFrame& frame, LazyGridOverlayGeometry& out) {
    const glm::vec4 white = toRgba(lazyGridLayerColor(LazyGridLayer::Touched));
    const glm::vec4 free = toRgba(lazyFreeTouchColor());
    const glm::vec4 query = toRgba(lazyGridLayerColor(LazyGridLayer::PixelQueries));
    for (const LazyGridOverlayGeometry::Touched& t : out.touched) {
        const ViewRect cell = lazyCellInView(frame, s, t.cell % s.cells_x, t.cell / s.cells_x);
        const ViewRect r = inset(cell, kTouchedInset);
        const glm::vec4& edge = t.free ? free : white;
        if (view.shown(LazyGridLayer::Touched)) {
            // Filled: internal cells, and the cell found free whatever its role,
            // which is what made the box potentially visible.
            if (t.role == CellRole::Internal || t.free)
                appendQuad(out.fill, r, glm::vec4(glm::vec3(edge), kTouchedFillAlpha));
            if (t.role == CellRole::Internal)
                appendOutline(out.thick_lines, r, edge);
            else
                appendDashedOutline(out.thick_lines, r, edge);
        }
        if (!view.shown(LazyGridLayer::PixelQueries)) continue;
        const double w = cell.x1 - cell.x0, h = cell.y1 - cell.y0;
        if (t.queried) {
            const double ix = kCrossInset * w, iy = kCrossInset * h;
            appendLine(out.thick_lines, cell.x0 + ix, cell.y0 + iy, cell.x1 - ix, cell.y1 - iy,
                       query);
            appendLine(out.thick_lines, cell.x1 - ix, cell.y0 + iy, cell.x0 + ix, cell.y1 - iy,
                       query);
        } else if (t.probability) {
            // Rated free by section 6's threshold: a small box, no pixels read.
            const double cx = 0.5 * (cell.x0 + cell.x1), cy = 0.5 * (cell.y0 + cell.y1);
            const double m = kProbabilityMark * std::min(w, h);
            appendOutline(out.thick_lines, {cx - m, cy - m, cx + m, cy + m}, query);
        }
    }
}

}  // namespace

ViewRect lazyCellInView(const ImageFrame& frame, const LazyGridSnapshot& snapshot, int cx, int cy) {
    const PixelRect p = lazyCellPixels(snapshot, cx, cy);
    return frame.pixelsToView(p.x0, p.y0, p.x1, p.y1);
}

void buildLazyGridOverlay(const LazyGridSnapshot& snapshot, const LazyGridViewState& view,
                          int focus_object, const ImageFrame& frame, LazyGridOverlayGeometry& out) {
    out.fill.clear();
    out.lines.clear();
    out.thick_lines.clear();
    out.touched.clear();
    if (!snapshot.valid || snapshot.cells_x <= 0 || snapshot.cells_y <= 0) return;
    if (view.shown(LazyGridLayer::Cells)) appendCells(snapshot, frame, out);
    if (view.shown(LazyGridLayer::GridLines)) appendGridLines(snapshot, frame, out);
    const LazyGridTest* test = focus_object >= 0 ? decidingTest(snapshot, focus_object) : nullptr;
    if (!test || !test->in_frustum) return;
    collectTouched(snapshot, *test, out);
    appendTouched(snapshot, view, frame, out);
    if (view.shown(LazyGridLayer::ScreenRect) && !test->box.rect.empty()) {
        const PixelRect& p = test->box.rect;
        appendOutline(out.thick_lines, frame.pixelsToView(p.x0, p.y0, p.x1, p.y1),
                      toRgba(lazyGridLayerColor(LazyGridLayer::ScreenRect)));
    }
}

void LazyGridOverlay::draw(const LazyGridSnapshot& snapshot, const LazyGridViewState& view,
                           int focus_object, const ImageFrame& frame, int view_width,
                           int view_height) {
    buildLazyGridOverlay(snapshot, view, focus_object, frame, geometry_);
    // View pixels, origin top left, onto the current viewport.
    const glm::mat4 pixels = glm::ortho(0.0f, float(view_width), float(view_height), 0.0f);
    line_renderer_.draw(geometry_.fill, GL_TRIANGLES, pixels, 1.0f, false);
    line_renderer_.draw(geometry_.lines, GL_LINES, pixels, 1.0f, false);
    line_renderer_.draw(geometry_.thick_lines, GL_LINES, pixels, kThickWidth, false);
}

}  // namespace gridcull
