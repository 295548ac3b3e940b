#include "app/trade_explorer.h"

#include <algorithm>

#include "culling/registry/registry.h"
#include "ui/trade_plot.h"

namespace gridcull {

void TradeExplorer::start(const Scene& scene, const std::string& algorithm,
                          const KnobValues& knobs) {
    stop();
    scene_ = std::make_unique<Scene>(scene);
    base_ = knobs;
    settings_ = tradeSettings({algorithm}, knobs);
    view_ = TradeCurveView{};
    view_.algorithm = algorithm;
    view_.frames = std::min(scene.frames, kWindowTradeFrames);
    view_.runs = 1;
    view_.settings = int(settings_.size());
    view_.running = true;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        measured_.clear();
        finished_ = false;
        error_.clear();
    }
    stop_ = false;
    steps_done_ = 0;
    steps_total_ = TradeSweep(*scene_, view_.frames, view_.runs).steps(settings_.size());
    const int frames = view_.frames, runs = view_.runs;
    thread_ = std::thread([this, frames, runs] { run(frames, runs); });
}

void TradeExplorer::run(int frames, int runs) {
    TradeSweep sweep(*scene_, frames, runs, &stop_);
    sweep.setStep([this] { steps_done_.fetch_add(1, std::memory_order_relaxed); });
    std::string error;
    bool ok = sweep.prepare(base_, error);
    for (size_t i = 0; ok && i < settings_.size(); ++i) {
        TradePoint point;
        const TradeSweep::Outcome outcome = sweep.measure(settings_[i], point, error);
        if (outcome != TradeSweep::Outcome::Measured) {
            if (outcome == TradeSweep::Outcome::Failed) error = settings_[i].label + ": " + error;
            break;
        }
        std::lock_guard<std::mutex> lock(mutex_);
        measured_.push_back(point);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    finished_ = true;
    error_ = error;
}

void TradeExplorer::stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    std::lock_guard<std::mutex> lock(mutex_);
    if (view_.running && error_.empty() && measured_.size() < settings_.size())
        error_ = "stopped after " + std::to_string(measured_.size()) + " settings";
}

void TradeExplorer::clear() {
    stop();
    view_ = TradeCurveView{};
    std::lock_guard<std::mutex> lock(mutex_);
    measured_.clear();
    error_.clear();
}

void TradeExplorer::poll(const KnobValues& knobs) {
    if (view_.algorithm.empty()) return;
    bool finished = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        // Points only grow: copy the new ones (nothing is allocated on a frame
        // without news).
        const size_t before = view_.points.size();
        for (size_t i = before; i < measured_.size(); ++i) view_.points.push_back(measured_[i]);
        if (view_.points.size() != before) view_.layout = tradePlotLayout(view_.points, {});
        finished = finished_ && view_.running;
        if (finished) view_.error = error_;
    }
    if (finished) {
        if (thread_.joinable()) thread_.join();  // it has handed over everything
        view_.running = false;
    }
    view_.progress =
        steps_total_ > 0 ? double(steps_done_.load(std::memory_order_relaxed)) / steps_total_ : 0;
    // The setting in use: the first whose every knob of the family has the
    // value the cullers were made with.
    view_.current = -1;
    const FamilyEntry* family = familyOfAlgorithm(view_.algorithm);
    for (size_t i = 0; family && i < view_.points.size() && view_.current < 0; ++i) {
        bool same = true;
        for (const Knob& k : family->knobs)
            same = same && settings_[i].knobs.get(k) == knobs.get(k);
        if (same) view_.current = int(i);
    }
}

const TradeSetting* TradeExplorer::setting(int index) const {
    return index >= 0 && size_t(index) < view_.points.size() ? &settings_[size_t(index)] : nullptr;
}

}  // namespace gridcull
