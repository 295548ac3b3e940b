// The window's trade curve (app/trade_explorer.h, ui/trade_panel.h): a sweep
// of the selected culler started from the knobs panel runs in the background,
// every setting lands in the curve, the setting in use is marked, and clicking
// a point applies its setting to the cullers. Needs a GL context (the test run
// provides an X display, under xvfb-run).
#include <chrono>
#include <memory>
#include <thread>

#include <gtest/gtest.h>

#include "app/debugger.h"
#include "app/gl_context.h"
#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"
#include "run_command.h"
#include "ui/trade_panel.h"

namespace gridcull {
namespace {

// Polls the sweep as the window does each frame, until it ends (or a minute).
void waitForSweep(Debugger& debugger) {
    for (int i = 0; i < 6000; ++i) {
        debugger.updateTrade();
        if (!debugger.snapshot().trade->running) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    FAIL() << "the trade sweep did not end within a minute";
}

// A window's debugger on `scene_file` with the lazy grid and a small oracle.
class DebuggerTrade : public ::testing::Test {
protected:
    void open(const char* scene_file) {
        std::string error;
        ASSERT_TRUE(window_.create(64, 64, "gridcull test", false, error)) << error;
        ViewOptions options;
        options.algo = "lazy-grid";
        options.knobs.set("oracle-res", 96);
        debugger_ = std::make_unique<Debugger>(options);
        SceneLoadResult loaded = loadSceneFile(test::sourcePath(scene_file));
        ASSERT_TRUE(loaded.scene);
        ASSERT_TRUE(debugger_->init(std::move(*loaded.scene), error)) << error;
    }
    GlWindow window_;
    std::unique_ptr<Debugger> debugger_;
};

TEST_F(DebuggerTrade, SweepsInTheBackgroundMarksTheSettingInUseAndAppliesAClickedOne) {
    ASSERT_NO_FATAL_FAILURE(open("scenes/city-walk-3d.json"));
    Debugger& debugger = *debugger_;
    EXPECT_TRUE(debugger.snapshot().trade->algorithm.empty());

    UiActions start;
    start.knobs.trade.start = true;
    debugger.apply(start);
    waitForSweep(debugger);
    const TradeCurveView& view = *debugger.snapshot().trade;
    EXPECT_EQ(view.algorithm, "lazy-grid");
    EXPECT_TRUE(view.error.empty()) << view.error;
    ASSERT_EQ(int(view.points.size()), view.settings);
    EXPECT_EQ(view.frames, kWindowTradeFrames);
    EXPECT_EQ(view.current, 0);  // the knobs in use: the sweep's base
    for (const TradePoint& p : view.points) EXPECT_GT(p.pvs_ratio, 0.0) << p.setting;

    int cell16 = -1;
    for (size_t i = 0; i < view.points.size(); ++i)
        if (view.points[i].setting == "lazy-grid:lazy-cell-size=16") cell16 = int(i);
    ASSERT_GE(cell16, 0);
    UiActions click;
    click.knobs.trade.apply = cell16;
    debugger.apply(click);
    EXPECT_EQ(debugger.session().knobs().get(*findKnob("lazy-cell-size")), 16);
    EXPECT_EQ(debugger.session().knobs().get(*findKnob("oracle-res")), 96);  // untouched
    debugger.updateTrade();
    EXPECT_EQ(debugger.snapshot().trade->current, cell16);
}

TEST_F(DebuggerTrade, AStoppedSweepKeepsWhatItMeasuredAndSaysSo) {
    ASSERT_NO_FATAL_FAILURE(open("scenes/forest-walk-3d.json"));
    Debugger& debugger = *debugger_;
    UiActions start;
    start.knobs.trade.start = true;
    debugger.apply(start);
    UiActions stop;
    stop.knobs.trade.stop = true;
    debugger.apply(stop);
    debugger.updateTrade();
    const TradeCurveView& view = *debugger.snapshot().trade;
    EXPECT_FALSE(view.running);
    EXPECT_LT(int(view.points.size()), view.settings);
    EXPECT_NE(view.error.find("stopped after"), std::string::npos) << view.error;
}

}  // namespace
}  // namespace gridcull
