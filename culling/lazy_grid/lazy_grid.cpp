#include "culling/lazy_grid/lazy_grid.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "culling/api/image_target.h"

namespace gridcull {

const char* occlusionStepName(OcclusionStep step) {
    switch (step) {
        case OcclusionStep::InternalWithoutPixelQuery:
            return "internalCellIsFreeWithoutPixelquery";
        case OcclusionStep::BorderWithoutPixelQuery:
            return "borderCellIsFreeWithoutPixelquery";
        case OcclusionStep::InternalWithPixelQuery:
            return "internalCellIsFreeWithPixelquery";
        case OcclusionStep::BorderWithPixelQuery:
            return "borderCellIsFreeWithPixelquery";
        case OcclusionStep::Occluded:
            return "occluded (no step found a free cell)";
        case OcclusionStep::OffScreen:
            return "off screen (no pixel)";
    }
    return "unknown";
}

void LazyOcclusionGrid::configure(int width, int height, int cell_size, LazyGridVariant variant,
                                  LazyGridUpdate update, const LazyGridExtensions& extensions) {
    assert(width >= 1 && height >= 1 && cell_size >= 1);
    variant_ = variant;
    update_ = update;
    extensions_ = extensions;
    width_ = width;
    height_ = height;
    cell_size_ = cell_size;
    cells_x_ = (width + cell_size - 1) / cell_size;
    cells_y_ = (height + cell_size - 1) / cell_size;
    const size_t count = size_t(cells_x_) * size_t(cells_y_);
    if (cells_.size() != count) {
        cells_.assign(count, LazyGridCell{});
        for (auto* list :
             {&internal_cells_, &border_cells_, &internal_query_list_, &border_query_list_})
            list->reserve(count);
    }
}

void LazyOcclusionGrid::begin(const PixelQueries* pixels) {
    assert(pixels);
    pixels_ = pixels;
    std::fill(cells_.begin(), cells_.end(), LazyGridCell{});
    counters_ = LazyGridCounters{};
}

PixelRect LazyOcclusionGrid::cellRect(int cx, int cy) const {
    return {cx * cell_size_, cy * cell_size_, std::min(width_, (cx + 1) * cell_size_) - 1,
            std::min(height_, (cy + 1) * cell_size_) - 1};
}

PixelRect LazyOcclusionGrid::cellsOf(const PixelRect& pixels) const {
    const PixelRect r = pixels.intersect({0, 0, width_ - 1, height_ - 1});
    if (r.empty()) return {};
    return {r.x0 / cell_size_, r.y0 / cell_size_, r.x1 / cell_size_, r.y1 / cell_size_};
}

void LazyOcclusionGrid::classify(const PixelRect& rect) {
    internal_cells_.clear();
    border_cells_.clear();
    const PixelRect cells = cellsOf(rect);
    const bool all_internal =
        extensions_.large_box_fraction > 0.0 &&
        double(rect.area()) > extensions_.large_box_fraction * double(width_) * height_;
    for (int cy = cells.y0; cy <= cells.y1; ++cy)
        for (int cx = cells.x0; cx <= cells.x1; ++cx) {
            const int index = cy * cells_x_ + cx;
            if (all_internal || rect.contains(cellRect(cx, cy)))
                internal_cells_.push_back(index);
            else
                border_cells_.push_back(index);
        }
}

bool LazyOcclusionGrid::ratedFreeByProbability(int index, CellRole role,
                                               std::vector<CellTouch>* trace) {
    if (extensions_.probability_threshold <= 0.0) return false;
    const LazyGridCell& cell = cells_[size_t(index)];
    const PixelRect rect = cellRect(index % cells_x_, index / cells_x_);
    if (!(cell.drawn_area < extensions_.probability_threshold * double(rect.area()))) return false;
    ++counters_.probability_skips;
    if (trace) trace->push_back({index, role, CellTouchKind::Probability, true});
    return true;
}

long long LazyOcclusionGrid::queryFree(const PixelRect& rect) {
    ++counters_.pixel_queries;
    counters_.pixels_read += rect.area();
    return pixels_->countFree(rect);
}

double LazyOcclusionGrid::queryFar(const PixelRect& rect) {
    ++counters_.pixel_queries;
    counters_.pixels_read += rect.area();
    return pixels_->farthestDepth(rect);
}

void LazyOcclusionGrid::updateCell(int index) {
    LazyGridCell& cell = cells_[size_t(index)];
    const PixelRect rect = cellRect(index % cells_x_, index / cells_x_);
    ++counters_.cell_updates;
    if (variant_ == LazyGridVariant::ZBuffer) {
        cell.zfar = queryFar(rect);
        cell.outdated = false;
        return;
    }
    const long long free = queryFree(rect);
    if (free == 0) {
        cell.full = true;
        cell.state = CellState::PartiallyFree;  // irrelevant once full
    } else {
        cell.state = free == rect.area() ? CellState::CompletelyFree : CellState::PartiallyFree;
    }
}

void LazyOcclusionGrid::afterDraw(const PixelRect& written, const PixelRect& image_area) {
    const PixelRect r = written.intersect({0, 0, width_ - 1, height_ - 1});
    if (!r.empty()) {
        const PixelRect cells = cellsOf(r);
        for (int cy = cells.y0; cy <= cells.y1; ++cy)
            for (int cx = cells.x0; cx <= cells.x1; ++cx) {
                const int index = cy * cells_x_ + cx;
                LazyGridCell& cell = cells_[size_t(index)];
                cell.drawn_area += double(r.intersect(cellRect(cx, cy)).area());
                if (update_ == LazyGridUpdate::BusyTight) {
                    if (!cell.full) updateCell(index);
                } else if (update_ == LazyGridUpdate::Busy) {
                    // below, over the whole image area
                } else if (variant_ == LazyGridVariant::ZBuffer) {
                    cell.outdated = true;
                } else if (!cell.full) {
                    cell.state = CellState::Outdated;
                }
            }
    }
    if (update_ != LazyGridUpdate::Busy) return;
    // The image area, grown to the written pixels (a camera inside an object
    // writes the whole image while its box's rectangle may be smaller).
    PixelRect area = image_area;
    if (area.empty()) {
        area = r;
    } else if (!r.empty()) {
        area = {std::min(area.x0, r.x0), std::min(area.y0, r.y0), std::max(area.x1, r.x1),
                std::max(area.y1, r.y1)};
    }
    if (area.empty()) return;
    const PixelRect cells = cellsOf(area);
    for (int cy = cells.y0; cy <= cells.y1; ++cy)
        for (int cx = cells.x0; cx <= cells.x1; ++cx) updateCell(cy * cells_x_ + cx);
}

bool LazyOcclusionGrid::isOccluded(const BoxOnScreen& box, OcclusionStep& step,
                                   std::vector<CellTouch>* trace) {
    ++counters_.occlusion_tests;
    if (box.rect.empty()) {
        step = OcclusionStep::OffScreen;
        return true;
    }
    classify(box.rect);
    return variant_ == LazyGridVariant::ZBuffer ? isOccludedZBuffer(box, trace, step)
                                                : isOccludedOcclusionBuffer(box, trace, step);
}

namespace {

void touch(std::vector<CellTouch>* trace, int cell, CellRole role, CellTouchKind kind, bool free) {
    if (trace) trace->push_back({cell, role, kind, free});
}

}  // namespace

bool LazyOcclusionGrid::isOccludedOcclusionBuffer(const BoxOnScreen& box,
                                                  std::vector<CellTouch>* trace,
                                                  OcclusionStep& step) {
    internal_query_list_.clear();
    border_query_list_.clear();
    // internalCellIsFreeWithoutPixelquery
    step = OcclusionStep::InternalWithoutPixelQuery;
    for (int index : internal_cells_) {
        const LazyGridCell& cell = cells_[size_t(index)];
        if (cell.full) {
            touch(trace, index, CellRole::Internal, CellTouchKind::State, false);
        } else if (cell.state == CellState::Outdated) {
            touch(trace, index, CellRole::Internal, CellTouchKind::Queued, false);
            internal_query_list_.push_back(index);
        } else {
            touch(trace, index, CellRole::Internal, CellTouchKind::State, true);
            return false;
        }
    }
    // borderCellIsFreeWithoutPixelquery
    step = OcclusionStep::BorderWithoutPixelQuery;
    for (int index : border_cells_) {
        const LazyGridCell& cell = cells_[size_t(index)];
        if (cell.full) {
            touch(trace, index, CellRole::Border, CellTouchKind::State, false);
        } else if (cell.state == CellState::CompletelyFree) {
            touch(trace, index, CellRole::Border, CellTouchKind::State, true);
            return false;
        } else {
            touch(trace, index, CellRole::Border, CellTouchKind::Queued, false);
            border_query_list_.push_back(index);
        }
    }
    // internalCellIsFreeWithPixelquery: the lazy update of outdated internal cells.
    step = OcclusionStep::InternalWithPixelQuery;
    for (int index : internal_query_list_) {
        LazyGridCell& cell = cells_[size_t(index)];
        if (ratedFreeByProbability(index, CellRole::Internal, trace)) return false;
        updateCell(index);
        touch(trace, index, CellRole::Internal, CellTouchKind::PixelQuery, !cell.full);
        if (!cell.full) return false;
    }
    // borderCellIsFreeWithPixelquery: only the part of the cell inside the box.
    step = OcclusionStep::BorderWithPixelQuery;
    for (int index : border_query_list_) {
        LazyGridCell& cell = cells_[size_t(index)];
        if (ratedFreeByProbability(index, CellRole::Border, trace)) return false;
        const PixelRect rect = cellRect(index % cells_x_, index / cells_x_);
        const PixelRect part = rect.intersect(box.rect);
        bool part_free;
        if (extensions_.border_whole_fraction > 0.0 && cell.state == CellState::Outdated &&
            double(part.area()) > extensions_.border_whole_fraction * double(rect.area())) {
            // Section 6: query the whole cell; when it is not full, the part is
            // read again (a second pixel query, counted as one).
            updateCell(index);
            part_free = !cell.full && queryFree(part) > 0;
        } else {
            part_free = queryFree(part) > 0;
            if (part_free && cell.state == CellState::Outdated)
                cell.state = CellState::PartiallyFree;
        }
        touch(trace, index, CellRole::Border, CellTouchKind::PixelQuery, part_free);
        if (part_free) return false;
    }
    step = OcclusionStep::Occluded;
    return true;
}

bool LazyOcclusionGrid::isOccludedZBuffer(const BoxOnScreen& box, std::vector<CellTouch>* trace,
                                          OcclusionStep& step) {
    internal_query_list_.clear();
    border_query_list_.clear();
    const double znear = box.znear;
    // internalCellIsFreeWithoutPixelquery
    step = OcclusionStep::InternalWithoutPixelQuery;
    for (int index : internal_cells_) {
        const LazyGridCell& cell = cells_[size_t(index)];
        if (!(znear <= cell.zfar)) {
            touch(trace, index, CellRole::Internal, CellTouchKind::State, false);
        } else if (cell.outdated) {
            touch(trace, index, CellRole::Internal, CellTouchKind::Queued, false);
            internal_query_list_.push_back(index);
        } else {
            touch(trace, index, CellRole::Internal, CellTouchKind::State, true);
            return false;
        }
    }
    // borderCellIsFreeWithoutPixelquery
    step = OcclusionStep::BorderWithoutPixelQuery;
    for (int index : border_cells_) {
        const LazyGridCell& cell = cells_[size_t(index)];
        if (cell.drawn_area == 0.0) {  // nothing drawn here: every pixel at zmax
            touch(trace, index, CellRole::Border, CellTouchKind::State, true);
            return false;
        }
        if (znear <= cell.zfar) {
            touch(trace, index, CellRole::Border, CellTouchKind::Queued, false);
            border_query_list_.push_back(index);
        } else {
            touch(trace, index, CellRole::Border, CellTouchKind::State, false);
        }
    }
    // internalCellIsFreeWithPixelquery: the lazy update of zfar.
    step = OcclusionStep::InternalWithPixelQuery;
    for (int index : internal_query_list_) {
        LazyGridCell& cell = cells_[size_t(index)];
        if (ratedFreeByProbability(index, CellRole::Internal, trace)) return false;
        updateCell(index);
        const bool free = znear <= cell.zfar;
        touch(trace, index, CellRole::Internal, CellTouchKind::PixelQuery, free);
        if (free) return false;
    }
    // borderCellIsFreeWithPixelquery
    step = OcclusionStep::BorderWithPixelQuery;
    for (int index : border_query_list_) {
        LazyGridCell& cell = cells_[size_t(index)];
        if (ratedFreeByProbability(index, CellRole::Border, trace)) return false;
        const PixelRect rect = cellRect(index % cells_x_, index / cells_x_);
        const PixelRect part = rect.intersect(box.rect);
        bool free;
        if (extensions_.border_whole_fraction > 0.0 && cell.outdated &&
            double(part.area()) > extensions_.border_whole_fraction * double(rect.area())) {
            updateCell(index);  // section 6: the whole cell, which bounds the part too
            free = znear <= cell.zfar;
            // The whole cell is not behind the box; the part may still be: a
            // second pixel query, counted as one.
            if (free) free = znear <= queryFar(part);
        } else {
            free = znear <= queryFar(part);
        }
        touch(trace, index, CellRole::Border, CellTouchKind::PixelQuery, free);
        if (free) return false;
    }
    step = OcclusionStep::Occluded;
    return true;
}

}  // namespace gridcull
