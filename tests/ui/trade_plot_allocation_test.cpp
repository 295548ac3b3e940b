// "Hot per-frame paths do not allocate": the window draws the trade panel every
// frame while it is open, and with the layout its view keeps (made when the
// points change) the panel and its plot allocate nothing once ImGui has settled.
// Counted by tests/common/counting_new.h (compiled into this binary by
// overlay_allocation_test.cpp); the counter runs only inside the measured frames.
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <imgui.h>

#include "tests/common/allocation_counter.h"
#include "tests/ui/headless_imgui.h"
#include "ui/trade_panel.h"
#include "ui/trade_plot.h"

namespace gridcull {
namespace {

// A sweep's worth of points: two algorithms, costs over 10x, a false cull, and
// settings with and without a knob (both label forms).
std::vector<TradePoint> sweep() {
    std::vector<TradePoint> points;
    for (int k = 0; k < 24; ++k) {
        TradePoint p;
        p.algorithm = k % 2 ? "lazy-grid" : "hzb-tbv";
        p.setting = k < 2 ? p.algorithm : p.algorithm + ":a-rather-long-knob-name=" + std::to_string(k);
        p.cull_ms = 0.3 * (k + 1);
        p.cull_p95_ms = 1.2 * p.cull_ms;
        p.pvs_ratio = 1.0 + 3.0 / (k + 1);
        p.false_culls = k == 5 ? 2 : 0;
        points.push_back(p);
    }
    return points;
}

class TradePlotAllocationTest : public test::HeadlessImGuiTest {
protected:
    // One frame of the panel, opened, the pointer over the plot's box.
    void frame(const TradeCurveView& view) {
        test::beginWholeDisplayWindow("knobs", 640, 480, 320, 300, false);
        ImGui::SetNextItemOpen(true);
        drawTradePanel(view, "lazy-grid");
        ImGui::End();
        ImGui::Render();
    }

    // Allocations of two frames after `settle` frames.
    long allocationsOfTwoFrames(const TradeCurveView& view) {
        for (int k = 0; k < 3; ++k) frame(view);
        test::startCounting();
        frame(view);
        frame(view);
        test::stopCounting();
        return test::allocationCount();
    }
};

TEST_F(TradePlotAllocationTest, ThePanelWithItsLayoutAllocatesNothing) {
    TradeCurveView view;
    view.algorithm = "lazy-grid";
    view.points = sweep();
    view.layout = tradePlotLayout(view.points, {});
    view.current = 3;
    view.frames = 60;
    view.runs = 2;
    view.settings = int(view.points.size());
    EXPECT_EQ(allocationsOfTwoFrames(view), 0);
    view.running = true;  // the progress bar and Stop instead of the start button
    EXPECT_EQ(allocationsOfTwoFrames(view), 0);
}

// The measure can fail: a layout made from other points is not used, and making
// one in the frame allocates.
TEST_F(TradePlotAllocationTest, AStaleLayoutIsMadeAgainInTheFrame) {
    TradeCurveView view;
    view.algorithm = "lazy-grid";
    view.points = sweep();
    view.layout = tradePlotLayout(std::vector<TradePoint>(view.points.begin(), view.points.end() - 1), {});
    EXPECT_GT(allocationsOfTwoFrames(view), 0);
}

}  // namespace
}  // namespace gridcull
