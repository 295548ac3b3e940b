// The lazy occlusion grid: H. Hey, R. F. Tobler, W. Purgathofer, "Real-time
// occlusion culling with a lazy occlusion grid" (2001), sections 3 (3.1 the
// occlusion-buffer variant, Fig. 2; 3.2 the z-buffer variant, Fig. 3), the busy
// update of section 7, and the extensions of section 6.
//
// A coarse grid of cells (cell_size x cell_size pixels; the last column and row
// may be narrower) over an occlusion buffer (one bit per pixel) or a z-buffer,
// read through PixelQueries (culling/api/image_target.h): by default the shared
// software rasterizer's (culling/raster/), sampled at pixel centres at the
// view's resolution. isOccluded() rates a box's screen rectangle occluded or
// potentially visible, reading cell states first and pixels only when the states
// cannot decide (a "pixel-level query"); cells are updated lazily, only when a
// test needs them and they are outdated.
//
// Paper names: completely free / partially free / full / outdated cell states,
// the full flag, internal and border cells of a bounding volume, zfar and the
// outdated flag per cell, the four steps internalCellIsFreeWithoutPixelquery,
// borderCellIsFreeWithoutPixelquery, internalCellIsFreeWithPixelquery,
// borderCellIsFreeWithPixelquery.
//
// Departures from the paper, and why:
// - After drawing, the cells marked outdated are those under the pixels the draw
//   actually wrote (the rasterizer's written rectangle), not under the whole
//   bounding volume's rectangle: tighter, and still every changed pixel's cell.
// - An internal cell's pixel query reads the whole cell anyway, so it sets the
//   cell completely free when no pixel is occluded (the paper sets partially
//   free); border steps can then answer from the state alone. Busy update sets
//   all three states exactly the same way.
// - In the z-buffer variant an empty pixel has depth +infinity (zmax); a box is
//   in front where znear <= zfar, ties counted as visible.
// - The z-buffer variant's borderCellIsFreeWithoutPixelquery returns "free" for a
//   border cell that nothing has been drawn into (drawn_area 0, the occlusion-
//   buffer variant's completely free), not for any cell with zfar = zmax: zfar is
//   the farthest pixel, so zfar = zmax only says that some pixel of the cell is
//   empty, perhaps outside the box, and an outdated cell's zmax is stale. Taken
//   literally, every box with a border cell drawn into lazily would be visible.
// - Section 6's extensions, each off by default (LazyGridExtensions): a cell
//   whose drawn area (the sum of the written rectangles' areas inside it, overlaps
//   counted twice) is below probability_threshold of its area is rated free
//   without a pixel query; a border cell whose intersection with the box exceeds
//   border_whole_fraction of the cell is queried whole, so its state is updated
//   and a full cell found, and when the cell is not full the intersection is
//   read again (two pixel queries, both counted); a
//   box whose rectangle exceeds large_box_fraction of the image treats its border
//   cells as internal cells (tested whole: never culls more). All three only ever
//   answer "visible" more often than the exact test, so none breaks conservatism.
//
// Conservative with respect to the image it samples: a box is rated occluded only
// when every pixel centre in its rectangle is occluded (occlusion buffer) or holds
// a depth < znear (z-buffer). With the occlusion-buffer variant the caller must
// only have drawn objects wholly in front of the box (the traversal of Fig. 6).
//
// Cost: isOccluded O(cells of the rectangle), plus O(pixels) per pixel query.
// Nothing allocates after configure().
#pragma once
#include <cstdint>
#include <limits>
#include <vector>

#include "culling/raster/screen_mapping.h"

