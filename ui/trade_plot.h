// The trade curve drawn with ImGui: each measured setting a point of cost
// (x: frame ms when the sweep drew, else cull ms; a log scale when the costs
// span more than 10x) against PVS/exact (y), one colour per algorithm, each
// algorithm's Pareto front joined by a line. A setting with a false cull is a
// cross in the false-cull colour, never on a front. The target PVS/exact is a
// dashed line and its pick a square; the setting in use is ringed. The window's
// trade panel and `gridcull trade`'s PNGs draw the same plot.
//
// The window draws the plot every frame, so what depends on the points alone
// (series, colours, fronts) is a TradePlotLayout, made when the points change;
// given one, drawing allocates nothing (tests/ui/trade_plot_allocation_test.cpp).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "ui/trade_front.h"

namespace gridcull {

// What the plot derives from its points: made once per change of the points.
struct TradePlotLayout {
    size_t point_count = 0;           // the points it was made from
    std::vector<std::string> names;   // the algorithms plotted, in order of appearance
    std::vector<int> name_series;     // per name: its colour slot
    std::vector<int> point_series;    // per point: its algorithm's colour slot
    std::vector<std::vector<size_t>> fronts;  // per name: its Pareto front, indices into points
    std::vector<size_t> front;        // the front of all points (named on the plot)
};

// `series_order`: as TradePlotInput's.
TradePlotLayout tradePlotLayout(const std::vector<TradePoint>& points,
                                const std::vector<std::string>& series_order);

struct TradePlotInput {
    const std::vector<TradePoint>* points = nullptr;
    std::string title;   // over the plot; "" for none
    double target = 0.0;  // > 0: the target PVS/exact, drawn as a line
    int chosen = -1;      // the target's pick, an index into points
    int current = -1;     // the setting in use (the window), an index into points
    // Algorithms in the order their colours are dealt, so that a plot of one
    // algorithm keeps the colour it has in the plot of all; empty: the order
    // in which they first appear in points.
    std::vector<std::string> series_order;
    // tradePlotLayout(*points, series_order), made by the caller when the points
    // changed; null (or made from another count of points): made here, which
    // allocates.
    const TradePlotLayout* layout = nullptr;
};

struct TradePlotResult {
    int hovered = -1;  // the point under the pointer
    int clicked = -1;  // the point clicked this frame
};

// Draws the plot into a width x height box at the cursor of the current ImGui
// window (a tooltip describes the hovered point). Empty points: a note instead.
TradePlotResult drawTradePlot(const TradePlotInput& input, float width, float height);

}  // namespace gridcull
