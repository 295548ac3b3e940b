#include "tests/sweep/sweep_check.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>

#include "culling/api/culler.h"
#include "culling/registry/registry.h"

namespace gridcull::sweep {

std::vector<SweepAlgorithm> conservativeAlgorithms() {
    std::vector<SweepAlgorithm> out;
    for (const FamilyEntry& family : families()) {
        if (family.reference) continue;
        for (const AlgorithmEntry& a : family.algorithms) out.push_back({a.name, a.late_frames});
    }
    return out;
}

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Runs one algorithm over the frames against the oracle's PVS of each.
void checkAlgorithm(const Scene& scene, const SweepAlgorithm& algo, const KnobValues& knobs,
                    const std::vector<std::vector<int>>& reference, AlgorithmTally& tally,
                    SceneCheck& check) {
    std::string error;
    std::unique_ptr<Culler> culler = makeCuller(algo.name, knobs, error);
    if (!culler) {
        check.errors.push_back(algo.name + ": " + error);
        return;
    }
    // Frames in a row each object (by index) has been missing from the PVS.
    std::vector<int> missing_for(scene.objects.size(), 0);
    std::vector<int> missed;
    bool reported = false;
    FrameResult out;
    const auto start = std::chrono::steady_clock::now();
    culler->reset(scene);
    tally.seconds += secondsSince(start);
    ++tally.scenes;
    for (int f = 0; f < scene.frames; ++f) {
        const double t = scene.timeOfFrame(f);
        const Camera camera = cameraAt(scene, t);
        const auto frame_start = std::chrono::steady_clock::now();
        culler->cull(scene, camera, t, out);
        tally.seconds += secondsSince(frame_start);
        ++tally.frames;
        // The comparison below needs the Culler contract's sorted, unique ids.
        if (std::adjacent_find(out.pvs.begin(), out.pvs.end(), std::greater_equal<int>()) !=
            out.pvs.end()) {
            check.errors.push_back(algo.name + ": frame " + std::to_string(f) +
                                   ": the PVS is not sorted and unique");
            return;
        }
        std::vector<int> gone;
        std::set_difference(reference[size_t(f)].begin(), reference[size_t(f)].end(),
                            out.pvs.begin(), out.pvs.end(), std::back_inserter(gone));
        missed.clear();
        std::vector<int> still(scene.objects.size(), 0);
        for (const int id : gone) {
            const size_t index = size_t(scene.indexOf(id));
            still[index] = missing_for[index] + 1;
            if (still[index] > algo.late_frames) missed.push_back(id);
        }
        missing_for.swap(still);
        tally.false_culls += int64_t(missed.size());
        if (!missed.empty() && !reported) {
            check.false_culls.push_back({algo.name, f, t, missed});
            reported = true;
        }
    }
}

}  // namespace

SceneCheck checkScene(const Scene& scene, const std::vector<SweepAlgorithm>& algorithms,
                      const KnobValues& knobs) {
    SceneCheck check;
    check.tallies.resize(algorithms.size());
    std::string error;
    std::unique_ptr<Culler> oracle = makeCuller(referenceAlgorithm(), knobs, error);
    if (!oracle) {
        check.errors.push_back(referenceAlgorithm() + ": " + error);
        return check;
    }
    std::vector<std::vector<int>> reference(size_t(scene.frames));
    FrameResult out;
    const auto start = std::chrono::steady_clock::now();
    oracle->reset(scene);
    for (int f = 0; f < scene.frames; ++f) {
        const double t = scene.timeOfFrame(f);
        oracle->cull(scene, cameraAt(scene, t), t, out);
        reference[size_t(f)] = out.pvs;
    }
    check.oracle.seconds = secondsSince(start);
    check.oracle.scenes = 1;
    check.oracle.frames = scene.frames;
    for (size_t a = 0; a < algorithms.size(); ++a) {
        std::string why;
        if (!algorithmFits(algorithms[a].name, scene, why)) continue;
        checkAlgorithm(scene, algorithms[a], knobs, reference, check.tallies[a], check);
    }
    return check;
}

}  // namespace gridcull::sweep
