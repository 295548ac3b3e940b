// A run of one row of pixels against a box under a level camera, the inner loop
// of the shared rasterizer's boxes (id_depth_buffer.h, forBoxHits). Under a
// level camera a pixel's slab interval is its row's [row_lo, row_hi] cut by its
// column's [col_lo[px], col_hi[px]], so a run needs no division and no per-pixel
// direction: only the interval, the entry depth and the depth test.
//
// Which pixels of a building's row are nearer than what is stored is what the
// CPU cannot predict, so a run is written without branches: two pixels at a time
// with SSE2 (every x86-64 CPU has it), one at a time elsewhere. Both give the
// same answer and the same depth as lineBox + solidEntry, bit for bit
// (tests/culling/raster/level_box_run_test.cpp compares them on random runs).
#pragma once
#include <algorithm>
#include <climits>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace gridcull {

// The box and the frame, shared by every pixel of a run.
struct LevelBoxRow {
    double row_lo, row_hi;          // the row axes' slab interval
    const double* col_lo;           // per column: the column axes' slab interval
    const double* col_hi;
    double near, far;               // the camera's depth range
    double z_min;                   // the box's least depth: pixels at or nearer are kept
};

// Where a pixel's ray enters the box: solidEntry of the cut interval, with the
// same comparisons and the same max, combined with & and ?: only.
inline bool levelBoxEntry(double row_lo, double row_hi, double col_lo, double col_hi, double near,
                          double far, double& s) {
    const double lo = std::max(row_lo, col_lo), hi = std::min(row_hi, col_hi);
    const bool eye_inside = (lo <= 0.0) & (hi >= 0.0);
    const double entry = std::max(lo, near);
    s = eye_inside ? near : entry;
    return (lo <= hi) & (eye_inside | ((hi >= near) & (entry <= far)));
}

// Would the box win pixel px of a row holding `depth`? s is its depth there.
inline bool levelBoxWins(const LevelBoxRow& r, int px, double depth, double& s) {
    const bool hit = levelBoxEntry(r.row_lo, r.row_hi, r.col_lo[px], r.col_hi[px], r.near, r.far, s);
    return hit & (depth > r.z_min) & (s < depth);
}

// The columns a run wrote: [lo, hi], empty (hi < 0) when none.
struct WrittenSpan {
    int lo = INT_MAX;
    int hi = -1;
};

// Depth-tests pixels [lo, hi] of a row: each the box wins gets the box's depth,
// and `index` in id_row when id_row is not null.
inline WrittenSpan writeLevelBoxRunScalar(const LevelBoxRow& r, int lo, int hi, double* depth_row,
                                          int32_t* id_row, int index) {
    WrittenSpan written;
    for (int px = lo; px <= hi; ++px) {
        double s;
        const double old = depth_row[px];
        const bool win = levelBoxWins(r, px, old, s);
        depth_row[px] = win ? s : old;
        if (id_row) id_row[px] = win ? index : id_row[px];
        written.lo = std::min(written.lo, win ? px : INT_MAX);
        written.hi = win ? px : written.hi;
    }
    return written;
}

#if defined(__SSE2__)
// Two pixels at a time. SSE2's max(a, b) is a > b ? a : b where std::max(a, b)
// is a < b ? b : a (min likewise), so each is called with std::max's operands
// swapped: the same function, ties and signed zeros included.
inline WrittenSpan writeLevelBoxRun(const LevelBoxRow& r, int lo, int hi, double* depth_row,
                                    int32_t* id_row, int index) {
    const __m128d row_lo = _mm_set1_pd(r.row_lo), row_hi = _mm_set1_pd(r.row_hi);
    const __m128d near = _mm_set1_pd(r.near), far = _mm_set1_pd(r.far);
    const __m128d z_min = _mm_set1_pd(r.z_min), zero = _mm_setzero_pd();
    WrittenSpan written;
    int px = lo;
    for (; px < hi; px += 2) {
        const __m128d cut_lo = _mm_max_pd(_mm_loadu_pd(r.col_lo + px), row_lo);
        const __m128d cut_hi = _mm_min_pd(_mm_loadu_pd(r.col_hi + px), row_hi);
        const __m128d eye_inside = _mm_and_pd(_mm_cmple_pd(cut_lo, zero), _mm_cmpge_pd(cut_hi, zero));
        const __m128d entry = _mm_max_pd(near, cut_lo);
        const __m128d s = _mm_or_pd(_mm_and_pd(eye_inside, near), _mm_andnot_pd(eye_inside, entry));
        const __m128d in_range = _mm_and_pd(_mm_cmpge_pd(cut_hi, near), _mm_cmple_pd(entry, far));
        const __m128d hit = _mm_and_pd(_mm_cmple_pd(cut_lo, cut_hi), _mm_or_pd(eye_inside, in_range));
        const __m128d old = _mm_loadu_pd(depth_row + px);
        const __m128d win =
            _mm_and_pd(hit, _mm_and_pd(_mm_cmpgt_pd(old, z_min), _mm_cmplt_pd(s, old)));
        _mm_storeu_pd(depth_row + px, _mm_or_pd(_mm_and_pd(win, s), _mm_andnot_pd(win, old)));
        const int mask = _mm_movemask_pd(win);  // bit 0: px, bit 1: px + 1
        if (mask == 0) continue;
        if (id_row) {
            if (mask & 1) id_row[px] = index;
            if (mask & 2) id_row[px + 1] = index;
        }
        written.lo = std::min(written.lo, px + ((mask & 1) ^ 1));
        written.hi = px + (mask >> 1);
    }
    if (px == hi) {
        const WrittenSpan last = writeLevelBoxRunScalar(r, px, px, depth_row, id_row, index);
        written.lo = std::min(written.lo, last.lo);
        written.hi = std::max(written.hi, last.hi);
    }
    return written;
}
#else
inline WrittenSpan writeLevelBoxRun(const LevelBoxRow& r, int lo, int hi, double* depth_row,
                                    int32_t* id_row, int index) {
    return writeLevelBoxRunScalar(r, lo, hi, depth_row, id_row, index);
}
#endif

}  // namespace gridcull
