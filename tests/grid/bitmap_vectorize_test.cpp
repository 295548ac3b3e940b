// BitmapVectorizer: hand-made bitmaps with their exact loops (empty, one pixel, a
// rectangle, an L, a ring, nested rings, diagonal pixels at a saddle, a
// checkerboard, a spiral), then seeded random bitmaps checked against the bitmap
// itself: areas, the even-odd interior, orientations, real corners, exact
// boundary edges, the saddle rule, components and holes counted independently,
// and reuse of the buffers.
#include "grid/bitmap_vectorize.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "culling/scene/seeded_random.h"
#include "tests/common/test_seeds.h"

namespace gridcull {
namespace {

struct Bitmap {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> pixels;  // pixel (x, y) at y * width + x

    Bitmap(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h), 0) {}
    bool operator()(int x, int y) const { return pixels[size_t(y) * width + x] != 0; }
    // Outside the bitmap counts as empty.
    bool at(int x, int y) const {
        return x >= 0 && y >= 0 && x < width && y < height && (*this)(x, y);
    }
    void set(int x, int y) { pixels[size_t(y) * width + x] = 1; }
    int count() const {
        int n = 0;
        for (uint8_t p : pixels) n += p;
        return n;
    }
};

// Rows as drawn, '#' filled: the first row is the top one, y = height - 1.
Bitmap drawn(std::initializer_list<const char*> rows) {
    Bitmap b(rows.size() ? int(std::strlen(*rows.begin())) : 0, int(rows.size()));
    int y = b.height - 1;
    for (const char* row : rows) {
        for (int x = 0; x < b.width; ++x)
            if (row[x] == '#') b.set(x, y);
        --y;
    }
    return b;
}

std::vector<glm::ivec2> loopCorners(const BitmapVectorizer& v, int loop) {
    const BitmapLoop& l = v.loops()[size_t(loop)];
    return std::vector<glm::ivec2>(v.corners(l), v.corners(l) + l.count);
}

// Winding number of one loop around a point off its edges.
int winding(const BitmapVectorizer& v, const BitmapLoop& loop, double px, double py) {
    const glm::ivec2* c = v.corners(loop);
    int w = 0;
    for (int i = 0; i < loop.count; ++i) {
        const glm::ivec2 p = c[i], q = c[(i + 1) % loop.count];
        if (p.x != q.x || p.x <= px) continue;
        if (p.y <= py && py < q.y) ++w;
        if (q.y <= py && py < p.y) --w;
    }
    return w;
}

// Labels of the connected components of cells where `in` holds, in a grid of
// w x h cells, 4- or 8-connected; -1 elsewhere. Returns the number of components.
template <typename In>
int components(int w, int h, bool eight, In&& in, std::vector<int>& label) {
    label.assign(size_t(w) * size_t(h), -1);
    int n = 0;
    std::vector<int> stack;
    for (int start = 0; start < w * h; ++start) {
        if (label[size_t(start)] >= 0 || !in(start % w, start / w)) continue;
        label[size_t(start)] = n;
        stack.push_back(start);
        while (!stack.empty()) {
            const int c = stack.back();
            stack.pop_back();
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    if ((dx == 0 && dy == 0) || (!eight && dx != 0 && dy != 0)) continue;
                    const int x = c % w + dx, y = c / w + dy;
                    if (x < 0 || y < 0 || x >= w || y >= h) continue;
                    const int m = y * w + x;
                    if (label[size_t(m)] < 0 && in(x, y)) {
                        label[size_t(m)] = n;
                        stack.push_back(m);
                    }
                }
            }
        }
        ++n;
    }
    return n;
}

