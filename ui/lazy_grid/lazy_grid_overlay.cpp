#include "ui/lazy_grid/lazy_grid_overlay.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcull {

namespace {

constexpr float kThinWidth = kHairline;
constexpr float kThickWidth = kBoldLine;
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

constexpr DrawSpace kView = DrawSpace::View;

void line(DebugDraw& draw, double x0, double y0, double x1, double y1, Paint paint, float width) {
    draw.line(kView, {x0, y0, 0.0}, {x1, y1, 0.0}, paint, width);
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

void drawCells(const LazyGridSnapshot& s, const ImageFrame& frame, DebugDraw& draw) {
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
            float alpha = lazyCellClassFillAlpha(c);
            if (c == LazyCellClass::ZfarFinite) {
                const double t = z_hi > z_lo ? (cell.zfar - z_lo) / (z_hi - z_lo) : 0.0;
                alpha = kNearAlpha + float(t) * (kFarAlpha - kNearAlpha);
            }
            drawLazyCell(c, alpha, lazyCellInView(frame, s, cx, cy), draw);
        }
}

void drawGridLines(const LazyGridSnapshot& s, const ImageFrame& frame, DebugDraw& draw) {
    const Paint paint{lazyGridLayerSwatch(LazyGridLayer::GridLines), kGridAlpha};
    const ViewRect& a = frame.area;
    // Every cell boundary, the image's own edges included.
    for (int cx = 0; cx <= s.cells_x; ++cx) {
        const double x = crisp(frame.toView(std::min(cx * s.cell_size, s.width), 0).x, a.x0, a.x1);
        line(draw, x, a.y0, x, a.y1, paint, kThinWidth);
    }
    for (int cy = 0; cy <= s.cells_y; ++cy) {
        const double y = crisp(frame.toView(0, std::min(cy * s.cell_size, s.height)).y, a.y0, a.y1);
        line(draw, a.x0, y, a.x1, y, paint, kThinWidth);
    }
}

// The focused test's cells, merged per cell: a queued cell is touched a second
// time by its pixel query or the probability rule.
void collectTouched(const LazyGridSnapshot& s, const LazyGridTest& test,
                    LazyGridOverlayScratch& out) {
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
        LazyGridOverlayScratch::Touched& t = out.touched[size_t(slot)];
        t.free |= touch.free;
        t.queried |= touch.kind == CellTouchKind::PixelQuery;
        t.probability |= touch.kind == CellTouchKind::Probability;
    }
}

void drawTouched(const LazyGridSnapshot& s, const LazyGridViewState& view, const ImageFrame& frame,
                 const LazyGridOverlayScratch& scratch, DebugDraw& draw) {
    const Paint white{lazyGridLayerSwatch(LazyGridLayer::Touched)};
    const Paint free{lazyFreeTouchSwatch()};
    const Paint query{lazyGridLayerSwatch(LazyGridLayer::PixelQueries)};
    for (const LazyGridOverlayScratch::Touched& t : scratch.touched) {
        const ViewRect cell = lazyCellInView(frame, s, t.cell % s.cells_x, t.cell / s.cells_x);
        const ViewRect r = inset(cell, kTouchedInset);
        const Paint edge = t.free ? free : white;
        if (view.shown(LazyGridLayer::Touched)) {
            // Filled: internal cells, and the cell found free whatever its role,
            // which is what made the box potentially visible.
            if (t.role == CellRole::Internal || t.free)
                draw.fillRect(r, {edge.swatch, kTouchedFillAlpha});
            if (t.role == CellRole::Internal)
                draw.outlineRect(r, edge, kThickWidth);
            else
                draw.dashedRect(kView, r.x0, r.y0, r.x1, r.y1, edge, kThickWidth, kDash, kDashGap);
        }
        if (!view.shown(LazyGridLayer::PixelQueries)) continue;
        const double w = cell.x1 - cell.x0, h = cell.y1 - cell.y0;
        if (t.queried) {
            const double ix = kCrossInset * w, iy = kCrossInset * h;
            line(draw, cell.x0 + ix, cell.y0 + iy, cell.x1 - ix, cell.y1 - iy, query, kThickWidth);
            line(draw, cell.x1 - ix, cell.y0 + iy, cell.x0 + ix, cell.y1 - iy, query, kThickWidth);
        } else if (t.probability) {
            // Rated free by section 6's threshold: a small box, no pixels read.
            const double cx = 0.5 * (cell.x0 + cell.x1), cy = 0.5 * (cell.y0 + cell.y1);
            const double m = kProbabilityMark * std::min(w, h);
            draw.outlineRect({cx - m, cy - m, cx + m, cy + m}, query, kThickWidth);
        }
    }
}

}  // namespace

void drawLazyCell(LazyCellClass c, float fill_alpha, const ViewRect& r, DebugDraw& draw) {
    const Swatch swatch = lazyCellClassSwatch(c);
    const bool free = c == LazyCellClass::CompletelyFree || c == LazyCellClass::ZfarAtZmax;
    if (fill_alpha > 0.0f) draw.fillRect(r, {swatch, fill_alpha});
    const ViewRect edge = inset(r, kClassInset);
    if (lazyCellClassHatched(c))
        draw.hatchRect(kView, edge.x0, edge.y0, edge.x1, edge.y1, {swatch, kHatchAlpha}, kThinWidth,
                       kHatchSpacing);
    // Thin outlines on small cells, which would otherwise be mostly outline.
    const bool small = std::min(r.x1 - r.x0, r.y1 - r.y0) < kThickOutlineMinCell;
    draw.outlineRect(edge, {swatch, free ? kFreeEdgeAlpha : kClassEdgeAlpha},
                     small ? kThinWidth : kThickWidth);
}

float lazyCellLegendAlpha(LazyCellClass c) {
    return c == LazyCellClass::ZfarFinite ? kNearAlpha : lazyCellClassFillAlpha(c);
}

ViewRect lazyCellInView(const ImageFrame& frame, const LazyGridSnapshot& snapshot, int cx, int cy) {
    return frame.pixelsToView(lazyCellPixels(snapshot, cx, cy));
}

void drawLazyGridOverlay(const LazyGridSnapshot& snapshot, const LazyGridViewState& view,
                         int focus_object, const ImageFrame& frame, DebugDraw& draw,
                         LazyGridOverlayScratch& scratch) {
    scratch.touched.clear();
    if (!snapshot.valid || snapshot.cells_x <= 0 || snapshot.cells_y <= 0) return;
    if (view.shown(LazyGridLayer::Cells)) drawCells(snapshot, frame, draw);
    if (view.shown(LazyGridLayer::GridLines)) drawGridLines(snapshot, frame, draw);
    const LazyGridTest* test = focus_object >= 0 ? decidingTest(snapshot, focus_object) : nullptr;
    if (!test || !test->in_frustum) return;
    collectTouched(snapshot, *test, scratch);
    drawTouched(snapshot, view, frame, scratch, draw);
    if (view.shown(LazyGridLayer::ScreenRect) && !test->box.rect.empty())
        draw.outlineRect(frame.pixelsToView(test->box.rect),
                         {lazyGridLayerSwatch(LazyGridLayer::ScreenRect)}, kThickWidth);
}

}  // namespace gridcull
