// The Z-pyramid of Greene, Kass & Miller's hierarchical z-buffer as Sudarsky &
// Gotsman use it ("Dynamic scene occlusion culling", section 2.1.1, Fig. 1, and
// section 4). z_pyramid.h says how the query departs from Greene's descent.
#include "culling/hzb_tbv/z_pyramid.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace gridcull {

namespace {

constexpr double kEmpty = std::numeric_limits<double>::infinity();

double sanitized(double depth) {
    return std::isnan(depth) ? kEmpty : depth;
}

}  // namespace

void ZPyramid::resize(int width, int height) {
    assert(width >= 1 && height >= 1);
    if (width == this->width() && height == this->height()) return;
    levels_.clear();
    size_t total = 0;
    int w = width, h = height;
    for (;;) {
        levels_.push_back({w, h, total});
        total += size_t(w) * size_t(h);
        if (w == 1 && h == 1) break;
        w = (w + 1) / 2;
        h = (h + 1) / 2;
    }
    texels_.assign(total, kEmpty);
}

ZPyramidLevel ZPyramid::level(int l) const {
    assert(l >= 0 && l < levelCount());
    const Level& lv = levels_[size_t(l)];
    return {lv.width, lv.height, texels_.data() + lv.offset};
}

void ZPyramid::build(const IdDepthBuffer& buffer) {
    resize(buffer.width(), buffer.height());
    const int w = buffer.width();
    double* out = texelsOf(0);
    for (int y = 0; y < buffer.height(); ++y) {
        const double* row = buffer.depthRow(y);
        std::transform(row, row + w, out + size_t(y) * size_t(w), sanitized);
    }
    reduceAll();
}

void ZPyramid::build(int width, int height, const double* depths) {
    resize(width, height);
    std::transform(depths, depths + size_t(width) * size_t(height), texelsOf(0), sanitized);
    reduceAll();
}

void ZPyramid::clear() {
    std::fill(texels_.begin(), texels_.end(), kEmpty);
}

void ZPyramid::reduceAll() {
    for (int l = 0; l + 1 < levelCount(); ++l) {
        const Level above = levels_[size_t(l) + 1];
        reduce(l, 0, above.width - 1, 0, above.height - 1);
    }
}

void ZPyramid::reduce(int l, int x0, int x1, int y0, int y1) {
    const Level below = levels_[size_t(l)];
    const Level above = levels_[size_t(l) + 1];
    const double* src = texelsOf(l);
    double* dst = texelsOf(l + 1);
    for (int y = y0; y <= y1; ++y) {
        // At an odd edge the second row (column) is the first again: the
        // texel takes the farthest of the texels that exist, no more.
        const int r0y = 2 * y, r1y = std::min(2 * y + 1, below.height - 1);
        const double* r0 = src + size_t(r0y) * size_t(below.width);
        const double* r1 = src + size_t(r1y) * size_t(below.width);
        double* out = dst + size_t(y) * size_t(above.width);
        for (int x = x0; x <= x1; ++x) {
            const int c0 = 2 * x, c1 = std::min(2 * x + 1, below.width - 1);
            out[x] = std::max(std::max(r0[c0], r0[c1]), std::max(r1[c0], r1[c1]));
        }
    }
}

void ZPyramid::refresh(const IdDepthBuffer& buffer, const ScreenRange& cols,
                       const ScreenRange& rows) {
    assert(buffer.width() == width() && buffer.height() == height());
    const int x0 = std::max(cols.lo, 0), x1 = std::min(cols.hi, width() - 1);
    const int y0 = std::max(rows.lo, 0), y1 = std::min(rows.hi, height() - 1);
    if (x0 > x1 || y0 > y1) return;
    double* level0 = texelsOf(0);
    for (int y = y0; y <= y1; ++y) {
        const double* row = buffer.depthRow(y);
        std::transform(row + x0, row + x1 + 1, level0 + size_t(y) * size_t(width()) + size_t(x0),
                       sanitized);
    }
    for (int l = 0; l + 1 < levelCount(); ++l)
        reduce(l, x0 >> (l + 1), x1 >> (l + 1), y0 >> (l + 1), y1 >> (l + 1));
}

int ZPyramid::queryLevel(const PixelRect& rect) const {
    int l = 0;
    while (l + 1 < levelCount() &&
           ((rect.x1 >> l) - (rect.x0 >> l) > 1 || (rect.y1 >> l) - (rect.y0 >> l) > 1))
        ++l;
    return l;
}

ZQueryResult ZPyramid::query(const PixelRect& rect, double znear) const {
    ZQueryResult result;
    if (levels_.empty()) return result;  // nothing built: visible
    const PixelRect r = rect.intersect({0, 0, width() - 1, height() - 1});
    if (r.empty()) {
        result.may_be_visible = false;  // no pixel of the image can see the box
        return result;
    }
    result.level = queryLevel(r);
    const ZPyramidLevel lv = level(result.level);
    const int l = result.level;
    for (int y = r.y0 >> l; y <= r.y1 >> l; ++y)
        for (int x = r.x0 >> l; x <= r.x1 >> l; ++x) {
            ++result.texels_read;
            if (!(lv.at(x, y) < znear)) return result;  // may be visible
        }
    result.may_be_visible = false;
    return result;
}

ZQueryResult ZPyramid::queryRefined(const PixelRect& rect, double znear, int max_reads) const {
    ZQueryResult result;
    if (levels_.empty()) return result;
    const PixelRect r = rect.intersect({0, 0, width() - 1, height() - 1});
    if (r.empty()) {
        result.may_be_visible = false;
        return result;
    }
    result.level = queryLevel(r);
    // Depth-first over the texels still undecided; each entry's four children
    // go on the stack, so it never holds more than 3 per level plus 4.
    struct Texel {
        int level, x, y;
    };
    constexpr int kStack = 4 + 3 * 32;
    Texel stack[kStack];
    int top = 0;
    const int l0 = result.level;
    for (int y = r.y1 >> l0; y >= r.y0 >> l0; --y)
        for (int x = r.x1 >> l0; x >= r.x0 >> l0; --x) stack[top++] = {l0, x, y};
    while (top > 0) {
        const Texel t = stack[--top];
        if (result.texels_read >= max_reads) return result;  // out of budget: visible
        ++result.texels_read;
        if (level(t.level).at(t.x, t.y) < znear) continue;  // hides its part
        if (t.level == 0) return result;                    // a pixel that may see it
        const int l = t.level - 1;
        const ZPyramidLevel below = level(l);
        for (int dy = 1; dy >= 0; --dy)
            for (int dx = 1; dx >= 0; --dx) {
                const int x = 2 * t.x + dx, y = 2 * t.y + dy;
                if (x >= below.width || y >= below.height) continue;
                // Only the children whose footprint meets the rectangle.
                if ((x + 1) << l <= r.x0 || x << l > r.x1 || (y + 1) << l <= r.y0 || y << l > r.y1)
                    continue;
                stack[top++] = {l, x, y};
            }
    }
    result.may_be_visible = false;
    return result;
}

}  // namespace gridcull
