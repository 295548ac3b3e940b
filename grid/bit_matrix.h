// A dense matrix of bits, one per voxel: the occluder matrix O, the static
// occluder matrix Os and the occlusion matrix H of Batagelo & Wu (section 3) are
// each one of these, in 2D and in 3D. Voxel (x, y) of a width x height grid, or
// (x, y, z) of a width x height x depth one, stored as the 2D matrix of
// height * depth rows with row y + z * height; bits are packed 64 to a word,
// rows padded to whole words so that a run of voxels in one row is set with a
// few word writes (the occlusion rasterizer fills row spans).
//
// Memory: height * depth * ceil(width / 64) * 8 bytes, allocated by resize()
// only; every other call allocates nothing. Coordinates are voxel indices;
// callers check bounds (asserts guard them).
#pragma once
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gridcull {

class BitMatrix {
public:
    BitMatrix() = default;
    BitMatrix(int width, int height, int depth = 1) { resize(width, height, depth); }

    // Sizes the matrix and clears every bit. width, height >= 0, depth >= 1.
    void resize(int width, int height, int depth = 1);
    // Frees the storage; width() and height() become 0.
    void release();

    int width() const { return width_; }
    int height() const { return height_; }
    int depth() const { return depth_; }
    bool empty() const { return words_.empty(); }
    // The row that holds voxels (*, y, z).
    int row(int y, int z) const {
        assert(y >= 0 && y < height_ && z >= 0 && z < depth_);
        return y + z * height_;
    }

    bool get(int x, int y) const {
        assert(x >= 0 && y >= 0 && x < width_ && y < rows_);
        return (words_[wordIndex(x, y)] >> (unsigned(x) & 63u)) & 1u;
    }
    void set(int x, int y) {
        assert(x >= 0 && y >= 0 && x < width_ && y < rows_);
        words_[wordIndex(x, y)] |= uint64_t(1) << (unsigned(x) & 63u);
    }
    void reset(int x, int y) {
        assert(x >= 0 && y >= 0 && x < width_ && y < rows_);
        words_[wordIndex(x, y)] &= ~(uint64_t(1) << (unsigned(x) & 63u));
    }
    bool get(int x, int y, int z) const { return get(x, row(y, z)); }
    void set(int x, int y, int z) { set(x, row(y, z)); }
    // Sets bits x0..x1 (inclusive) of row y (a row index: y + z * height in 3D);
    // no-op when x0 > x1. O(run / 64).
    void setRun(int y, int x0, int x1);
    // Are bits x0..x1 (inclusive) of row y all set? True when x0 > x1. O(run / 64).
    bool allSet(int y, int x0, int x1) const;
    // Is any of bits x0..x1 (inclusive) of row y set? False when x0 > x1. O(run / 64).
    bool anySet(int y, int x0, int x1) const;
    // Clears every bit. O(words).
    void clearAll();
    // Becomes a bit-for-bit copy of `other`, which must have the same size. O(words).
    void copyFrom(const BitMatrix& other);
    // Number of set bits. O(words).
    int64_t count() const;
    // Bytes held by the bit storage (the capacity of the word array).
    size_t memoryBytes() const { return words_.capacity() * sizeof(uint64_t); }

private:
    size_t wordIndex(int x, int y) const {
        return size_t(y) * size_t(words_per_row_) + size_t(unsigned(x) >> 6);
    }

    int width_ = 0;
    int height_ = 0;
    int depth_ = 1;
    int rows_ = 0;  // height * depth
    int words_per_row_ = 0;
    std::vector<uint64_t> words_;
};

}  // namespace gridcull
