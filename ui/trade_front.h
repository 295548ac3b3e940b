// The choice `gridcull trade` makes from a sweep of settings: which settings
// are on the Pareto front of cost against accuracy, and which is the cheapest
// one that is accurate enough. Pure arithmetic on the sweep's table, kept
// apart from the sweep so it is tested on synthetic tables.
//
// Cost is the frame time (cull + draw) when the sweep drew, else the median
// cull time; accuracy is PVS/exact (1 is exact, larger draws more than is
// seen). A setting with a false cull is never chosen and never on the front:
// a conservative culler that drops a visible object is wrong, not cheap.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace gridcull {

struct TradePoint {
    std::string setting;     // "NAME:FLAG=VALUE", or "NAME" for the defaults
    std::string algorithm;   // NAME: the curve it belongs to
    double cull_ms = 0.0;    // median per frame
    double cull_p95_ms = 0.0;
    double draw_ms = 0.0;    // median per frame; 0 when the sweep did not draw
    double frame_ms = 0.0;   // median of cull + draw per frame; 0 when not drawn
    double frame_p95_ms = 0.0;
    double memory_bytes = 0.0;
    double pvs_ratio = 0.0;  // summed PVS over summed exact visible
    int64_t false_culls = 0;

    double cost() const { return frame_ms > 0.0 ? frame_ms : cull_ms; }
};

// Indices of the settings no other conservative setting beats on both cost and
// PVS/exact (at least as good on both, better on one), in increasing cost.
std::vector<size_t> paretoFront(const std::vector<TradePoint>& points);

// The cheapest conservative setting whose PVS/exact is at most `target`: the
// model the scene needs and no more. Ties in cost go to the smaller memory,
// then the smaller PVS/exact. -1 when none is accurate enough.
int cheapestWithin(const std::vector<TradePoint>& points, double target);

}  // namespace gridcull