// Every property the header promises, checked against the bitmap itself.
void checkLoops(const BitmapVectorizer& v, const Bitmap& b) {
    ASSERT_EQ(v.width(), b.width);
    ASSERT_EQ(v.height(), b.height);
    const std::vector<BitmapLoop>& loops = v.loops();
    int64_t area2 = 0;
    int outers = 0, holes = 0;
    // Directed unit edges (x, y, direction 0..3 = E, N, W, S) of all loops.
    std::set<std::tuple<int, int, int>> edges;
    int expected_first = 0;
    for (size_t li = 0; li < loops.size(); ++li) {
        const BitmapLoop& loop = loops[li];
        SCOPED_TRACE(::testing::Message() << "loop " << li);
        ASSERT_EQ(loop.first, expected_first);
        expected_first += loop.count;
        ASSERT_GE(loop.count, 4);
        ASSERT_EQ(loop.count % 2, 0);
        const int64_t a = signedDoubleArea(v.corners(loop), loop.count);
        area2 += a;
        if (loop.hole) {
            ++holes;
            ASSERT_LT(a, 0) << "a hole runs clockwise";
            ASSERT_LT(loop.outer, int(li)) << "the outer loop comes first";
            ASSERT_FALSE(loops[size_t(loop.outer)].hole);
            // The hole's first edge runs along the top of an empty pixel inside it;
            // that pixel is inside the owner's outer loop.
            const glm::ivec2 f = v.corners(loop)[0];
            ASSERT_EQ(winding(v, loop, f.x + 0.5, f.y - 0.5), -1);
            ASSERT_EQ(winding(v, loops[size_t(loop.outer)], f.x + 0.5, f.y - 0.5), 1);
        } else {
            ++outers;
            ASSERT_GT(a, 0) << "an outer loop runs counter-clockwise";
            ASSERT_EQ(loop.outer, int(li));
        }
        const glm::ivec2* c = v.corners(loop);
        for (int i = 0; i < loop.count; ++i) {
            const glm::ivec2 p = c[i], q = c[(i + 1) % loop.count];
            const glm::ivec2 o = c[(i + loop.count - 1) % loop.count];
            ASSERT_TRUE(p.x >= 0 && p.y >= 0 && p.x <= b.width && p.y <= b.height);
            // Axis-aligned, not empty, and turning at every corner.
            ASSERT_TRUE((p.x == q.x) != (p.y == q.y)) << "edge " << i;
            ASSERT_NE(p.x == q.x, o.x == p.x) << "collinear at corner " << i;
            // At a saddle corner (two filled pixels touching only diagonally) the
            // loop turns left.
            const bool ne = b.at(p.x, p.y), nw = b.at(p.x - 1, p.y);
            const bool sw = b.at(p.x - 1, p.y - 1), se = b.at(p.x, p.y - 1);
            if (ne == sw && nw == se && ne != nw) {
                const glm::ivec2 in = p - o, out = q - p;
                ASSERT_GT(int64_t(in.x) * out.y - int64_t(in.y) * out.x, 0)
                    << "right turn at saddle corner " << p.x << "," << p.y;
            }
            // Unit edges, each with the filled pixel on its left and the empty
            // one on its right, each once.
            const glm::ivec2 step{q.x > p.x ? 1 : (q.x < p.x ? -1 : 0),
                                  q.y > p.y ? 1 : (q.y < p.y ? -1 : 0)};
            const int dir = step.x == 1 ? 0 : step.y == 1 ? 1 : step.x == -1 ? 2 : 3;
            for (glm::ivec2 u = p; u != q; u += step) {
                // Left pixel of the unit edge from u, right pixel across it.
                const glm::ivec2 left = dir == 0   ? u
                                        : dir == 1 ? u - glm::ivec2(1, 0)
                                        : dir == 2 ? u - glm::ivec2(1, 1)
                                                   : u - glm::ivec2(0, 1);
                const glm::ivec2 right = left + (dir == 0   ? glm::ivec2(0, -1)
                                                 : dir == 1 ? glm::ivec2(1, 0)
                                                 : dir == 2 ? glm::ivec2(0, 1)
                                                            : glm::ivec2(-1, 0));
                ASSERT_TRUE(b.at(left.x, left.y) && !b.at(right.x, right.y))
                    << "edge from " << u.x << "," << u.y << " dir " << dir;
                ASSERT_TRUE(edges.insert({u.x, u.y, dir}).second) << "unit edge used twice";
            }
        }
    }
    ASSERT_EQ(area2, 2 * int64_t(b.count()));
    // All boundary unit edges: every filled-empty pair of 4-neighbours, outside included.
    size_t boundary = 0;
    for (int y = -1; y <= b.height; ++y)
        for (int x = -1; x <= b.width; ++x) {
            boundary += b.at(x, y) != b.at(x + 1, y);
            boundary += b.at(x, y) != b.at(x, y + 1);
        }
    ASSERT_EQ(edges.size(), boundary);
    // Even-odd interior at every pixel centre.
    for (int y = 0; y < b.height; ++y)
        for (int x = 0; x < b.width; ++x)
            ASSERT_EQ(insideEvenOdd(v, x + 0.5, y + 0.5), b(x, y)) << "pixel " << x << "," << y;

    // One outer loop per 4-connected component of filled pixels, one hole per
    // 8-connected component of empty pixels cut off from the outside, and the
    // loops of one component share its outer loop.
    std::vector<int> filled_label, empty_label;
    const int filled_components = components(b.width, b.height, false, b, filled_label);
    ASSERT_EQ(outers, filled_components);
    const int pw = b.width + 2, ph = b.height + 2;
    const int empty_components = components(
        pw, ph, true, [&](int x, int y) { return !b.at(x - 1, y - 1); }, empty_label);
    ASSERT_EQ(holes, empty_components - 1) << "the padding is the one outside component";
    std::vector<int> outer_of_component(size_t(filled_components), -1);
    for (size_t li = 0; li < loops.size(); ++li) {
        const glm::ivec2 f = v.corners(loops[li])[0];  // left end of a rightward edge
        ASSERT_TRUE(b.at(f.x, f.y) && !b.at(f.x, f.y - 1));
        const int component = filled_label[size_t(f.y) * b.width + f.x];
        int& outer = outer_of_component[size_t(component)];
        if (outer < 0) outer = loops[li].outer;
        ASSERT_EQ(loops[li].outer, outer) << "loop " << li << " of component " << component;
    }
}

