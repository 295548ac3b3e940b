#include "grid/bitmap_vectorize.h"

#include <algorithm>
#include <cassert>

namespace gridcull {

namespace {

// Directions in counter-clockwise order, so left of d is (d + 1) & 3 and right
// of d is (d + 3) & 3.
constexpr int kEast = 0, kNorth = 1, kWest = 2, kSouth = 3;
constexpr int kStepX[4] = {1, 0, -1, 0};
constexpr int kStepY[4] = {0, 1, 0, -1};

// Unit boundary edges of a width x height bitmap at most: every horizontal and
// vertical unit edge of the lattice. A loop has at most one corner per edge and
// at least four edges.
int64_t maxEdges(int64_t width, int64_t height) {
    return 2 * width * height + width + height;
}

}  // namespace

size_t BitmapVectorizer::reservedBytes() const {
    return cells_.capacity() * sizeof(uint8_t) + component_.capacity() * sizeof(int32_t) +
           stack_.capacity() * sizeof(int32_t) + corners_.capacity() * sizeof(glm::ivec2) +
           loops_.capacity() * sizeof(BitmapLoop);
}

uint8_t* BitmapVectorizer::beginBitmap(int width, int height) {
    assert(width >= 0 && height >= 0);
    const int64_t cells = (int64_t(width) + 2) * (int64_t(height) + 2);
    assert(cells <= kMaxPixels);
    width_ = width;
    height_ = height;
    // resize() and reserve() within the capacity a larger bitmap left allocate nothing.
    cells_.assign(size_t(cells), 0);
    component_.assign(size_t(cells), -1);
    stack_.reserve(size_t(width) * size_t(height));
    const int64_t edges = maxEdges(width, height);
    corners_.reserve(size_t(edges));
    loops_.reserve(size_t(edges / 4));
    corners_.clear();
    loops_.clear();
    return cells_.data();
}

void BitmapVectorizer::traceLoops() {
    const int stride = width_ + 2;
    // Every loop has a rightward edge (an outer loop along its bottom, a hole
    // along its top); a loop starts at its first one in row order. A component's
    // lowest-leftmost pixel's bottom edge comes before any edge of its holes,
    // which have pixels of the component below them, so the first loop met of
    // each component is its outer one.
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            const int cell = (y + 1) * stride + x + 1;
            const uint8_t c = cells_[size_t(cell)];
            if (!(c & kFilled) || (c & kBottomTraced) || (cells_[size_t(cell - stride)] & kFilled))
                continue;
            const int32_t known = component_[size_t(cell)];
            if (known >= 0) {
                traceLoop(x, y, known, true);
            } else {
                const int outer = int(loops_.size());
                labelComponent(cell, outer);
                traceLoop(x, y, outer, false);
            }
        }
    }
}

// Walks the loop through the rightward edge from corner (x, y) to (x + 1, y)
// and appends it to loops_.
void BitmapVectorizer::traceLoop(int x, int y, int outer, bool hole) {
    const int stride = width_ + 2;
    // The edge leaving corner (cx, cy) in direction d exists when the pixel on
    // its left is filled and the one on its right empty. Around the corner, in
    // counter-clockwise order from north-east, the pixels are NE (cx, cy),
    // NW (cx - 1, cy), SW (cx - 1, cy - 1), SE (cx, cy - 1); the edge in
    // direction d has pixel d of these on its left and pixel (d + 3) & 3 on its right.
    const int around[4] = {0, -1, -stride - 1, -stride};
    auto leaves = [&](int cx, int cy, int d) {
        const int ne = (cy + 1) * stride + cx + 1;
        return (cells_[size_t(ne + around[d])] & kFilled) &&
               !(cells_[size_t(ne + around[(d + 3) & 3])] & kFilled);
    };

    BitmapLoop loop;
    loop.first = int(corners_.size());
    loop.hole = hole;
    loop.outer = outer;
    corners_.push_back({x, y});
    cells_[size_t((y + 1) * stride + x + 1)] |= kBottomTraced;
    int cx = x + 1, cy = y, d = kEast;
    for (;;) {
        // Left first: at a saddle that keeps to the filled pixel being passed
        // (filled pixels 4-connected); elsewhere only one edge leaves.
        int next = (d + 1) & 3;
        if (!leaves(cx, cy, next)) next = leaves(cx, cy, d) ? d : (d + 3) & 3;
        assert(leaves(cx, cy, next));
        if (cx == x && cy == y && next == kEast) break;  // back at the first edge
        if (next != d) corners_.push_back({cx, cy});
        if (next == kEast) cells_[size_t((cy + 1) * stride + cx + 1)] |= kBottomTraced;
        cx += kStepX[next];
        cy += kStepY[next];
        d = next;
    }
    // The first corner is a real one: the edge into it is no rightward edge, or
    // the row scan would have started the loop there.
    assert(d != kEast);
    loop.count = int(corners_.size()) - loop.first;
    assert(loop.count >= 4 && loop.count % 2 == 0);
    loops_.push_back(loop);
}

// Writes `outer` into component_ for every filled cell 4-connected to `cell`.
void BitmapVectorizer::labelComponent(int cell, int outer) {
    const int stride = width_ + 2;
    const int neighbours[4] = {1, stride, -1, -stride};
    stack_.clear();
    stack_.push_back(cell);
    component_[size_t(cell)] = outer;
    while (!stack_.empty()) {
        const int c = stack_.back();
        stack_.pop_back();
        for (int n : neighbours) {
            const int m = c + n;
            // The border cells are empty, so m never leaves the padded bitmap.
            if ((cells_[size_t(m)] & kFilled) && component_[size_t(m)] < 0) {
                component_[size_t(m)] = outer;
                stack_.push_back(m);
            }
        }
    }
}

int64_t signedDoubleArea(const glm::ivec2* corners, int count) {
    int64_t sum = 0;
    for (int i = 0; i < count; ++i) {
        const glm::ivec2 p = corners[i], q = corners[(i + 1) % count];
        sum += int64_t(p.x) * q.y - int64_t(q.x) * p.y;
    }
    return sum;
}

bool insideEvenOdd(const BitmapVectorizer& vectorizer, double px, double py) {
    // A ray towards +x crosses the vertical edges to the right of the point
    // whose span [y0, y1) holds py.
    bool inside = false;
    for (const BitmapLoop& loop : vectorizer.loops()) {
        const glm::ivec2* c = vectorizer.corners(loop);
        for (int i = 0; i < loop.count; ++i) {
            const glm::ivec2 p = c[i], q = c[(i + 1) % loop.count];
            if (p.x != q.x || p.x <= px) continue;
            const int y0 = std::min(p.y, q.y), y1 = std::max(p.y, q.y);
            if (py >= y0 && py < y1) inside = !inside;
        }
    }
    return inside;
}

}  // namespace gridcull
