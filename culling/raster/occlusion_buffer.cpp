#include "culling/raster/occlusion_buffer.h"

#include <algorithm>
#include <cassert>
#include <limits>

#include "culling/raster/id_depth_buffer.h"

namespace gridcull {

namespace {

// Bits lo..hi (0..63, lo <= hi) of a word.
uint64_t bitRange(int lo, int hi) {
    const uint64_t upto_hi = hi == 63 ? ~uint64_t(0) : (uint64_t(1) << (hi + 1)) - 1;
    return upto_hi & ~((uint64_t(1) << lo) - 1);
}

}  // namespace

void OcclusionBuffer::resize(int width, int height) {
    assert(width >= 1 && height >= 1);
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    words_per_row_ = (size_t(width) + 63) / 64;
    bits_.assign(words_per_row_ * size_t(height), 0);
}

void OcclusionBuffer::clear() {
    std::fill(bits_.begin(), bits_.end(), 0);
}

void OcclusionBuffer::markDrawn(const IdDepthBuffer& zbuffer, const PixelRect& rect) {
    assert(zbuffer.width() == width_ && zbuffer.height() == height_);
    const PixelRect r = rect.intersect({0, 0, width_ - 1, height_ - 1});
    if (r.empty()) return;
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (int py = r.y0; py <= r.y1; ++py) {
        const double* depth = zbuffer.depthRow(py);
        uint64_t* row = bits_.data() + size_t(py) * words_per_row_;
        // A word at a time, each written once; words already wholly occluded (most,
        // once the near objects are drawn) are skipped without reading depths.
        for (int w = r.x0 >> 6; w <= r.x1 >> 6; ++w) {
            const int lo = std::max(r.x0, w * 64), hi = std::min(r.x1, w * 64 + 63);
            const uint64_t span = bitRange(lo & 63, hi & 63);
            if ((row[w] & span) == span) continue;
            uint64_t word = 0;
            for (int px = lo; px <= hi; ++px) word |= uint64_t(depth[px] < kInf) << (px & 63);
            row[w] |= word;
        }
    }
}

void OcclusionBuffer::markOccluded(const PixelRect& rect) {
    const PixelRect r = rect.intersect({0, 0, width_ - 1, height_ - 1});
    for (int py = r.y0; py <= r.y1; ++py) {
        uint64_t* row = bits_.data() + size_t(py) * words_per_row_;
        for (int w = r.x0 >> 6; w <= r.x1 >> 6; ++w)
            row[w] |= bitRange(w == r.x0 >> 6 ? (r.x0 & 63) : 0, w == r.x1 >> 6 ? (r.x1 & 63) : 63);
    }
}

long long OcclusionBuffer::countFree(const PixelRect& rect) const {
    const PixelRect r = rect.intersect({0, 0, width_ - 1, height_ - 1});
    if (r.empty()) return 0;
    const int w0 = r.x0 >> 6, w1 = r.x1 >> 6;
    long long occluded = 0;
    for (int py = r.y0; py <= r.y1; ++py) {
        const uint64_t* row = bits_.data() + size_t(py) * words_per_row_;
        for (int w = w0; w <= w1; ++w) {
            const int lo = w == w0 ? (r.x0 & 63) : 0;
            const int hi = w == w1 ? (r.x1 & 63) : 63;
            occluded += __builtin_popcountll(row[w] & bitRange(lo, hi));
        }
    }
    return r.area() - occluded;
}

}  // namespace gridcull