TEST(BitmapVectorize, EmptyBitmapsHaveNoLoops) {
    BitmapVectorizer v;
    for (const Bitmap& b : {Bitmap(0, 0), Bitmap(5, 0), Bitmap(0, 4), Bitmap(7, 3)}) {
        // Nothing is left of the bitmap before.
        v.vectorize(2, 2, [](int x, int) { return x == 0; });
        v.vectorize(b.width, b.height, b);
        EXPECT_TRUE(v.loops().empty());
        EXPECT_TRUE(v.corners().empty());
        EXPECT_FALSE(insideEvenOdd(v, 0.5, 0.5));
    }
}

TEST(BitmapVectorize, OnePixelIsOneSquare) {
    BitmapVectorizer v;
    const Bitmap b = drawn({"...", ".#.", "..."});
    v.vectorize(b.width, b.height, b);
    ASSERT_EQ(v.loops().size(), size_t(1));
    EXPECT_FALSE(v.loops()[0].hole);
    EXPECT_EQ(loopCorners(v, 0), (std::vector<glm::ivec2>{{1, 1}, {2, 1}, {2, 2}, {1, 2}}));
    checkLoops(v, b);
}

TEST(BitmapVectorize, FullRectangleIsItsFourCorners) {
    BitmapVectorizer v;
    const Bitmap b = drawn({"#####", "#####", "#####"});
    v.vectorize(b.width, b.height, b);
    ASSERT_EQ(v.loops().size(), size_t(1));
    EXPECT_EQ(loopCorners(v, 0), (std::vector<glm::ivec2>{{0, 0}, {5, 0}, {5, 3}, {0, 3}}));
    EXPECT_EQ(signedDoubleArea(v.corners(v.loops()[0]), 4), 30);
    checkLoops(v, b);
}

TEST(BitmapVectorize, LShapeHasSixCorners) {
    BitmapVectorizer v;
    const Bitmap b = drawn({"#..", "#..", "###"});
    v.vectorize(b.width, b.height, b);
    ASSERT_EQ(v.loops().size(), size_t(1));
    EXPECT_EQ(loopCorners(v, 0),
              (std::vector<glm::ivec2>{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}}));
    checkLoops(v, b);
}

TEST(BitmapVectorize, RingHasOneClockwiseHole) {
    BitmapVectorizer v;
    const Bitmap b = drawn({"###", "#.#", "###"});
    v.vectorize(b.width, b.height, b);
    ASSERT_EQ(v.loops().size(), size_t(2));
    EXPECT_FALSE(v.loops()[0].hole);
    EXPECT_EQ(loopCorners(v, 0), (std::vector<glm::ivec2>{{0, 0}, {3, 0}, {3, 3}, {0, 3}}));
    EXPECT_TRUE(v.loops()[1].hole);
    EXPECT_EQ(v.loops()[1].outer, 0);
    EXPECT_EQ(loopCorners(v, 1), (std::vector<glm::ivec2>{{1, 2}, {2, 2}, {2, 1}, {1, 1}}));
    checkLoops(v, b);
}

