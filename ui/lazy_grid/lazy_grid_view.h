// What the window shows of the lazy occlusion grid (lazy-grid, lazy-grid-z,
// busy-grid; culling/lazy_grid/lazy_grid_snapshot.h) and the colours it uses, shared by the
// lazy grid panel (ui/lazy_grid/lazy_grid_panel.h), which changes the view state and keys
// the colours, and the overlay (ui/lazy_grid/lazy_grid_overlay.h), which draws it.
//
// Cell classes use the paper's state names (Hey, Tobler & Purgathofer, section 3):
// completely free, partially free, full and outdated for the occlusion-buffer
// variant; zfar = zmax, zfar < zmax and outdated for the z-buffer variant. Colours
// are the palette's hues (ui/palette.h) that the object states and the camera
// leave free, or greys, so a cell never reads as an object's state.
#pragma once
#include <cstdint>

#include <vector>

#include "culling/lazy_grid/lazy_grid_snapshot.h"
#include "ui/overlay_preset.h"
#include "ui/palette.h"

namespace gridcull {

// A cell at the end of a frame, as the overlay colours it.
enum class LazyCellClass : uint8_t {
    CompletelyFree,  // occlusion buffer: no pixel occluded
    PartiallyFree,   // occlusion buffer: some pixels occluded, not all
    Full,            // occlusion buffer: the full flag, every pixel occluded
    Outdated,        // either variant: drawn into since its state was last read
    ZfarAtZmax,      // z-buffer: some pixel still empty (zfar = zmax)
    ZfarFinite,      // z-buffer: every pixel drawn, zfar the farthest of them
};
constexpr int kLazyCellClassCount = 6;

// The classes a variant's cells can be in, in legend order; returns how many
// were written to `out` (at most kLazyCellClassCount).
int lazyCellClassesOf(LazyGridVariant variant, LazyCellClass* out);
LazyCellClass lazyCellClassOf(const LazyGridCell& cell, LazyGridVariant variant);
const char* lazyCellClassName(LazyCellClass c);
const char* lazyCellClassMeaning(LazyCellClass c);
// Each cell is drawn as a faint fill and a solid outline just inside it in its
// class colour: the outline carries the colour, so the fill can stay faint
// enough that the objects under it keep their state colours. Outdated cells are
// hatched instead of filled (their state is unknown until a test reads them).
Swatch lazyCellClassSwatch(LazyCellClass c);
float lazyCellClassFillAlpha(LazyCellClass c);  // 0: not filled
bool lazyCellClassHatched(LazyCellClass c);

// Cells per class at the end of the frame. O(cells).
struct LazyCellCounts {
    int64_t count[kLazyCellClassCount] = {};
    int64_t of(LazyCellClass c) const { return count[int(c)]; }
};
LazyCellCounts countLazyCells(const LazyGridSnapshot& snapshot);

// The pixels of cell (cx, cy) of the snapshot's image, clipped to it (the last
// column and row may be narrower), as LazyOcclusionGrid::cellRect.
PixelRect lazyCellPixels(const LazyGridSnapshot& snapshot, int cx, int cy);

// The layers of the lazy grid overlay, each a toggle in the panel.
enum class LazyGridLayer {
    Cells,         // every cell filled by its class
    GridLines,     // cell boundaries and the image's border
    Touched,       // the focused object's deciding test: internal cells solid, border dashed
    PixelQueries,  // of those, the cells whose pixels were read (a cross)
    ScreenRect,    // the deciding test's screen rectangle
};
constexpr int kLazyGridLayerCount = 5;

const char* lazyGridLayerName(LazyGridLayer layer);
const char* lazyGridLayerMeaning(LazyGridLayer layer);
Swatch lazyGridLayerSwatch(LazyGridLayer layer);
// The colour of a touched cell the test found free (the cell that made the box
// potentially visible), instead of lazyGridLayerSwatch(Touched).
Swatch lazyFreeTouchSwatch();

struct LazyGridViewState {
    // The "all" preset's; a family view starts with its first preset instead.
    bool show[kLazyGridLayerCount] = {true, true, true, true, true};
    bool shown(LazyGridLayer l) const { return show[int(l)]; }
};

// The overlay presets, the first the one a view starts with: "occlusion only"
// (the cells by state, what the grid knows of the image, and the grid lines),
// "traversal" (the focused object's deciding test: the cells it touched, those
// whose pixels it read, its screen rectangle, over the grid lines) and "all".
// No TBVs: the lazy grid has none.
std::vector<OverlayPreset> lazyGridOverlayPresets();
void lazyGridApplyPreset(LazyGridViewState& view, OverlayPreset preset);

// The focused object's deciding test (decidingTest) summed up for the panel.
struct LazyDecision {
    const LazyGridTest* test = nullptr;  // null: nothing on its path was tested
    bool own_box = false;                // the test was of the object's own leaf box
    int internal = 0, border = 0;        // cells touched in each role
    int pixel_queries = 0;               // touches that read pixels
    int probability = 0;                 // touches rated free by section 6's threshold
};
// O(touches of the test). object_index indexes Scene::objects.
LazyDecision describeLazyDecision(const LazyGridSnapshot& snapshot, int object_index);

}  // namespace gridcull
