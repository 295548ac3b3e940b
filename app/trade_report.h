// What `gridcull trade` writes: the CSV of every setting measured, and the
// table and picks it prints.
#pragma once
#include <string>
#include <vector>

#include "app/trade_sweep.h"
#include "ui/trade_front.h"

namespace gridcull {

// One row per point, `settings[i]` describing points[i]: setting, algorithm,
// knob, value, median and 95th-percentile cull, draw and frame ms, memory,
// PVS/exact, false culls, and whether it is on its algorithm's Pareto front
// and on the front of all the algorithms together.
std::string formatTradeCsv(const std::vector<TradeSetting>& settings,
                           const std::vector<TradePoint>& points);
// Reads what formatTradeCsv wrote back (for trade --replot): false with
// `error` naming the line and what was expected.
bool parseTradeCsv(const std::string& text, std::vector<TradeSetting>& settings,
                   std::vector<TradePoint>& points, std::string& error);
// The table printed at the end: the same columns, front marked with '*'.
std::string formatTradeTable(const std::vector<TradePoint>& points);

// Indices of `points` whose algorithm is `algorithm`.
std::vector<size_t> pointsOf(const std::vector<TradePoint>& points, const std::string& algorithm);
// Whether each point is on its own algorithm's front (`by_algorithm`) or on
// the front of all of them.
std::vector<bool> onFront(const std::vector<TradePoint>& points, bool by_algorithm);

}  // namespace gridcull
