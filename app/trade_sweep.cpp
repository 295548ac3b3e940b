#include "app/trade_sweep.h"

#include <algorithm>

#include "app/app_cullers.h"
#include "app/bench_table.h"
#include "culling/registry/registry.h"
#include "ui/heap_bytes.h"

namespace gridcull {

std::vector<TradeSetting> tradeSettings(const std::vector<std::string>& algorithms,
                                        const KnobValues& base) {
    std::vector<TradeSetting> settings;
    for (const std::string& algorithm : algorithms) {
        TradeSetting defaults;
        defaults.algorithm = algorithm;
        defaults.label = algorithm;
        defaults.knobs = base;
        settings.push_back(defaults);
        const FamilyEntry* family = familyOfAlgorithm(registryAlgorithmOf(algorithm));
        if (!family) continue;
        for (const Knob& knob : family->knobs) {
            if (!knobReadBy(knob, registryAlgorithmOf(algorithm))) continue;
            for (double value : knob.sweep) {
                TradeSetting s = defaults;
                s.knob = knob.flag;
                s.value = value;
                s.label = algorithm + ":" + knob.flag + "=" + knobValueText(knob, value);
                s.knobs.set(knob.flag, value);
                settings.push_back(std::move(s));
            }
        }
    }
    return settings;
}

TradeSweep::TradeSweep(const Scene& scene, int frames, int runs, const std::atomic<bool>* stop)
    : scene_(scene), frames_(frames), runs_(runs), stop_(stop) {
    result_.pvs.reserve(scene.objects.size());
}

long long TradeSweep::steps(size_t settings) const {
    const long long passes = runs_ + (drawn() ? 1 : 0);  // a drawn sweep's memory pass
    return (long long)frames_ * (1 + (long long)settings * passes);
}

bool TradeSweep::prepare(const KnobValues& base, std::string& error) {
    std::unique_ptr<Culler> oracle = makeCuller(referenceAlgorithm(), base, error);
    if (!oracle) return false;
    oracle->reset(scene_);
    exact_.assign(size_t(frames_), FrameResult{});
    for (int f = 0; f < frames_; ++f) {
        if (stopped()) return false;
        const double t = scene_.timeOfFrame(f);
        oracle->cull(scene_, cameraAt(scene_, t), t, exact_[size_t(f)]);
        step();
    }
    return true;
}

namespace {

double heapGrowth(size_t before) {
    const size_t now = heapBytesInUse();
    return now > before ? double(now - before) : 0.0;
}

}  // namespace

TradeSweep::Outcome TradeSweep::measureMemory(const TradeSetting& setting, double& bytes,
                                              std::string& error) {
    const size_t heap_before = heapBytesInUse();
    std::unique_ptr<Culler> culler = makeAppCuller(setting.algorithm, setting.knobs, error);
    if (!culler) return Outcome::Failed;
    culler->reset(scene_);
    for (int f = 0; f < frames_; ++f) {
        if (stopped()) return Outcome::Stopped;
        const double t = scene_.timeOfFrame(f);
        culler->cull(scene_, cameraAt(scene_, t), t, result_);
        step();
    }
    bytes = heapGrowth(heap_before);
    return Outcome::Measured;
}

TradeSweep::Outcome TradeSweep::measure(const TradeSetting& setting, TradePoint& point,
                                        std::string& error) {
    AlgoBench bench;
    bench.algo = setting.label;
    sizeBench(bench, frames_, runs_, drawn());
    // Without drawing, the first run measures the memory too; the GL driver's
    // allocations would blur it, so a drawn sweep measures it in a pass of its own.
    double memory = 0.0;
    if (drawn()) {
        const Outcome outcome = measureMemory(setting, memory, error);
        if (outcome != Outcome::Measured) return outcome;
    }
    const size_t heap_before = heapBytesInUse();
    std::unique_ptr<Culler> culler = makeAppCuller(setting.algorithm, setting.knobs, error);
    if (!culler) return Outcome::Failed;
    for (int run = 0; run < runs_; ++run) {
        culler->reset(scene_);
        for (int f = 0; f < frames_; ++f) {
            if (stopped()) return Outcome::Stopped;
            const double t = scene_.timeOfFrame(f);
            const Camera camera = cameraAt(scene_, t);
            timedCull(*culler, scene_, camera, t, result_);
            const size_t slot = size_t(run) * size_t(frames_) + size_t(f);
            bench.ms[slot] = result_.stats.cull_ms;
            if (drawn()) bench.draw_ms[slot] = draw_(camera, t, result_.pvs);
            if (run == 0) recordFrame(scene_, f, result_, &exact_[size_t(f)], bench);
            step();
        }
        if (run == 0 && !drawn()) memory = heapGrowth(heap_before);
    }
    const BenchSummary s = summarize(bench, frames_, runs_);
    point = TradePoint{};
    point.setting = setting.label;
    point.algorithm = setting.algorithm;
    point.cull_ms = s.median_ms;
    point.cull_p95_ms = s.p95_ms;
    point.draw_ms = s.median_draw_ms;
    point.frame_ms = s.median_frame_ms;
    point.frame_p95_ms = s.p95_frame_ms;
    point.memory_bytes = memory;
    point.pvs_ratio = s.pvs_over_exact;
    point.false_culls = s.false_culls;
    return Outcome::Measured;
}

}  // namespace gridcull
