// The trade curve (ui/trade_plot.h), drawn headless: every point, crowded or
// not, false-culling or not, can be found under the pointer, and clicking one
// reports it (what the window applies).
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <imgui.h>

#include "tests/ui/headless_imgui.h"
#include "ui/trade_plot.h"

namespace gridcull {
namespace {

TradePoint point(const char* setting, const char* algorithm, double cull_ms, double ratio,
                 int false_culls = 0) {
    TradePoint p;
    p.setting = setting;
    p.algorithm = algorithm;
    p.cull_ms = cull_ms;
    p.cull_p95_ms = cull_ms * 1.2;
    p.pvs_ratio = ratio;
    p.false_culls = false_culls;
    return p;
}

class TradePlotTest : public test::HeadlessImGuiTest {
protected:
    // One frame with the pointer at (x, y), the button down or not.
    TradePlotResult frame(const TradePlotInput& input, float x, float y, bool down) {
        test::beginWholeDisplayWindow("plot", 640, 480, x, y, down);
        const TradePlotResult result = drawTradePlot(input, 600, 400);
        ImGui::End();
        ImGui::Render();
        return result;
    }
};

TEST_F(TradePlotTest, EveryPointCanBeHoveredAndAClickReportsIt) {
    // Two algorithms, a span of costs over 10x (a log scale), a false cull.
    const std::vector<TradePoint> points = {
        point("a", "a", 0.2, 3.0),        point("a:k=1", "a", 0.5, 2.0),
        point("a:k=2", "a", 4.0, 1.1),    point("b", "b", 1.0, 1.5),
        point("b:j=1", "b", 1.05, 1.52),  point("b:j=2", "b", 8.0, 1.2, /*false culls*/ 3)};
    TradePlotInput input;
    input.points = &points;
    input.target = 1.6;
    input.chosen = 3;
    input.current = 1;
    std::set<int> hovered;
    float found_x = -1, found_y = -1;
    for (float y = 0; y < 480; y += 2)
        for (float x = 0; x < 640; x += 2) {
            const int h = frame(input, x, y, false).hovered;
            if (h < 0) continue;
            hovered.insert(h);
            if (h == 2) found_x = x, found_y = y;
        }
    EXPECT_EQ(hovered.size(), points.size());
    ASSERT_GE(found_x, 0.0f);
    frame(input, found_x, found_y, false);
    const TradePlotResult press = frame(input, found_x, found_y, true);
    EXPECT_EQ(press.clicked, 2);
    EXPECT_EQ(frame(input, found_x, found_y, false).clicked, -1);  // released
}

// The layout the window keeps: each algorithm's front is paretoFront of its own
// points, the named front that of all, and colours are dealt in series_order first.
TEST(TradePlotLayout, FrontsAndColoursFollowThePoints) {
    const std::vector<TradePoint> points = {
        point("a", "a", 0.2, 3.0),       point("b", "b", 1.0, 1.5),
        point("a:k=1", "a", 0.5, 2.0),   point("a:k=2", "a", 4.0, 1.1),
        point("a:k=3", "a", 5.0, 2.5),   point("b:j=1", "b", 0.9, 1.6, /*false culls*/ 1),
        point("b:j=2", "b", 8.0, 1.2)};
    const TradePlotLayout layout = tradePlotLayout(points, {"b", "z"});
    EXPECT_EQ(layout.point_count, points.size());
    ASSERT_EQ(layout.names, (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(layout.name_series, (std::vector<int>{2, 0}));  // "b" and "z" dealt first
    EXPECT_EQ(layout.point_series, (std::vector<int>{2, 0, 2, 2, 2, 0, 0}));
    ASSERT_EQ(layout.fronts.size(), 2u);
    EXPECT_EQ(layout.fronts[0], (std::vector<size_t>{0, 2, 3}));  // a:k=3 is beaten by a:k=2
    EXPECT_EQ(layout.fronts[1], (std::vector<size_t>{1, 6}));     // b:j=1 falsely culls
    EXPECT_EQ(layout.front, paretoFront(points));
}

TEST_F(TradePlotTest, NoPointsDrawsANoteAndReportsNothing) {
    const std::vector<TradePoint> none;
    TradePlotInput input;
    input.points = &none;
    const TradePlotResult r = frame(input, 100, 100, true);
    EXPECT_EQ(r.hovered, -1);
    EXPECT_EQ(r.clicked, -1);
}

}  // namespace
}  // namespace gridcull
