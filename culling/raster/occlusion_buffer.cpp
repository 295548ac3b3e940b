#include "culling/raster/occlusion_buffer.h"

#include <algorithm>
#include <cassert>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "culling/raster/id_depth_buffer.h"

namespace gridcull {

namespace {

// Bits lo..hi (0..63, lo <= hi) of a word.
uint64_t bitRange(int lo, int hi) {
    const uint64_t upto_hi = hi == 63 ? ~uint64_t(0) : (uint64_t(1) << (hi + 1)) - 1;
    return upto_hi & ~((uint64_t(1) << lo) - 1);
}

// The bits of one word for pixels lo..hi (in the same word): set where something
// was drawn, a finite depth. SSE2 (every x86-64 CPU) compares two depths at a
// time and gives their bits at once; a whole word is 32 such steps.
uint64_t drawnBits(const double* depth, int lo, int hi) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    uint64_t word = 0;
    int px = lo;
#if defined(__SSE2__)
    const __m128d inf = _mm_set1_pd(kInf);
    for (; px < hi; px += 2) {
        const int pair = _mm_movemask_pd(_mm_cmplt_pd(_mm_loadu_pd(depth + px), inf));
        word |= uint64_t(pair) << (px & 63);
    }
#endif
    for (; px <= hi; ++px) word |= uint64_t(depth[px] < kInf) << (px & 63);
    return word;
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
    for (int py = r.y0; py <= r.y1; ++py) {
        const double* depth = zbuffer.depthRow(py);
        uint64_t* row = bits_.data() + size_t(py) * words_per_row_;
        // A word at a time, each written once; words already wholly occluded (most,
        // once the near objects are drawn) are skipped without reading depths.
        for (int w = r.x0 >> 6; w <= r.x1 >> 6; ++w) {
            const int lo = std::max(r.x0, w * 64), hi = std::min(r.x1, w * 64 + 63);
            const uint64_t span = bitRange(lo & 63, hi & 63);
            if ((row[w] & span) == span) continue;
            row[w] |= drawnBits(depth, lo, hi);
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

namespace {

// The occluded pixels of rows [y0, y1], words [w0, w1], with the first and last
// word masked. The build has no -march flag, so __builtin_popcountll is a call
// into libgcc's __popcountdi2 per word (about 3x slower per 32 x 32 query
// than the POPCNT instruction; docs/results/ has the figures). The
// same loop is compiled twice: with POPCNT enabled for this function alone,
// taken when the CPU has the instruction (checked once), and with a branch-free
// SWAR count for any other x86-64.
struct WordSpan {
    const uint64_t* bits;
    size_t words_per_row;
    int y0, y1, w0, w1;
    uint64_t first_mask, last_mask;
};

inline int popcountSwar(uint64_t x) {
    x = x - ((x >> 1) & 0x5555555555555555ULL);
    x = (x & 0x3333333333333333ULL) + ((x >> 2) & 0x3333333333333333ULL);
    x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fULL;
    return int((x * 0x0101010101010101ULL) >> 56);
}

template <typename Count>
inline long long countOccluded(const WordSpan& s, Count count) {
    long long occluded = 0;
    for (int py = s.y0; py <= s.y1; ++py) {
        const uint64_t* row = s.bits + size_t(py) * s.words_per_row;
        if (s.w0 == s.w1) {
            occluded += count(row[s.w0] & s.first_mask & s.last_mask);
            continue;
        }
        occluded += count(row[s.w0] & s.first_mask);
        for (int w = s.w0 + 1; w < s.w1; ++w) occluded += count(row[w]);
        occluded += count(row[s.w1] & s.last_mask);
    }
    return occluded;
}

long long countOccludedSwar(const WordSpan& s) {
    return countOccluded(s, popcountSwar);
}

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
__attribute__((target("popcnt"))) long long countOccludedPopcnt(const WordSpan& s) {
    return countOccluded(s, [](uint64_t x) { return __builtin_popcountll(x); });
}
bool cpuHasPopcnt() {
    __builtin_cpu_init();  // may run before libgcc's constructor has
    return __builtin_cpu_supports("popcnt");
}
long long countOccludedFast(const WordSpan& s) {
    static const bool has_popcnt = cpuHasPopcnt();
    return has_popcnt ? countOccludedPopcnt(s) : countOccludedSwar(s);
}
#else
long long countOccludedFast(const WordSpan& s) {
    return countOccluded(s, [](uint64_t x) { return __builtin_popcountll(x); });
}
#endif

// The words of rectangle `r` (inside the buffer, not empty).
WordSpan spanOf(const uint64_t* bits, size_t words_per_row, const PixelRect& r) {
    return {bits,      words_per_row,          r.y0, r.y1, r.x0 >> 6,
            r.x1 >> 6, bitRange(r.x0 & 63, 63), bitRange(0, r.x1 & 63)};
}

}  // namespace

long long OcclusionBuffer::countFree(const PixelRect& rect) const {
    const PixelRect r = rect.intersect({0, 0, width_ - 1, height_ - 1});
    if (r.empty()) return 0;
    return r.area() - countOccludedFast(spanOf(bits_.data(), words_per_row_, r));
}

long long OcclusionBuffer::countFreeSwar(const PixelRect& rect) const {
    const PixelRect r = rect.intersect({0, 0, width_ - 1, height_ - 1});
    if (r.empty()) return 0;
    return r.area() - countOccludedSwar(spanOf(bits_.data(), words_per_row_, r));
}

}  // namespace gridcull
