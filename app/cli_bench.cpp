// `gridcull bench SCENE --algo A[,B...]`: algorithms timed side by side on the same
// frames. Each run resets every culler and replays frames 0..N-1; within a frame the
// algorithms take turns, starting with a different one each frame, so that machine
// noise falls on all of them alike. Quality (PVS against the exact visible set) is
// measured in the first run by a separate, untimed oracle.
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "app/app_cullers.h"
#include "app/bench_table.h"
#include "app/cli.h"
#include "app/cli_commands.h"
#include "app/output_file.h"
#include "app/progress_bar.h"
#include "culling/registry/registry.h"
#include "culling/scene/object_triangles.h"

namespace gridcull {

namespace {

int countMissing(const std::vector<int>& exact, const std::vector<int>& pvs) {
    // Both sorted: ids in exact that pvs lacks.
    int missing = 0;
    size_t j = 0;
    for (int id : exact) {
        while (j < pvs.size() && pvs[j] < id) ++j;
        if (j == pvs.size() || pvs[j] != id) ++missing;
    }
    return missing;
}

// An example of entries with knobs of their own, from the registry: the first
// family's first knob with a plain default, at a quarter and at twice it.
std::string variantExample() {
    for (const FamilyEntry& family : families()) {
        if (family.reference) continue;  // its knobs apply to the reference, not a culler
        for (const Knob& knob : family.knobs) {
            if (!knob.automatic.empty() || knob.default_value <= 0.0) continue;
            double low = std::clamp(knob.default_value / 4, knob.min, knob.max);
            double high = std::clamp(knob.default_value * 2, knob.min, knob.max);
            if (knob.kind == KnobKind::Integer) {
                low = std::round(low);
                high = std::round(high);
            }
            const std::string entry = family.algorithms.front().name + ":" + knob.flag + "=";
            return entry + knobValueText(knob, low) + "," + entry + knobValueText(knob, high) +
                   "\ntimes two values of --" + knob.flag + " side by side.";
        }
    }
    return "";
}

}  // namespace

CLI::App* addBenchCommand(CLI::App& app, BenchCommand& c) {
    CLI::App* cmd = app.add_subcommand(
        "bench",
        "Times the algorithms on the same frames of SCENE, side by side in one process,\n"
        "R runs, and prints one row per algorithm: the median and 95th percentile cull\n"
        "time per frame (each frame's median over runs), the ratio to the first algorithm\n"
        "listed, the mean PVS size, the mean exact visible count, PVS/exact, the false\n"
        "culls (ids the exact oracle sees that the PVS lacks) and the frames that had any,\n"
        "the mean triangles of the PVS, and each algorithm's counters per frame.\n"
        "An --algo entry may set knobs for itself: NAME:FLAG=VALUE[:FLAG=VALUE], e.g.\n" +
            variantExample() + "\nQuote ratios, not milliseconds: the machine may be shared.");
    cmd->add_option("SCENE", c.scene, "the scene file")->required()->type_name("");
    cmd->add_option("--algo", c.algo, "algorithms, comma-separated (listed below)")
        ->required()
        ->type_name("A[,B...]");
    cmd->add_option("--frames", c.frames,
                    "frames to run, 1 to 1000000 (default: the scene's time.frames)")
        ->check(CLI::Range(1LL, 1000000LL).description(""))
        ->type_name("N");
    cmd->add_option("--runs", c.runs, "repetitions, 1 to 1000 (default 5)")
        ->check(CLI::Range(1LL, 1000LL).description(""))
        ->type_name("N");
    c.csv_option =
        cmd->add_option("--csv", c.csv, "also write one row per algorithm and frame to FILE")
            ->type_name("FILE");
    cmd->add_flag("--no-quality", c.no_quality, "skip the exact oracle (pvs only, faster)");
    cmd->add_option("--seek", c.seek,
                    "time the window's seeks instead: a step forward into each frame F\n"
                    "and a step back into it (R runs each), the frames each replayed, and\n"
                    "the memory its checkpoints take")
        ->type_name("F[,G...]");
    c.knobs.addTo(*cmd, false);
    cmd->footer(cullingHelpFooter(appAlgorithmNames()));
    return cmd;
}

int runBench(const BenchCommand& c) {
    std::string error;
    KnobValues knobs, view_flags;
    if (!c.knobs.read(knobs, view_flags, error)) return usageError("bench", error);
    std::vector<AlgoVariant> algos;
    if (!parseAlgoVariants(c.algo, knobs, algos, error)) return usageError("bench", error);

    Scene scene;
    if (!loadSceneOrReport(c.scene, scene)) return kExitSceneRejected;
    const int n_frames = int(c.frames < 0 ? scene.frames : c.frames), n_runs = int(c.runs);
    const bool quality = !c.no_quality;
    std::vector<std::string> run_algorithms;
    for (const AlgoVariant& v : algos) {
        run_algorithms.push_back(registryAlgorithmOf(v.name));
        if (!algorithmFits(run_algorithms.back(), scene, error))
            return usageError("bench", c.scene + ": " + error);
    }
    printUnusedNotes("bench", c.knobs, run_algorithms);
    if (!c.seek.empty()) return runSeekBench(c, scene, algos);

    std::vector<std::unique_ptr<Culler>> cullers;
    std::vector<AlgoBench> benches(algos.size());
    for (size_t i = 0; i < algos.size(); ++i) {
        cullers.push_back(makeAppCuller(algos[i].name, algos[i].knobs, error));
        if (!cullers.back()) {
            std::cerr << "gridcull bench: " << algos[i].label << ": " << error << "\n";
            return kExitFailure;
        }
        AlgoBench& b = benches[i];
        b.algo = algos[i].label;
        b.pvs_triangles.assign(size_t(n_frames), 0);
        b.ms.assign(size_t(n_frames) * size_t(n_runs), 0.0);
        b.pvs_size.assign(size_t(n_frames), 0);
        b.exact_size.assign(size_t(n_frames), -1);
        b.false_culls.assign(size_t(n_frames), 0);
        b.stats.assign(size_t(n_frames), CullStats{});
    }
    std::unique_ptr<Culler> oracle;
    if (quality) {
        oracle = makeCuller(referenceAlgorithm(), knobs, error);
        if (!oracle) {
            std::cerr << "gridcull bench: " << error << "\n";
            return kExitFailure;
        }
        oracle->reset(scene);
    }

    std::printf("scene: %s (%dD, %zu objects), frames 0..%d, %d runs, algorithms: %s\n",
                scene.name.c_str(), scene.dimensions, scene.objects.size(), n_frames - 1, n_runs,
                c.algo.c_str());
    std::printf("options: %s\n", describeKnobs(knobs).c_str());
    std::fflush(stdout);

    ProgressBar progress((long long)n_frames * n_runs);
    FrameResult result, exact;
    const size_t k = algos.size();
    for (int run = 0; run < n_runs; ++run) {
        for (auto& c : cullers) c->reset(scene);
        for (int f = 0; f < n_frames; ++f) {
            const double t = scene.timeOfFrame(f);
            const Camera camera = cameraAt(scene, t);
            if (run == 0 && quality) oracle->cull(scene, camera, t, exact);
            for (size_t turn = 0; turn < k; ++turn) {
                const size_t i = (turn + size_t(f) + size_t(run)) % k;
                timedCull(*cullers[i], scene, camera, t, result);
                AlgoBench& b = benches[i];
                b.ms[size_t(run) * size_t(n_frames) + size_t(f)] = result.stats.cull_ms;
                if (run != 0) continue;
                b.pvs_size[size_t(f)] = int(result.pvs.size());
                for (int id : result.pvs)
                    b.pvs_triangles[size_t(f)] +=
                        trianglesOf(scene.objects[size_t(scene.indexOf(id))]);
                b.stats[size_t(f)] = result.stats;
                if (quality) {
                    b.exact_size[size_t(f)] = int(exact.pvs.size());
                    b.false_culls[size_t(f)] = countMissing(exact.pvs, result.pvs);
                }
            }
            progress.step();
        }
    }

    std::fputs(formatBenchTable(benches, n_frames, n_runs).c_str(), stdout);
    if (c.csv_option->count() > 0) {
        OutputFile csv;
        const std::string text = formatBenchCsv(benches, n_frames, n_runs, scene.dt);
        bool ok = csv.open(c.csv, error);
        if (ok && std::fwrite(text.data(), 1, text.size(), csv.stream()) != text.size()) {
            error = "writing '" + c.csv + "' failed";
            ok = false;
        }
        if (!ok || !csv.commit(error)) {
            std::cerr << "gridcull bench: " << error << "\n";
            return kExitFailure;
        }
        std::printf("csv: %s\n", c.csv.c_str());
    }
    return kExitOk;
}

}  // namespace gridcull
