#include "ui/trade_front.h"

#include <algorithm>
#include <cmath>

namespace gridcull {

namespace {

bool usable(const TradePoint& p) {
    return p.false_culls == 0 && std::isfinite(p.cost()) && std::isfinite(p.pvs_ratio);
}

// a is at least as good as b on cost and PVS/exact, and better on one.
bool dominates(const TradePoint& a, const TradePoint& b) {
    const bool no_worse = a.cost() <= b.cost() && a.pvs_ratio <= b.pvs_ratio;
    return no_worse && (a.cost() < b.cost() || a.pvs_ratio < b.pvs_ratio);
}

}  // namespace

std::vector<size_t> paretoFront(const std::vector<TradePoint>& points) {
    std::vector<size_t> front;
    for (size_t i = 0; i < points.size(); ++i) {
        if (!usable(points[i])) continue;
        bool beaten = false;
        for (size_t j = 0; j < points.size() && !beaten; ++j)
            beaten = j != i && usable(points[j]) && dominates(points[j], points[i]);
        if (!beaten) front.push_back(i);
    }
    std::stable_sort(front.begin(), front.end(), [&](size_t a, size_t b) {
        return points[a].cost() < points[b].cost();
    });
    return front;
}

int cheapestWithin(const std::vector<TradePoint>& points, double target) {
    int best = -1;
    for (size_t i = 0; i < points.size(); ++i) {
        const TradePoint& p = points[i];
        if (!usable(p) || !(p.pvs_ratio <= target)) continue;
        if (best < 0) {
            best = int(i);
            continue;
        }
        const TradePoint& b = points[size_t(best)];
        const bool better =
            p.cost() != b.cost()             ? p.cost() < b.cost()
            : p.memory_bytes != b.memory_bytes ? p.memory_bytes < b.memory_bytes
                                               : p.pvs_ratio < b.pvs_ratio;
        if (better) best = int(i);
    }
    return best;
}

}  // namespace gridcull