TEST(BitmapVectorize, NestedIslandsInHoles) {
    // Five levels: ring A, its hole, ring B inside it, B's hole, pixel C inside that.
    BitmapVectorizer v;
    const Bitmap b = drawn({"#########",    // y 8
                            "#.......#",    // y 7
                            "#.#####.#",    // y 6
                            "#.#...#.#",    // y 5
                            "#.#.#.#.#",    // y 4
                            "#.#...#.#",    // y 3
                            "#.#####.#",    // y 2
                            "#.......#",    // y 1
                            "#########"});  // y 0
    v.vectorize(b.width, b.height, b);
    // Row order of the loops' first edges: A's bottom (y 0), B's bottom (y 2),
    // C's bottom (y 4), B's hole's top (y 6), A's hole's top (y 8).
    ASSERT_EQ(v.loops().size(), size_t(5));
    const bool hole[5] = {false, false, false, true, true};
    const int outer[5] = {0, 1, 2, 1, 0};
    const glm::ivec2 first[5] = {{0, 0}, {2, 2}, {4, 4}, {3, 6}, {1, 8}};
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(v.loops()[size_t(i)].hole, hole[i]) << i;
        EXPECT_EQ(v.loops()[size_t(i)].outer, outer[i]) << i;
        EXPECT_EQ(v.loops()[size_t(i)].count, 4) << i;
        EXPECT_EQ(v.corners(v.loops()[size_t(i)])[0], first[i]) << i;
    }
    checkLoops(v, b);
}

TEST(BitmapVectorize, DiagonalPixelsAreTwoLoopsTouchingAtTheSaddle) {
    BitmapVectorizer v;
    for (const Bitmap& b : {drawn({".#", "#."}), drawn({"#.", ".#"})}) {
        v.vectorize(b.width, b.height, b);
        ASSERT_EQ(v.loops().size(), size_t(2));
        EXPECT_FALSE(v.loops()[0].hole);
        EXPECT_FALSE(v.loops()[1].hole);
        EXPECT_EQ(v.loops()[1].outer, 1);
        // Both squares have the saddle (1, 1) as a corner.
        for (int i = 0; i < 2; ++i) {
            const std::vector<glm::ivec2> c = loopCorners(v, i);
            EXPECT_EQ(std::count(c.begin(), c.end(), glm::ivec2(1, 1)), 1);
        }
        checkLoops(v, b);
    }
}

TEST(BitmapVectorize, RingClosedOnlyDiagonallyIsOneLoopWithoutHole) {
    // The empty centre reaches the outside through the saddle (1, 1): no hole;
    // the outer loop passes the saddle twice, touching itself, not crossing.
    BitmapVectorizer v;
    const Bitmap b = drawn({"###", "#.#", ".##"});
    v.vectorize(b.width, b.height, b);
    ASSERT_EQ(v.loops().size(), size_t(1));
    EXPECT_FALSE(v.loops()[0].hole);
    const std::vector<glm::ivec2> c = loopCorners(v, 0);
    EXPECT_EQ(std::count(c.begin(), c.end(), glm::ivec2(1, 1)), 2);
    EXPECT_EQ(signedDoubleArea(c.data(), int(c.size())), 14);
    checkLoops(v, b);
}

TEST(BitmapVectorize, HoleThroughASaddleIsOneHole) {
    // Two empty pixels touching diagonally inside a filled block are one hole
    // (empty pixels are 8-connected), which passes the saddle (2, 2) twice.
    BitmapVectorizer v;
    const Bitmap b = drawn({"####", "##.#", "#.##", "####"});
    v.vectorize(b.width, b.height, b);
    ASSERT_EQ(v.loops().size(), size_t(2));
    EXPECT_TRUE(v.loops()[1].hole);
    const std::vector<glm::ivec2> c = loopCorners(v, 1);
    EXPECT_EQ(c.size(), size_t(8));
    EXPECT_EQ(std::count(c.begin(), c.end(), glm::ivec2(2, 2)), 2);
    checkLoops(v, b);
}

TEST(BitmapVectorize, CheckerboardIsOneSquarePerFilledPixel) {
    BitmapVectorizer v;
    for (int size : {1, 2, 5, 6}) {
        Bitmap b(size, size + 1);
        for (int y = 0; y < b.height; ++y)
            for (int x = 0; x < b.width; ++x)
                if ((x + y) % 2 == 0) b.set(x, y);
        v.vectorize(b.width, b.height, b);
        ASSERT_EQ(v.loops().size(), size_t(b.count())) << size;
        for (const BitmapLoop& loop : v.loops()) {
            EXPECT_EQ(loop.count, 4);
            EXPECT_FALSE(loop.hole);
        }
        checkLoops(v, b);
    }
}