namespace gridcull {

class PixelQueries;

enum class LazyGridVariant : uint8_t { OcclusionBuffer, ZBuffer };
// Lazy: section 3's lazy update. Busy: section 7's busy update as the paper
// states it, "everytime after an object has been drawn the occlusion states of all
// cells in its image area are being updated" (its box's rectangle, full cells
// included). BusyTight: a stronger busy baseline of ours, which updates only the
// cells under the pixels the draw wrote and skips cells already full.
enum class LazyGridUpdate : uint8_t { Lazy, Busy, BusyTight };

// Occlusion-buffer variant states; `full` is a separate flag that overrides them.
enum class CellState : uint8_t { CompletelyFree, PartiallyFree, Outdated };

struct LazyGridCell {
    CellState state = CellState::CompletelyFree;            // occlusion-buffer variant
    bool full = false;                                      // occlusion-buffer variant
    bool outdated = false;                                  // z-buffer variant
    double zfar = std::numeric_limits<double>::infinity();  // z-buffer variant; +inf = zmax
    double drawn_area = 0.0;  // pixels of written rectangles inside this cell (section 6)
};

// The step of Fig. 2 / Fig. 3 that decided a test; Occluded when none found a
// free cell, OffScreen when the rectangle holds no pixel at all.
enum class OcclusionStep : uint8_t {
    InternalWithoutPixelQuery,
    BorderWithoutPixelQuery,
    InternalWithPixelQuery,
    BorderWithPixelQuery,
    Occluded,
    OffScreen,
};
const char* occlusionStepName(OcclusionStep step);

// How one cell took part in one test.
enum class CellRole : uint8_t { Internal, Border };
enum class CellTouchKind : uint8_t {
    State,        // read its state only
    Queued,       // read its state, put on a pixel-query list
    PixelQuery,   // pixels read (the whole cell, or cell and box for a border cell)
    Probability,  // rated free by the section 6 probability threshold, no pixels read
};
struct CellTouch {
    int32_t cell = 0;
    CellRole role = CellRole::Internal;
    CellTouchKind kind = CellTouchKind::State;
    bool free = false;  // this touch found the cell (or its part in the box) free
};

struct LazyGridExtensions {
    double probability_threshold = 0.0;  // (0, 1]; 0 = off
    double border_whole_fraction = 0.0;  // (0, 1]; 0 = off
    double large_box_fraction = 0.0;     // (0, 1]; 0 = off
};

struct LazyGridCounters {
    int64_t pixel_queries = 0;  // cell updates and border queries that read pixels
    int64_t cell_updates = 0;   // of those: whole cells read to set their state / zfar
    int64_t pixels_read = 0;
    int64_t occlusion_tests = 0;
    int64_t probability_skips = 0;  // pixel queries saved by the probability threshold
};

class LazyOcclusionGrid {
public:
    // Sizes the grid for a width x height image and cells of cell_size pixels
    // (each >= 1). Allocates only when a size changes.
    void configure(int width, int height, int cell_size, LazyGridVariant variant,
                   LazyGridUpdate update, const LazyGridExtensions& extensions);
    // Every cell completely free / zfar = zmax, nothing outdated; counters zeroed.
    // `pixels` answers the pixel-level queries (culling/api/image_target.h) and must
    // be cleared alongside; it must outlive the frame. O(cells).
    void begin(const PixelQueries* pixels);

    // Fig. 2 (occlusion buffer) or Fig. 3 (z-buffer) for a box at `box`, lazily
    // updating the cells it needs. When `trace` is given, every cell touched is
    // appended to it. Returns true when the box is occluded.
    bool isOccluded(const BoxOnScreen& box, OcclusionStep& step, std::vector<CellTouch>* trace);

    // After an object was drawn into the buffers over `written` pixels, with
    // `image_area` its box's rectangle: lazy update marks the cells under `written`
    // outdated; busy update queries every cell under `image_area` and `written` at
    // once; tight busy update queries the cells under `written` that are not full.
    void afterDraw(const PixelRect& written, const PixelRect& image_area);

    int cellsX() const { return cells_x_; }
    int cellsY() const { return cells_y_; }
    int cellSize() const { return cell_size_; }
    LazyGridVariant variant() const { return variant_; }
    LazyGridUpdate update() const { return update_; }
    const std::vector<LazyGridCell>& cells() const { return cells_; }
    const LazyGridCounters& counters() const { return counters_; }
    // The pixels of cell (cx, cy), clipped to the image.
    PixelRect cellRect(int cx, int cy) const;
    // The cells a pixel rectangle touches, as a rectangle of cell indices.
    PixelRect cellsOf(const PixelRect& pixels) const;

    // Splits the cells a box rectangle touches into its internal cells (wholly
    // inside it; every touched cell with the large-box extension and a large box)
    // and its border cells. isOccluded calls it; tests and the window may too.
    void classify(const PixelRect& rect);
    const std::vector<int32_t>& internalCells() const { return internal_cells_; }
    const std::vector<int32_t>& borderCells() const { return border_cells_; }

private:
    bool isOccludedOcclusionBuffer(const BoxOnScreen& box, std::vector<CellTouch>* trace,
                                   OcclusionStep& step);
    bool isOccludedZBuffer(const BoxOnScreen& box, std::vector<CellTouch>* trace,
                           OcclusionStep& step);
    // Section 6: rates the cell free without reading pixels when little was drawn
    // into it (counted, and traced as CellTouchKind::Probability).
    bool ratedFreeByProbability(int index, CellRole role, std::vector<CellTouch>* trace);
    // Pixel queries. Each counts one query and the pixels it reads.
    long long queryFree(const PixelRect& rect);  // free pixels (occlusion buffer)
    double queryFar(const PixelRect& rect);      // farthest depth (z-buffer)
    // Reads a whole cell and sets its state (or zfar) exactly.
    void updateCell(int index);

    LazyGridVariant variant_ = LazyGridVariant::OcclusionBuffer;
    LazyGridUpdate update_ = LazyGridUpdate::Lazy;
    LazyGridExtensions extensions_;
    int width_ = 0, height_ = 0, cell_size_ = 32, cells_x_ = 0, cells_y_ = 0;
    std::vector<LazyGridCell> cells_;
    std::vector<int32_t> internal_cells_, border_cells_;            // of the box under test
    std::vector<int32_t> internal_query_list_, border_query_list_;  // the paper's lists
    const PixelQueries* pixels_ = nullptr;
    LazyGridCounters counters_;
};

}  // namespace gridcull
