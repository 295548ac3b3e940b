// What `gridcull trade` and the window's trade curve measure: the settings of
// the algorithms named, and each setting's cost and accuracy on the same frames.
//
// The settings of an algorithm are its defaults, then each knob of its family
// that it reads and that the family sweeps (Knob::sweep, the values listed in
// docs/LIMITS.md), one knob at a time from the defaults, at each of its values.
// One knob at a time keeps the sweep linear in the values; a knob's effect is
// read off against the same defaults every time.
//
// The oracle runs once over the frames; its visible sets judge every setting.
// Each setting is then made afresh and timed over the frames `runs` times (reset
// before each run), drawn when a draw function is given; quality comes from the
// first run. Its memory is the heap it holds after the last frame of a run
// (ui/heap_bytes.h), which covers what it keeps between frames: the first
// run's, or with drawing an undrawn pass of its own, since the GL driver
// allocates from the same heap.
#pragma once
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "culling/api/culler.h"
#include "culling/api/knobs.h"
#include "culling/scene/scene.h"
#include "ui/trade_front.h"

namespace gridcull {

struct TradeSetting {
    std::string algorithm;  // a registry name
    std::string knob;       // the flag set apart from the defaults; "" for the defaults
    double value = 0.0;
    std::string label;  // "NAME" or "NAME:FLAG=VALUE", as bench --algo takes it
    KnobValues knobs;   // the base values with `knob` set
};

std::vector<TradeSetting> tradeSettings(const std::vector<std::string>& algorithms,
                                        const KnobValues& base);

class TradeSweep {
public:
    // Times one PVS's draw at time t; milliseconds.
    using DrawFunction =
        std::function<double(const Camera& camera, double t, const std::vector<int>& pvs)>;
    // Called after every frame culled (and the oracle's), for a progress bar.
    using StepFunction = std::function<void()>;

    // `stop`, when set, is polled every frame: a sweep stopped leaves the
    // setting it was measuring unmeasured.
    TradeSweep(const Scene& scene, int frames, int runs, const std::atomic<bool>* stop = nullptr);
    void setDraw(DrawFunction draw) { draw_ = std::move(draw); }
    void setStep(StepFunction step) { step_ = std::move(step); }
    bool drawn() const { return bool(draw_); }
    // Frame steps the whole sweep of `settings` takes, the oracle's included
    // (call after setDraw).
    long long steps(size_t settings) const;

    // Runs the oracle (with `base`'s oracle knobs) over the frames, once.
    // False when stopped, or with `error` when it cannot be made.
    bool prepare(const KnobValues& base, std::string& error);

    enum class Outcome { Measured, Stopped, Failed };
    // Measures one setting into `point` (Failed: `error` says why).
    Outcome measure(const TradeSetting& setting, TradePoint& point, std::string& error);

private:
    Outcome measureMemory(const TradeSetting& setting, double& bytes, std::string& error);
    bool stopped() const { return stop_ && stop_->load(std::memory_order_relaxed); }
    void step() const {
        if (step_) step_();
    }

    const Scene& scene_;
    int frames_, runs_;
    const std::atomic<bool>* stop_;
    DrawFunction draw_;
    StepFunction step_;
    std::vector<FrameResult> exact_;  // [frame]
    FrameResult result_;               // reused by every setting, so it is not their memory
};

}  // namespace gridcull
