// The trade sweep (app/trade_sweep.h): which settings it measures, and what it
// measures of one, against the oracle on a scene whose answer is plain.
#include <gtest/gtest.h>

#include "app/trade_sweep.h"
#include "culling/registry/registry.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

TEST(TradeSweep, SettingsAreTheDefaultsThenEachSweptKnobAlone) {
    KnobValues base;
    base.set("oracle-res", 256);
    const std::vector<TradeSetting> settings = tradeSettings({"lazy-grid", "vfc"}, base);
    ASSERT_FALSE(settings.empty());
    EXPECT_EQ(settings.front().label, "lazy-grid");
    EXPECT_TRUE(settings.front().knob.empty());
    size_t lazy = 0;
    for (const TradeSetting& s : settings) {
        // The base values stay; the one knob swept is set over them.
        EXPECT_EQ(s.knobs.get(*findKnob("oracle-res")), 256) << s.label;
        if (s.algorithm != "lazy-grid") continue;
        ++lazy;
        if (s.knob.empty()) continue;
        EXPECT_EQ(s.knobs.set_values().size(), 2u) << s.label;
        EXPECT_EQ(s.knobs.get(*findKnob(s.knob)), s.value) << s.label;
        EXPECT_EQ(s.label.rfind("lazy-grid:" + s.knob + "=", 0), 0u) << s.label;
    }
    size_t swept = 1;
    for (const Knob& k : familyOfAlgorithm("lazy-grid")->knobs) swept += k.sweep.size();
    EXPECT_EQ(lazy, swept);
    // vfc's family has no knob: its defaults alone.
    EXPECT_EQ(settings.back().label, "vfc");
    EXPECT_EQ(settings.size(), swept + 1);
}

TEST(TradeSweep, AKnobOnlySomeAlgorithmsReadIsSweptForThemOnly) {
    const std::vector<TradeSetting> full = tradeSettings({"bsp-oq"}, {});
    const std::vector<TradeSetting> simple = tradeSettings({"bsp-oq-simple"}, {});
    bool history_full = false, history_simple = false;
    for (const TradeSetting& s : full) history_full = history_full || s.knob == "bsp-history";
    for (const TradeSetting& s : simple) history_simple = history_simple || s.knob == "bsp-history";
    EXPECT_TRUE(history_full);
    EXPECT_FALSE(history_simple);
    EXPECT_LT(simple.size(), full.size());
}

// A wall hides five of seven spheres: vfc keeps all seven, the lazy grid two.
Scene wallScene() {
    Scene scene = test::sphereWallScene();
    scene.frames = 4;
    return scene;
}

TEST(TradeSweep, MeasuresCostAccuracyAndMemoryAgainstTheOracle) {
    const Scene scene = wallScene();
    KnobValues base;
    base.set("oracle-res", 256);
    TradeSweep sweep(scene, 4, 2);
    long long steps = 0;
    sweep.setStep([&] { ++steps; });
    std::string error;
    ASSERT_TRUE(sweep.prepare(base, error)) << error;
    const std::vector<TradeSetting> settings = tradeSettings({"vfc", "lazy-grid"}, base);
    TradePoint vfc, lazy;
    ASSERT_EQ(sweep.measure(settings[0], vfc, error), TradeSweep::Outcome::Measured) << error;
    ASSERT_EQ(sweep.measure(settings[1], lazy, error), TradeSweep::Outcome::Measured) << error;
    EXPECT_EQ(steps, sweep.steps(2));
    EXPECT_EQ(lazy.setting, "lazy-grid");
    EXPECT_EQ(lazy.algorithm, "lazy-grid");
    EXPECT_EQ(vfc.false_culls, 0);
    EXPECT_EQ(lazy.false_culls, 0);
    // The wall and the two spheres are seen: vfc keeps 8 of them, the grid
    // what is seen.
    EXPECT_DOUBLE_EQ(vfc.pvs_ratio, 8.0 / 3.0);
    EXPECT_DOUBLE_EQ(lazy.pvs_ratio, 1.0);
    EXPECT_GT(lazy.cull_ms, 0.0);
    EXPECT_GE(lazy.cull_p95_ms, lazy.cull_ms);
    EXPECT_EQ(lazy.frame_ms, 0.0);  // not drawn
    // The grid keeps an image and its cells between frames.
    EXPECT_GT(lazy.memory_bytes, 64.0 * 1024);
}

TEST(TradeSweep, AStopLeavesTheSettingUnmeasured) {
    const Scene scene = wallScene();
    std::atomic<bool> stop{false};
    TradeSweep sweep(scene, 4, 1, &stop);
    std::string error;
    ASSERT_TRUE(sweep.prepare({}, error)) << error;
    stop = true;
    TradePoint point;
    point.setting = "untouched";
    EXPECT_EQ(sweep.measure(tradeSettings({"vfc"}, {})[0], point, error),
              TradeSweep::Outcome::Stopped);
    EXPECT_EQ(point.setting, "untouched");
}

}  // namespace
}  // namespace gridcull
