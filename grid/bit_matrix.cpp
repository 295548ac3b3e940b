#include "grid/bit_matrix.h"

#include <algorithm>
#include <bitset>

namespace gridcull {

void BitMatrix::resize(int width, int height, int depth) {
    assert(width >= 0 && height >= 0 && depth >= 1);
    width_ = width;
    height_ = height;
    depth_ = depth;
    rows_ = height * depth;
    words_per_row_ = (width + 63) / 64;
    words_.assign(size_t(words_per_row_) * size_t(rows_), 0);
}

void BitMatrix::release() {
    width_ = height_ = rows_ = words_per_row_ = 0;
    depth_ = 1;
    std::vector<uint64_t>().swap(words_);
}

void BitMatrix::setRun(int y, int x0, int x1) {
    if (x0 > x1) return;
    assert(y >= 0 && y < rows_ && x0 >= 0 && x1 < width_);
    uint64_t* row = words_.data() + size_t(y) * size_t(words_per_row_);
    const int w0 = x0 >> 6, w1 = x1 >> 6;
    // Masks of the bits at and above x0, and at and below x1, within their words.
    const uint64_t low = ~uint64_t(0) << (unsigned(x0) & 63u);
    const uint64_t high = ~uint64_t(0) >> (63u - (unsigned(x1) & 63u));
    if (w0 == w1) {
        row[w0] |= low & high;
        return;
    }
    row[w0] |= low;
    for (int w = w0 + 1; w < w1; ++w) row[w] = ~uint64_t(0);
    row[w1] |= high;
}

bool BitMatrix::allSet(int y, int x0, int x1) const {
    if (x0 > x1) return true;
    assert(y >= 0 && y < rows_ && x0 >= 0 && x1 < width_);
    const uint64_t* row = words_.data() + size_t(y) * size_t(words_per_row_);
    const int w0 = x0 >> 6, w1 = x1 >> 6;
    const uint64_t low = ~uint64_t(0) << (unsigned(x0) & 63u);
    const uint64_t high = ~uint64_t(0) >> (63u - (unsigned(x1) & 63u));
    if (w0 == w1) return (row[w0] & (low & high)) == (low & high);
    if ((row[w0] & low) != low || (row[w1] & high) != high) return false;
    for (int w = w0 + 1; w < w1; ++w)
        if (row[w] != ~uint64_t(0)) return false;
    return true;
}

bool BitMatrix::anySet(int y, int x0, int x1) const {
    if (x0 > x1) return false;
    assert(y >= 0 && y < rows_ && x0 >= 0 && x1 < width_);
    const uint64_t* row = words_.data() + size_t(y) * size_t(words_per_row_);
    const int w0 = x0 >> 6, w1 = x1 >> 6;
    const uint64_t low = ~uint64_t(0) << (unsigned(x0) & 63u);
    const uint64_t high = ~uint64_t(0) >> (63u - (unsigned(x1) & 63u));
    if (w0 == w1) return (row[w0] & low & high) != 0;
    if ((row[w0] & low) != 0 || (row[w1] & high) != 0) return true;
    for (int w = w0 + 1; w < w1; ++w)
        if (row[w] != 0) return true;
    return false;
}

void BitMatrix::clearAll() { std::fill(words_.begin(), words_.end(), 0); }

void BitMatrix::copyFrom(const BitMatrix& other) {
    assert(other.width_ == width_ && other.rows_ == rows_);
    std::copy(other.words_.begin(), other.words_.end(), words_.begin());
}

int64_t BitMatrix::count() const {
    int64_t n = 0;
    for (const uint64_t w : words_) n += int64_t(std::bitset<64>(w).count());
    return n;
}

}  // namespace gridcull
