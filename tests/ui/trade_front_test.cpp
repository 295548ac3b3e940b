// The trade's choice (ui/trade_front.h) on synthetic sweeps: the Pareto front
// of cost against PVS/exact leaves out dominated and false-culling settings,
// the target picks the cheapest accurate-enough conservative setting, ties go
// to memory, and a target nothing meets picks nothing.
#include <gtest/gtest.h>

#include "ui/trade_front.h"

namespace gridcull {
namespace {

TradePoint point(const char* name, double cull_ms, double ratio, int64_t false_culls = 0,
                 double memory = 0.0) {
    TradePoint p;
    p.setting = name;
    p.cull_ms = cull_ms;
    p.pvs_ratio = ratio;
    p.false_culls = false_culls;
    p.memory_bytes = memory;
    return p;
}

TEST(TradeFront, TheFrontLeavesOutDominatedAndFalseCullingSettings) {
    const std::vector<TradePoint> sweep = {
        point("coarse", 1.0, 3.0),         // 0: cheapest, least accurate: on the front
        point("mid", 2.0, 2.0),            // 1: on the front
        point("mid-worse", 2.5, 2.2),      // 2: beaten by mid on both
        point("fine", 4.0, 1.2),           // 3: on the front
        point("finer-but-slow", 4.0, 1.3), // 4: same cost as fine, less accurate
        point("exact-but-wrong", 0.5, 1.0, 3),  // 5: false culls: never
        point("finest", 9.0, 1.05),        // 6: on the front
    };
    EXPECT_EQ(paretoFront(sweep), (std::vector<size_t>{0, 1, 3, 6}));
}

TEST(TradeFront, FrameTimeIsTheCostWhenTheSweepDrew) {
    std::vector<TradePoint> sweep = {point("a", 1.0, 2.0), point("b", 2.0, 1.5)};
    sweep[0].frame_ms = 10.0;  // cheap to cull, costly to draw its large PVS
    sweep[1].frame_ms = 6.0;
    EXPECT_EQ(paretoFront(sweep), (std::vector<size_t>{1}));
    EXPECT_EQ(cheapestWithin(sweep, 3.0), 1);
}

TEST(TradeFront, TheTargetPicksTheCheapestAccurateEnoughConservativeSetting) {
    const std::vector<TradePoint> sweep = {
        point("coarse", 1.0, 3.0),
        point("mid", 2.0, 1.9),
        point("mid-lean", 2.0, 1.95, 0, 100.0),
        point("mid-fat", 2.0, 1.8, 0, 500.0),
        point("wrong", 0.1, 1.0, 1),
        point("fine", 4.0, 1.4),
    };
    EXPECT_EQ(cheapestWithin(sweep, 2.0), 1) << "cost 2.0, no memory beats 100 and 500";
    EXPECT_EQ(cheapestWithin(sweep, 1.5), 5);
    EXPECT_EQ(cheapestWithin(sweep, 3.0), 0);
    EXPECT_EQ(cheapestWithin(sweep, 1.1), -1) << "only the false-culling one is that accurate";
}

TEST(TradeFront, TiesInCostGoToLessMemoryThenBetterAccuracy) {
    const std::vector<TradePoint> sweep = {point("a", 2.0, 1.9, 0, 300.0),
                                           point("b", 2.0, 1.8, 0, 100.0),
                                           point("c", 2.0, 1.7, 0, 100.0)};
    EXPECT_EQ(cheapestWithin(sweep, 2.0), 2);
}

}  // namespace
}  // namespace gridcull
