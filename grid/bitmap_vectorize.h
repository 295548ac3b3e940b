// Vectorizing a binary bitmap into rectilinear polygons with holes, for Batagelo
// & Wu's 3D occlusion step (section 5.3): the opaque-or-occluded voxels of one
// face of a chess layer, seen as a bitmap, become a cap polygon (possibly with
// holes) that is then extruded away from the viewer.
//
// The boundary is found by crack following: every unit edge between a filled
// and an empty pixel (the outside counts as empty) is directed so that the
// filled pixel lies on its left, and the edges are chained corner to corner into
// closed loops. With y up, outer boundaries then run counter-clockwise and holes
// clockwise, and the filled region is exactly the even-odd interior of all loops.
//
// Saddle rule: at a lattice corner where two filled pixels touch only diagonally
// (the other two pixels empty), the chaining turns left, around the filled pixel
// it is passing. So filled pixels are 4-connected and empty ones 8-connected:
// two diagonal pixels are two components, two loops that touch at that corner,
// and an empty pixel that reaches the outside through a saddle is no hole. A
// loop never crosses itself or another loop; it may touch itself at a saddle
// corner (a ring closed only by a diagonal contact is one outer loop through
// that corner twice, no hole), and it may touch another loop there. Either
// rule bounds the same region; this one keeps the pixels of a component
// edge-connected, so voxels touching only along a line give separate caps.
//
// Coordinates are pixel indices: pixel (x, y) covers [x, x + 1] x [y, y + 1],
// so loop corners are integer lattice points in [0, width] x [0, height].
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace gridcull {

// One closed loop of BitmapVectorizer's output: corners()[first, first + count).
struct BitmapLoop {
    int first = 0;
    // Corners in the loop, at least 4 and even: edges alternate between
    // horizontal and vertical, and no two consecutive edges are collinear.
    int count = 0;
    // A hole (clockwise) of its component, or the component's outer boundary
    // (counter-clockwise).
    bool hole = false;
    // Index in loops() of the outer loop of the 4-connected component this loop
    // bounds; an outer loop's own index. The outer loop comes before its holes.
    int outer = 0;
};

// Owns the loops of the last bitmap it vectorized and the scratch buffers that
// made them. The buffers grow to the worst case of each bitmap size seen, so
// vectorizing again a bitmap no wider and no taller than one seen before
// allocates nothing, whatever its pixels.
class BitmapVectorizer {
public:
    // Vectorizes the width x height bitmap whose pixel (x, y), 0 <= x < width,
    // 0 <= y < height, is filled when filled(x, y) is true; filled is called
    // once per pixel, in row order. Precondition: width, height >= 0 and
    // (width + 2) * (height + 2) <= kMaxPixels. Loops come in the order of
    // their first rightward edge (lowest row first, then left to right), which
    // puts each component's outer loop before its holes; a loop's first corner
    // is the left end of that edge, always a real corner.
    // Cost: O(width * height) time; memory about 33 bytes per pixel, kept.
    template <typename Filled>
    void vectorize(int width, int height, Filled&& filled) {
        uint8_t* cells = beginBitmap(width, height);
        const int stride = width + 2;
        for (int y = 0; y < height; ++y) {
            uint8_t* row = cells + (y + 1) * stride + 1;
            for (int x = 0; x < width; ++x) row[x] = filled(x, y) ? kFilled : 0;
        }
        traceLoops();
    }

    const std::vector<BitmapLoop>& loops() const { return loops_; }
    // All loops' corners, loop after loop.
    const std::vector<glm::ivec2>& corners() const { return corners_; }
    const glm::ivec2* corners(const BitmapLoop& loop) const { return corners_.data() + loop.first; }
    int width() const { return width_; }
    int height() const { return height_; }
    // Bytes held by the output and scratch buffers.
    size_t reservedBytes() const;

    static constexpr int64_t kMaxPixels = int64_t(1) << 28;

private:
    static constexpr uint8_t kFilled = 1;
    // On a filled pixel: the rightward edge along its bottom is in a loop already.
    static constexpr uint8_t kBottomTraced = 2;

    uint8_t* beginBitmap(int width, int height);
    void traceLoops();
    void traceLoop(int x, int y, int outer, bool hole);
    void labelComponent(int cell, int outer);

    int width_ = 0;
    int height_ = 0;
    // The bitmap with a one-pixel empty border: pixel (x, y) at (y + 1) * (width + 2) + x + 1.
    std::vector<uint8_t> cells_;
    // Per cell: the index of the outer loop of its component, -1 before that is known.
    std::vector<int32_t> component_;
    std::vector<int32_t> stack_;  // the flood fill's pending cells
    std::vector<glm::ivec2> corners_;
    std::vector<BitmapLoop> loops_;
};

// Twice the signed area of a closed loop (the shoelace sum): positive for
// counter-clockwise order, negative for a hole. Summed over all of a
// vectorizer's loops it is twice the number of filled pixels. Cost: O(count).
int64_t signedDoubleArea(const glm::ivec2* corners, int count);

// Whether (px, py) lies inside an odd number of the vectorizer's loops, i.e. in
// a filled pixel; a point on a loop may count either way. Cost: O(corners).
bool insideEvenOdd(const BitmapVectorizer& vectorizer, double px, double py);

}  // namespace gridcull
