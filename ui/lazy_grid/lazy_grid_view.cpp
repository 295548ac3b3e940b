#include "ui/lazy_grid/lazy_grid_view.h"

#include <algorithm>
#include <limits>

namespace gridcull {

namespace {

// Hues the object states (blue, sky blue, vermillion, dim grey) and the camera
// (yellow) do not use.
constexpr Swatch kBluishGreen = Swatch::BluishGreen;
constexpr Swatch kOrange = Swatch::Orange;
constexpr Swatch kReddishPurple = Swatch::ReddishPurple;
constexpr Swatch kGrey = Swatch::Grey;
constexpr Swatch kWhite = Swatch::White;

}  // namespace

int lazyCellClassesOf(LazyGridVariant variant, LazyCellClass* out) {
    if (variant == LazyGridVariant::ZBuffer) {
        out[0] = LazyCellClass::ZfarAtZmax;
        out[1] = LazyCellClass::ZfarFinite;
        out[2] = LazyCellClass::Outdated;
        return 3;
    }
    out[0] = LazyCellClass::CompletelyFree;
    out[1] = LazyCellClass::PartiallyFree;
    out[2] = LazyCellClass::Full;
    out[3] = LazyCellClass::Outdated;
    return 4;
}

LazyCellClass lazyCellClassOf(const LazyGridCell& cell, LazyGridVariant variant) {
    if (variant == LazyGridVariant::ZBuffer) {
        if (cell.outdated) return LazyCellClass::Outdated;
        return cell.zfar == std::numeric_limits<double>::infinity() ? LazyCellClass::ZfarAtZmax
                                                                    : LazyCellClass::ZfarFinite;
    }
    // The full flag overrides the state (culling/lazy_grid/lazy_grid.h).
    if (cell.full) return LazyCellClass::Full;
    switch (cell.state) {
        case CellState::CompletelyFree:
            return LazyCellClass::CompletelyFree;
        case CellState::PartiallyFree:
            return LazyCellClass::PartiallyFree;
        case CellState::Outdated:
            return LazyCellClass::Outdated;
    }
    return LazyCellClass::Outdated;
}

const char* lazyCellClassName(LazyCellClass c) {
    switch (c) {
        case LazyCellClass::CompletelyFree:
            return "completely free";
        case LazyCellClass::PartiallyFree:
            return "partially free";
        case LazyCellClass::Full:
            return "full";
        case LazyCellClass::Outdated:
            return "outdated";
        case LazyCellClass::ZfarAtZmax:
            return "zfar = zmax";
        case LazyCellClass::ZfarFinite:
            return "zfar < zmax";
    }
    return "?";
}

const char* lazyCellClassMeaning(LazyCellClass c) {
    switch (c) {
        case LazyCellClass::CompletelyFree:
            return "no pixel occluded";
        case LazyCellClass::PartiallyFree:
            return "some pixels occluded";
        case LazyCellClass::Full:
            return "every pixel occluded";
        case LazyCellClass::Outdated:
            return "drawn into, not read since";
        case LazyCellClass::ZfarAtZmax:
            return "some pixel still empty";
        case LazyCellClass::ZfarFinite:
            return "all drawn; nearer = denser";
    }
    return "";
}

Swatch lazyCellClassSwatch(LazyCellClass c) {
    switch (c) {
        case LazyCellClass::CompletelyFree:
        case LazyCellClass::ZfarAtZmax:
            return kBluishGreen;
        case LazyCellClass::PartiallyFree:
            return kOrange;
        case LazyCellClass::Full:
        case LazyCellClass::ZfarFinite:
            return kReddishPurple;
        case LazyCellClass::Outdated:
            return kGrey;
    }
    return kWhite;
}

float lazyCellClassFillAlpha(LazyCellClass c) {
    switch (c) {
        case LazyCellClass::CompletelyFree:
        case LazyCellClass::ZfarAtZmax:
            return 0.08f;
        case LazyCellClass::PartiallyFree:
            return 0.16f;
        case LazyCellClass::Full:
        case LazyCellClass::ZfarFinite:
            return 0.20f;
        case LazyCellClass::Outdated:
            return 0.0f;
    }
    return 0.0f;
}

bool lazyCellClassHatched(LazyCellClass c) {
    return c == LazyCellClass::Outdated;
}

LazyCellCounts countLazyCells(const LazyGridSnapshot& snapshot) {
    LazyCellCounts counts;
    for (const LazyGridCell& cell : snapshot.cells)
        ++counts.count[int(lazyCellClassOf(cell, snapshot.variant))];
    return counts;
}

PixelRect lazyCellPixels(const LazyGridSnapshot& snapshot, int cx, int cy) {
    const int s = snapshot.cell_size;
    return {cx * s, cy * s, std::min(snapshot.width, (cx + 1) * s) - 1,
            std::min(snapshot.height, (cy + 1) * s) - 1};
}

const char* lazyGridLayerName(LazyGridLayer layer) {
    switch (layer) {
        case LazyGridLayer::Cells:
            return "cells";
        case LazyGridLayer::GridLines:
            return "grid";
        case LazyGridLayer::Touched:
            return "touched";
        case LazyGridLayer::PixelQueries:
            return "queries";
        case LazyGridLayer::ScreenRect:
            return "rect";
    }
    return "?";
}

const char* lazyGridLayerMeaning(LazyGridLayer layer) {
    switch (layer) {
        case LazyGridLayer::Cells:
            return "cell states, as keyed above";
        case LazyGridLayer::GridLines:
            return "cell lines, image border";
        case LazyGridLayer::Touched:
            return "internal solid, border dashed";
        case LazyGridLayer::PixelQueries:
            return "cells whose pixels were read (X)";
        case LazyGridLayer::ScreenRect:
            return "the tested box's rectangle";
    }
    return "";
}

Swatch lazyGridLayerSwatch(LazyGridLayer layer) {
    switch (layer) {
        case LazyGridLayer::Cells:
            return kReddishPurple;
        case LazyGridLayer::GridLines:
            return Swatch::LineGrey;
        case LazyGridLayer::Touched:
        case LazyGridLayer::PixelQueries:
            return kWhite;
        case LazyGridLayer::ScreenRect:
            return Swatch::Yellow;  // the camera's: the box as the culling camera sees it
    }
    return kWhite;
}

Swatch lazyFreeTouchSwatch() {
    return kBluishGreen;
}

std::vector<OverlayPreset> lazyGridOverlayPresets() {
    return {OverlayPreset::Occlusion, OverlayPreset::Traversal, OverlayPreset::All};
}

void lazyGridApplyPreset(LazyGridViewState& view, OverlayPreset preset) {
    using L = LazyGridLayer;
    const auto set = [&](auto&& on) {
        for (int l = 0; l < kLazyGridLayerCount; ++l) view.show[l] = on(L(l));
    };
    switch (preset) {
        case OverlayPreset::Occlusion:
            set([](L l) { return l == L::Cells || l == L::GridLines; });
            break;
        case OverlayPreset::Traversal:
            set([](L l) { return l != L::Cells; });
            break;
        case OverlayPreset::All:
            set([](L) { return true; });
            break;
        case OverlayPreset::Tbvs:  // not offered: the toggles stay
            break;
    }
}

LazyDecision describeLazyDecision(const LazyGridSnapshot& snapshot, int object_index) {
    LazyDecision d;
    d.test = decidingTest(snapshot, object_index);
    if (!d.test) return d;
    d.own_box = d.test->node == snapshot.leaf_of_object[size_t(object_index)];
    const int32_t end = d.test->first_touch + d.test->touch_count;
    for (int32_t k = d.test->first_touch; k < end; ++k) {
        const CellTouch& touch = snapshot.touches[size_t(k)];
        // A queued cell is touched again by its pixel query (or the probability
        // rule); count each cell once, at its first touch.
        const bool first =
            touch.kind == CellTouchKind::State || touch.kind == CellTouchKind::Queued;
        if (first) ++(touch.role == CellRole::Internal ? d.internal : d.border);
        d.pixel_queries += touch.kind == CellTouchKind::PixelQuery ? 1 : 0;
        d.probability += touch.kind == CellTouchKind::Probability ? 1 : 0;
    }
    return d;
}

}  // namespace gridcull