TEST(BitmapVectorize, OnePixelWideSpiralIsOneLoop) {
    BitmapVectorizer v;
    const Bitmap b = drawn({"#########",    // y 8
                            "........#",    // y 7
                            "#######.#",    // y 6
                            "#.....#.#",    // y 5
                            "#.###.#.#",    // y 4
                            "#.#...#.#",    // y 3
                            "#.#####.#",    // y 2
                            "#.......#",    // y 1
                            "#########"});  // y 0
    v.vectorize(b.width, b.height, b);
    ASSERT_EQ(v.loops().size(), size_t(1));
    EXPECT_FALSE(v.loops()[0].hole);
    // Nine arms, so eight turns, each an inner and an outer corner, and two
    // ends of two corners each.
    EXPECT_EQ(v.loops()[0].count, 2 * 8 + 2 * 2);
    checkLoops(v, b);
}

Bitmap randomBitmap(SeededRandom& rng) {
    Bitmap b(1 + int(rng.below(40)), 1 + int(rng.below(40)));
    const double densities[] = {0.05, 0.3, 0.5, 0.7, 0.95};
    const double density = densities[rng.below(5)];
    for (int y = 0; y < b.height; ++y)
        for (int x = 0; x < b.width; ++x)
            if (rng.uniform() < density) b.set(x, y);
    return b;
}

TEST(BitmapVectorize, RandomBitmapsMatchTheirLoops) {
    BitmapVectorizer reused;
    for (const uint64_t seed : test::seedsToRun(7000, 500)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed);
            const Bitmap b = randomBitmap(rng);
            reused.vectorize(b.width, b.height, b);
            checkLoops(reused, b);
            if (::testing::Test::HasFatalFailure()) return;
            // A vectorizer that saw other bitmaps before gives what a fresh one gives.
            BitmapVectorizer fresh;
            fresh.vectorize(b.width, b.height, b);
            ASSERT_EQ(fresh.corners(), reused.corners());
            ASSERT_EQ(fresh.loops().size(), reused.loops().size());
            for (size_t i = 0; i < fresh.loops().size(); ++i) {
                ASSERT_EQ(fresh.loops()[i].first, reused.loops()[i].first);
                ASSERT_EQ(fresh.loops()[i].count, reused.loops()[i].count);
                ASSERT_EQ(fresh.loops()[i].hole, reused.loops()[i].hole);
                ASSERT_EQ(fresh.loops()[i].outer, reused.loops()[i].outer);
            }
        });
    }
}

// "Hot per-frame paths allocate nothing": after one bitmap, any bitmap no wider
// and no taller, worst cases included, leaves every buffer where it was. This
// is measured by the buffers, not by tests/common/counting_new.h: that header
// replaces the global operator new and may be included once per test binary,
// and core_tests has it from tests/culling/lazy_grid/lazy_grid_allocation_test.cpp.
TEST(BitmapVectorize, AgainNoLargerKeepsEveryBuffer) {
    BitmapVectorizer v;
    SeededRandom rng(71);
    Bitmap first(40, 40);
    for (uint8_t& p : first.pixels) p = rng.uniform() < 0.5;
    v.vectorize(40, 40, first);
    const size_t bytes = v.reservedBytes();
    const glm::ivec2* corners = v.corners().data();
    const BitmapLoop* loops = v.loops().data();
    auto checkerboard = [](int x, int y) { return (x + y) % 2 == 0; };
    auto full = [](int, int) { return true; };
    auto stripes = [](int x, int) { return x % 2 == 0; };
    auto combs = [](int x, int y) { return x % 2 == 0 || y == 0; };
    for (const auto& [w, h] : {std::pair{40, 40}, {40, 1}, {1, 40}, {13, 27}, {0, 0}}) {
        v.vectorize(w, h, checkerboard);
        v.vectorize(w, h, full);
        v.vectorize(w, h, stripes);
        v.vectorize(w, h, combs);
        EXPECT_EQ(v.reservedBytes(), bytes) << w << "x" << h;
        EXPECT_EQ(v.corners().data(), corners) << w << "x" << h;
        EXPECT_EQ(v.loops().data(), loops) << w << "x" << h;
    }
    // The checkerboard has the most loops and corners a 40 x 40 bitmap can have.
    v.vectorize(40, 40, checkerboard);
    EXPECT_EQ(v.loops().size(), size_t(800));
    EXPECT_EQ(v.corners().data(), corners);
    EXPECT_EQ(v.loops().data(), loops);
}

}  // namespace
}  // namespace gridcull
