// Trade curve: the speed / accuracy trade of the selected algorithm on the
// open scene, measured in the background over its family's knobs as `gridcull
// trade` measures it (cull time only: the window's GL context draws the view),
// plotted as trade's PNGs are (ui/trade_plot.h), the setting in use ringed.
// Clicking a point applies its setting, as the knobs panel's Apply would.
#pragma once
#include <string>
#include <vector>

#include "ui/trade_front.h"
#include "ui/trade_plot.h"

namespace gridcull {

// What the window's trade sweep has measured so far.
struct TradeCurveView {
    std::string algorithm;  // what was swept ("" before the first sweep)
    std::vector<TradePoint> points;
    // tradePlotLayout(points, {}), made again whenever points grow, so that the
    // panel, drawn every frame, allocates nothing.
    TradePlotLayout layout;
    int current = -1;  // the point whose setting the cullers now use, or -1
    int frames = 0, runs = 0;
    int settings = 0;          // settings the sweep measures in all
    double progress = 0.0;     // 0 to 1
    bool running = false;
    std::string error;  // why the last sweep stopped early ("" when it did not)
};

struct TradeAction {
    bool start = false;  // sweep the selected algorithm
    bool stop = false;
    int apply = -1;  // the point clicked: apply its setting
};

// Draws into the current ImGui window (a collapsed header until opened).
// `selected`: the algorithm the window shows, which a start sweeps.
TradeAction drawTradePanel(const TradeCurveView& view, const std::string& selected);

}  // namespace gridcull
