// The lazy occlusion grid alone (culling/lazy_grid/lazy_grid.h), on buffers written by
// hand or by the rasterizer: internal and border cells, the cell-state
// transitions of Hey et al. Fig. 2 and Fig. 3 (lazy and busy), and the central
// promise, checked against brute force on random buffers: a box is rated
// occluded exactly when every pixel of its rectangle is occluded (occlusion
// buffer) or nearer than its znear (z-buffer), so a box behind a horizon is
// culled only when the horizon hides all of it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "culling/lazy_grid/lazy_grid.h"
#include "culling/raster/id_depth_buffer.h"
#include "culling/raster/occlusion_buffer.h"
#include "culling/raster/software_image_target.h"
#include "culling/scene/seeded_random.h"
#include "tests/common/test_seeds.h"

namespace gridcull {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<int> sorted(std::vector<int> v) {
    std::sort(v.begin(), v.end());
    return v;
}

// 100 x 70 pixels in cells of 32: 4 x 3 cells, the last column 4 pixels wide
// (96..99) and the last row 6 pixels high (64..69).
TEST(LazyGridCells, InternalCellsLieWhollyInsideTheRectangleBorderCellsCrossIt) {
    LazyOcclusionGrid grid;
    grid.configure(100, 70, 32, LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Lazy, {});
    EXPECT_EQ(grid.cellsX(), 4);
    EXPECT_EQ(grid.cellsY(), 3);
    const PixelRect last = grid.cellRect(3, 2);
    EXPECT_EQ(last.x0, 96);
    EXPECT_EQ(last.x1, 99);
    EXPECT_EQ(last.y0, 64);
    EXPECT_EQ(last.y1, 69);

    grid.classify({10, 10, 70, 69});  // cells x 0..2, y 0..2
    // Internal: (1,1) = [32,63]^2 and (1,2) = [32,63] x [64,69], the clipped bottom cell.
    EXPECT_EQ(sorted(grid.internalCells()), (std::vector<int>{1 * 4 + 1, 2 * 4 + 1}));
    EXPECT_EQ(sorted(grid.borderCells()), (std::vector<int>{0, 1, 2, 4, 6, 8, 10}));

    grid.classify({32, 32, 63, 63});  // exactly one cell: internal, no border
    EXPECT_EQ(grid.internalCells(), (std::vector<int>{5}));
    EXPECT_TRUE(grid.borderCells().empty());

    grid.classify({40, 40, 41, 41});  // inside one cell: a border cell only
    EXPECT_TRUE(grid.internalCells().empty());
    EXPECT_EQ(grid.borderCells(), (std::vector<int>{5}));

    grid.classify({0, 0, 99, 69});  // the whole image: every cell internal
    EXPECT_EQ(grid.internalCells().size(), 12u);
    EXPECT_TRUE(grid.borderCells().empty());
}

TEST(LazyGridCells, LargeBoxExtensionTreatsBorderCellsAsInternal) {
    LazyOcclusionGrid grid;
    LazyGridExtensions ext;
    ext.large_box_fraction = 0.25;  // 1750 pixels of 7000
    grid.configure(100, 70, 32, LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Lazy, ext);
    grid.classify({10, 10, 70, 69});  // 61 x 60 = 3660 pixels: large
    EXPECT_EQ(grid.internalCells().size(), 9u);
    EXPECT_TRUE(grid.borderCells().empty());
    grid.classify({10, 10, 40, 40});  // 961 pixels: not large
    EXPECT_EQ(grid.internalCells().size(), 0u);
    EXPECT_EQ(grid.borderCells().size(), 4u);
}

BoxOnScreen boxAt(const PixelRect& rect, double znear = 1.0) {
    return {rect, znear, znear + 1};
}

TEST(LazyGridStates, OcclusionBufferLazyUpdate) {
    OcclusionBuffer buffer;
    buffer.resize(64, 32);  // two cells of 32
    LazyOcclusionGrid grid;
    grid.configure(64, 32, 32, LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Lazy, {});
    const SoftwarePixelQueries pixels(&buffer, nullptr);
    grid.begin(&pixels);
    const auto& cells = grid.cells();
    EXPECT_EQ(cells[0].state, CellState::CompletelyFree);
    EXPECT_FALSE(cells[0].full);

    // Something drawn over all of cell 0 and part of cell 1.
    buffer.markOccluded({0, 0, 40, 31});
    grid.afterDraw({0, 0, 40, 31}, {0, 0, 40, 31});
    EXPECT_EQ(cells[0].state, CellState::Outdated);
    EXPECT_EQ(cells[1].state, CellState::Outdated);
    EXPECT_EQ(grid.counters().pixel_queries, 0);  // lazy: nothing read yet
    EXPECT_DOUBLE_EQ(cells[1].drawn_area, 9 * 32);

    // A box over cell 0 only: its internal outdated cell is queried and found full.
    OcclusionStep step;
    EXPECT_TRUE(grid.isOccluded(boxAt({0, 0, 31, 31}), step, nullptr));
    EXPECT_EQ(step, OcclusionStep::Occluded);
    EXPECT_TRUE(cells[0].full);
    EXPECT_EQ(cells[1].state, CellState::Outdated);  // not needed, not updated
    EXPECT_EQ(grid.counters().pixel_queries, 1);
    EXPECT_EQ(grid.counters().cell_updates, 1);

    // Cell 1 whole: queried, a free pixel, partially free.
    EXPECT_FALSE(grid.isOccluded(boxAt({32, 0, 63, 31}), step, nullptr));
    EXPECT_EQ(step, OcclusionStep::InternalWithPixelQuery);
    EXPECT_EQ(cells[1].state, CellState::PartiallyFree);
    EXPECT_FALSE(cells[1].full);

    // Now decided from the states alone, no pixels read.
    const int64_t queries = grid.counters().pixel_queries;
    EXPECT_FALSE(grid.isOccluded(boxAt({32, 0, 63, 31}), step, nullptr));
    EXPECT_EQ(step, OcclusionStep::InternalWithoutPixelQuery);
    EXPECT_TRUE(grid.isOccluded(boxAt({0, 0, 31, 31}), step, nullptr));
    EXPECT_EQ(grid.counters().pixel_queries, queries);

    // A full cell is never set outdated again.
    grid.afterDraw({0, 0, 63, 31}, {0, 0, 63, 31});
    EXPECT_TRUE(cells[0].full);
    EXPECT_EQ(cells[1].state, CellState::Outdated);

    // A border part of cell 1 inside the occluded columns: queried on the part only,
    // occluded; the cell stays outdated (the part says nothing about the rest).
    EXPECT_TRUE(grid.isOccluded(boxAt({10, 0, 40, 31}), step, nullptr));
    EXPECT_EQ(cells[1].state, CellState::Outdated);
    // A part that reaches the free columns: visible, the cell partially free.
    EXPECT_FALSE(grid.isOccluded(boxAt({10, 0, 41, 31}), step, nullptr));
    EXPECT_EQ(step, OcclusionStep::BorderWithPixelQuery);
    EXPECT_EQ(cells[1].state, CellState::PartiallyFree);

    // A cell queried whole and found untouched goes back to completely free.
    grid.begin(&pixels);
    buffer.clear();
    grid.afterDraw({0, 0, 5, 5}, {0, 0, 5, 5});  // drawn, but nothing was written into the buffer
    EXPECT_FALSE(grid.isOccluded(boxAt({0, 0, 31, 31}), step, nullptr));
    EXPECT_EQ(cells[0].state, CellState::CompletelyFree);
}

TEST(LazyGridStates, BusyUpdateQueriesEveryCellOfTheImageAreaAtOnce) {
    OcclusionBuffer buffer;
    buffer.resize(128, 32);
    LazyOcclusionGrid grid;
    grid.configure(128, 32, 32, LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Busy, {});
    const SoftwarePixelQueries pixels(&buffer, nullptr);
    grid.begin(&pixels);
    // Written over cells 0 and 1; the object's box rectangle reaches into cell 2.
    buffer.markOccluded({0, 0, 40, 31});
    grid.afterDraw({0, 0, 40, 31}, {0, 0, 70, 31});
    const auto& cells = grid.cells();
    EXPECT_TRUE(cells[0].full);
    EXPECT_EQ(cells[1].state, CellState::PartiallyFree);
    EXPECT_EQ(cells[2].state, CellState::CompletelyFree);  // read, nothing there
    EXPECT_EQ(cells[3].state, CellState::CompletelyFree);  // outside: not read
    EXPECT_EQ(grid.counters().cell_updates, 3);
    for (const LazyGridCell& cell : cells) EXPECT_NE(cell.state, CellState::Outdated);
    // As the paper states it, every cell of the image area again, the full one too.
    grid.afterDraw({0, 0, 40, 31}, {0, 0, 40, 31});
    EXPECT_EQ(grid.counters().cell_updates, 5);
    // A camera inside an object writes more than its box's rectangle: all of it counts.
    grid.afterDraw({0, 0, 127, 31}, {0, 0, 10, 10});
    EXPECT_EQ(grid.counters().cell_updates, 9);
}

TEST(LazyGridStates, TightBusyUpdateQueriesOnlyWrittenCellsThatAreNotFull) {
    OcclusionBuffer buffer;
    buffer.resize(96, 32);
    LazyOcclusionGrid grid;
    grid.configure(96, 32, 32, LazyGridVariant::OcclusionBuffer, LazyGridUpdate::BusyTight, {});
    const SoftwarePixelQueries pixels(&buffer, nullptr);
    grid.begin(&pixels);
    buffer.markOccluded({0, 0, 40, 31});
    grid.afterDraw({0, 0, 40, 31}, {0, 0, 70, 31});
    const auto& cells = grid.cells();
    EXPECT_TRUE(cells[0].full);
    EXPECT_EQ(cells[1].state, CellState::PartiallyFree);
    EXPECT_EQ(cells[2].state, CellState::CompletelyFree);  // not under the written pixels
    EXPECT_EQ(grid.counters().cell_updates, 2);
    for (const LazyGridCell& cell : cells) EXPECT_NE(cell.state, CellState::Outdated);
    // A full cell is not read again by later draws.
    grid.afterDraw({0, 0, 40, 31}, {0, 0, 40, 31});
    EXPECT_EQ(grid.counters().cell_updates, 3);
}

// A camera at the origin looking along +z, and boxes facing it: a box at depth
// [d, d + 1] covering what its rectangle covers.
struct ZScene {
    IdDepthBuffer zbuffer;
    Camera camera;
    ZScene(int width, int height) {
        camera.position = {0, 0, 0};
        camera.target = {0, 0, 1};
        camera.fov_deg = 90.0;
        camera.aspect = double(width) / height;
        camera.near = 0.1;
        camera.far = 1000.0;
        zbuffer.resize(width, height);
        zbuffer.begin(camera);
    }
    // A box whose front face at depth d covers at least the pixel rectangle r.
    PixelRect drawCovering(int index, const PixelRect& r, double d) {
        const double tan_y = 1.0, tan_x = camera.aspect;  // fov 90
        const double w = zbuffer.width(), h = zbuffer.height();
        // Continuous pixel x -> u -> world x; camera right is world -x (forward x up).
        auto worldX = [&](double px) { return -((2.0 * px / w - 1.0) * tan_x) * d; };
        auto worldY = [&](double py) { return ((1.0 - 2.0 * py / h) * tan_y) * d; };
        const double x_a = worldX(r.x0 + 0.25), x_b = worldX(r.x1 + 0.75);
        const double y_a = worldY(r.y0 + 0.25), y_b = worldY(r.y1 + 0.75);
        const Aabb box{{std::min(x_a, x_b), std::min(y_a, y_b), d},
                       {std::max(x_a, x_b), std::max(y_a, y_b), d + 1.0}};
        EXPECT_TRUE(zbuffer.drawBox(index, box));
        const ScreenRange c = zbuffer.lastDrawCols(), rr = zbuffer.lastDrawRows();
        return {c.lo, rr.lo, c.hi, rr.hi};
    }
};

TEST(LazyGridStates, ZBufferVariantKeepsZfarAndAnOutdatedFlag) {
    ZScene z(64, 32);
    LazyOcclusionGrid grid;
    grid.configure(64, 32, 32, LazyGridVariant::ZBuffer, LazyGridUpdate::Lazy, {});
    const SoftwarePixelQueries pixels(nullptr, &z.zbuffer);
    grid.begin(&pixels);
    const auto& cells = grid.cells();
    EXPECT_EQ(cells[0].zfar, kInf);
    EXPECT_FALSE(cells[0].outdated);

    const PixelRect drawn = z.drawCovering(0, {0, 0, 31, 31}, 10.0);
    grid.afterDraw(drawn, drawn);
    EXPECT_TRUE(cells[0].outdated);
    OcclusionStep step;
    // Behind the box (znear 20 > the cell's farthest depth, about 10): occluded,
    // found by the lazy update of zfar.
    EXPECT_TRUE(grid.isOccluded(boxAt({0, 0, 31, 31}, 20.0), step, nullptr));
    EXPECT_FALSE(cells[0].outdated);
    EXPECT_GT(cells[0].zfar, 9.9);
    EXPECT_LT(cells[0].zfar, 10.5);
    // In front of it: visible from the state alone.
    const int64_t queries = grid.counters().pixel_queries;
    EXPECT_FALSE(grid.isOccluded(boxAt({0, 0, 31, 31}, 5.0), step, nullptr));
    EXPECT_EQ(step, OcclusionStep::InternalWithoutPixelQuery);
    EXPECT_EQ(grid.counters().pixel_queries, queries);
    // A border cell nothing was drawn into: free from the state alone.
    EXPECT_FALSE(grid.isOccluded(boxAt({20, 0, 40, 31}, 20.0), step, nullptr));
    EXPECT_EQ(step, OcclusionStep::BorderWithoutPixelQuery);
}

// Section 6's border-whole read: the whole cell is one pixel query, the part
// read again after it a second one; both are counted (pixel_queries and
// pixels_read), for both variants.
TEST(LazyGridCounters, BorderWholeReadCountsTheWholeCellAndThePartAsTwoQueries) {
    LazyGridExtensions ext;
    ext.border_whole_fraction = 0.3;
    {
        OcclusionBuffer buffer;
        buffer.resize(64, 32);
        LazyOcclusionGrid grid;
        grid.configure(64, 32, 32, LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Lazy, ext);
        const SoftwarePixelQueries pixels(&buffer, nullptr);
        grid.begin(&pixels);
        buffer.markOccluded({0, 0, 15, 31});  // cell 0 half occluded: outdated, not full
        grid.afterDraw({0, 0, 15, 31}, {0, 0, 15, 31});
        OcclusionStep step;
        // A box over columns 0..23 of cell 0: a border part of 24 x 32 > 0.3 of the
        // cell, with free pixels (16..23).
        EXPECT_FALSE(grid.isOccluded(boxAt({0, 0, 23, 31}), step, nullptr));
        EXPECT_EQ(step, OcclusionStep::BorderWithPixelQuery);
        EXPECT_EQ(grid.counters().pixel_queries, 2);
        EXPECT_EQ(grid.counters().pixels_read, 32 * 32 + 24 * 32);
        EXPECT_EQ(grid.counters().cell_updates, 1);
    }
    {
        ZScene z(64, 32);
        LazyOcclusionGrid grid;
        grid.configure(64, 32, 32, LazyGridVariant::ZBuffer, LazyGridUpdate::Lazy, ext);
        const SoftwarePixelQueries pixels(nullptr, &z.zbuffer);
        grid.begin(&pixels);
        const PixelRect drawn = z.drawCovering(0, {0, 0, 15, 31}, 10.0);
        grid.afterDraw(drawn, drawn);
        OcclusionStep step;
        // The cell's farthest depth is +infinity (columns 16.. are empty): not
        // behind the box, so the part is read too.
        EXPECT_FALSE(grid.isOccluded(boxAt({0, 0, 23, 31}, 20.0), step, nullptr));
        EXPECT_EQ(step, OcclusionStep::BorderWithPixelQuery);
        EXPECT_EQ(grid.counters().pixel_queries, 2);
        EXPECT_EQ(grid.counters().pixels_read, 32 * 32 + 24 * 32);
    }
}

// Random buffers, random draws and random boxes, interleaved: the grid's answer
// against brute force over the box's pixels, for both variants and both updates.
void checkAgainstBruteForce(LazyGridVariant variant, LazyGridUpdate update,
                            const LazyGridExtensions& ext, bool exact, uint64_t seed) {
    SeededRandom rng(seed);
    const int width = 40 + int(rng.below(140)), height = 30 + int(rng.below(100));
    const int cell = 1 + int(rng.below(40));
    ZScene z(width, height);
    OcclusionBuffer buffer;
    buffer.resize(width, height);
    LazyOcclusionGrid grid;
    grid.configure(width, height, cell, variant, update, ext);
    const SoftwarePixelQueries pixels(&buffer, &z.zbuffer);
    grid.begin(&pixels);
    auto randomRect = [&](int max_side) {
        const int x0 = int(rng.below(uint64_t(width))), y0 = int(rng.below(uint64_t(height)));
        return PixelRect{x0, y0, std::min(width - 1, x0 + int(rng.below(uint64_t(max_side)))),
                         std::min(height - 1, y0 + int(rng.below(uint64_t(max_side))))};
    };
    for (int step_index = 0; step_index < 200; ++step_index) {
        if (rng.uniform() < 0.3) {
            const PixelRect written =
                z.drawCovering(step_index, randomRect(width / 2), rng.uniform(2.0, 50.0));
            buffer.markDrawn(z.zbuffer, written);
            grid.afterDraw(written, written);
            continue;
        }
        const PixelRect rect = randomRect(width);
        const double znear = rng.uniform(1.0, 60.0);
        bool all_hidden = true;
        for (int py = rect.y0; py <= rect.y1; ++py)
            for (int px = rect.x0; px <= rect.x1; ++px) {
                const bool hidden = variant == LazyGridVariant::OcclusionBuffer
                                        ? buffer.occluded(px, py)
                                        : z.zbuffer.depthRow(py)[px] < znear;
                all_hidden = all_hidden && hidden;
            }
        OcclusionStep step;
        std::vector<CellTouch> trace;
        const bool occluded = grid.isOccluded({rect, znear, znear + 1.0}, step, &trace);
        if (occluded) {
            EXPECT_TRUE(all_hidden) << "rated occluded with a free pixel, step " << step_index;
        }
        if (exact) {
            EXPECT_EQ(occluded, all_hidden) << "step " << step_index;
        }
        EXPECT_FALSE(trace.empty());
    }
}

TEST(LazyGridExactness, OccludedExactlyWhenEveryPixelOfTheBoxIsHidden) {
    for (uint64_t seed : test::seedsToRun(1, 60)) {
        test::withSeed(seed, [&] {
            checkAgainstBruteForce(LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Lazy, {}, true,
                                   seed);
            checkAgainstBruteForce(LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Busy, {}, true,
                                   seed);
            checkAgainstBruteForce(LazyGridVariant::OcclusionBuffer, LazyGridUpdate::BusyTight, {},
                                   true, seed);
            checkAgainstBruteForce(LazyGridVariant::ZBuffer, LazyGridUpdate::Lazy, {}, true, seed);
        });
    }
}

TEST(LazyGridExactness, SectionSixExtensionsNeverRateAFreeBoxOccluded) {
    for (uint64_t seed : test::seedsToRun(1, 60)) {
        test::withSeed(seed, [&] {
            SeededRandom rng(seed * 7919);
            LazyGridExtensions ext;
            ext.probability_threshold = rng.uniform() < 0.5 ? rng.uniform(0.05, 1.0) : 0.0;
            ext.border_whole_fraction = rng.uniform() < 0.5 ? rng.uniform(0.05, 1.0) : 0.0;
            ext.large_box_fraction = rng.uniform() < 0.5 ? rng.uniform(0.05, 1.0) : 0.0;
            for (auto variant : {LazyGridVariant::OcclusionBuffer, LazyGridVariant::ZBuffer})
                checkAgainstBruteForce(variant, LazyGridUpdate::Lazy, ext, false, seed);
            checkAgainstBruteForce(LazyGridVariant::OcclusionBuffer, LazyGridUpdate::Busy, ext,
                                   false, seed);
        });
    }
}

// The paper's horizon (Fig. 1 and section 3.1): a wall whose top edge runs
// through a row of cells, so those cells are partially free. A box behind it is
// occluded only when its border cells' parts below the edge are all hidden.
TEST(LazyGridHorizon, ABoxBehindAHorizonIsOccludedOnlyWhenAllOfItIsHidden) {
    for (auto variant : {LazyGridVariant::OcclusionBuffer, LazyGridVariant::ZBuffer}) {
        SCOPED_TRACE(variant == LazyGridVariant::ZBuffer ? "z-buffer" : "occlusion buffer");
        ZScene z(128, 96);
        OcclusionBuffer buffer;
        buffer.resize(128, 96);
        LazyOcclusionGrid grid;
        grid.configure(128, 96, 32, variant, LazyGridUpdate::Lazy, {});
        const SoftwarePixelQueries pixels(&buffer, &z.zbuffer);
        grid.begin(&pixels);
        // The wall covers rows 50..95: its horizon is inside the cell row 32..63.
        const PixelRect wall = z.drawCovering(0, {0, 50, 127, 95}, 10.0);
        EXPECT_LE(wall.y0, 50);
        EXPECT_GE(wall.y0, 49);
        buffer.markDrawn(z.zbuffer, wall);
        grid.afterDraw(wall, wall);
        const int horizon = [&] {
            for (int py = 0; py < 96; ++py)
                if (std::isfinite(z.zbuffer.depthRow(py)[64])) return py;
            return 96;
        }();
        OcclusionStep step;
        // Wholly below the horizon, behind the wall: occluded, although the cells
        // its top border lies in are partially free.
        EXPECT_TRUE(grid.isOccluded(boxAt({40, horizon, 90, 80}, 20.0), step, nullptr));
        // The cell the horizon runs through (columns and rows 32..63) is not full.
        EXPECT_FALSE(grid.cells()[1 * 4 + 1].full);
        // One row above the horizon: visible, found by a border pixel query.
        EXPECT_FALSE(grid.isOccluded(boxAt({40, horizon - 1, 90, 80}, 20.0), step, nullptr));
        EXPECT_EQ(step, OcclusionStep::BorderWithPixelQuery);
        // In front of the wall (z-buffer only: the occlusion buffer cannot tell).
        if (variant == LazyGridVariant::ZBuffer) {
            EXPECT_FALSE(grid.isOccluded(boxAt({40, horizon, 90, 80}, 5.0), step, nullptr));
        }
    }
}

}  // namespace
}  // namespace gridcull
