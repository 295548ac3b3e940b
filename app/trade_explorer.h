// The window's trade sweep: app/trade_sweep.h run on a thread of its own over
// a copy of the open scene, so the window stays live while it measures. The
// window polls it once a frame for the points measured so far
// (ui/trade_panel.h's TradeCurveView). Cull time only: drawing would need the
// window's GL context. Memory figures are the process's heap growth while a
// setting runs, so the window's own allocations blur them a little.
#pragma once
#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "app/trade_sweep.h"
#include "ui/trade_panel.h"

namespace gridcull {

// Frames the window sweeps: the scene's first ones, enough to see the trade,
// few enough to see it soon.
constexpr int kWindowTradeFrames = 60;

class TradeExplorer {
public:
    ~TradeExplorer() { stop(); }
    // Stops a sweep under way and starts one of `algorithm` with `knobs` as the
    // base, on frames 0..min(scene.frames, kWindowTradeFrames) - 1, one run.
    void start(const Scene& scene, const std::string& algorithm, const KnobValues& knobs);
    // Stops the sweep (the points measured stay) and waits for its thread.
    void stop();
    // Forgets the curve (another scene).
    void clear();
    // Takes in what the thread measured since the last call, and marks the
    // point that `knobs` (the cullers' knobs now) select.
    void poll(const KnobValues& knobs);
    const TradeCurveView& view() const { return view_; }
    // The setting of point `index` of the view.
    const TradeSetting* setting(int index) const;

private:
    void run(int frames, int runs);

    std::unique_ptr<Scene> scene_;
    std::vector<TradeSetting> settings_;
    KnobValues base_;
    std::thread thread_;
    std::atomic<bool> stop_{false};
    std::atomic<long long> steps_done_{0};
    long long steps_total_ = 1;  // set before the thread starts
    std::mutex mutex_;                 // guards what the thread hands over:
    std::vector<TradePoint> measured_;  // points so far
    bool finished_ = true;
    std::string error_;
    TradeCurveView view_;
};

}  // namespace gridcull
