// `gridcull bench SCENE --algo A[,B...]`: algorithms timed side by side on the same
// frames. Each run resets every culler and replays frames 0..N-1; within a frame the
// algorithms take turns, starting with a different one each frame, so that machine
// noise falls on all of them alike. Quality (PVS against the exact visible set) is
// measured in the first run by a separate, untimed oracle.
//
// With --draw gl each PVS is also drawn (app/pvs_draw_timer.h) right after its
// cull, and a `limit` row draws the oracle's visible set: what a perfect
// culler, free of cost, would leave to draw.
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
#include "app/pvs_draw_timer.h"
#include "culling/registry/registry.h"
#include "culling/scene/object_triangles.h"

namespace gridcull {

namespace {

// The row of bench --draw that draws the exact visible set.
constexpr const char* kLimitRow = "limit";

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
    cmd->add_option("--draw", c.draw,
                    "gl: also draw each PVS with the OpenGL renderer from the culling camera\n"
                    "(offscreen, at the oracle's image size, finished before the clock\n"
                    "stops) and time cull, draw and frame = cull + draw; adds a row\n"
                    "`limit` that draws the exact visible set (no cull time). Needs an X\n"
                    "display: xvfb-run on a headless machine")
        ->check(CLI::IsMember({"gl"}))
        ->type_name("gl");
    cmd->add_option("--baseline", c.baseline,
                    "the row ratios are taken against: an --algo entry, or limit with\n"
                    "--draw (default: the first entry)")
        ->type_name("NAME");
    cmd->add_option("--query-cost", c.query_cost_us,
                    "also model each frame as its measured time plus its queries\n"
                    "(pixel_queries + occlusion_queries) x US microseconds each, a GPU\n"
                    "round trip's cost, 0 to 1e6: column \"model\"")
        ->check(CLI::Range(0.0, 1e6).description(""))
        ->type_name("US");
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
    if (!c.seek.empty()) {
        if (!c.draw.empty())
            return usageError("bench", "--seek times seeks and draws nothing: drop --draw");
        return runSeekBench(c, scene, algos);
    }
    const bool drawing = !c.draw.empty();
    if (drawing && c.no_quality)
        return usageError("bench",
                          "--draw needs the exact oracle for its limit row: drop --no-quality");
    // The rows: the entries, then the limit when drawing.
    std::vector<std::string> row_names;
    for (const AlgoVariant& v : algos) row_names.push_back(v.label);
    if (drawing) row_names.push_back(kLimitRow);
    size_t baseline = 0;
    if (!c.baseline.empty()) {
        const auto found = std::find(row_names.begin(), row_names.end(), c.baseline);
        if (found == row_names.end()) {
            std::string names;
            for (const std::string& n : row_names) names += (names.empty() ? "" : ", ") + n;
            return usageError("bench", "--baseline '" + c.baseline +
                                           "' is not a row; the rows are " + names);
        }
        baseline = size_t(found - row_names.begin());
    }

    std::vector<std::unique_ptr<Culler>> cullers;
    std::vector<AlgoBench> benches(row_names.size());
    for (size_t i = 0; i < benches.size(); ++i) {
        if (i < algos.size()) {
            cullers.push_back(makeAppCuller(algos[i].name, algos[i].knobs, error));
            if (!cullers.back()) {
                std::cerr << "gridcull bench: " << algos[i].label << ": " << error << "\n";
                return kExitFailure;
            }
        }
        benches[i].algo = row_names[i];
        sizeBench(benches[i], n_frames, n_runs, drawing);
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
    PvsDrawTimer draw_timer;
    if (drawing && !draw_timer.init(scene, referenceResolution(knobs), error)) {
        std::cerr << "gridcull bench: --draw gl: " << error << "\n";
        return kExitFailure;
    }
    // The exact visible set of every frame, kept from the first run for the
    // limit row's draws in the others.
    std::vector<std::vector<int>> exact_sets(drawing ? size_t(n_frames) : 0);

    std::printf("scene: %s (%dD, %zu objects), frames 0..%d, %d runs, algorithms: %s\n",
                scene.name.c_str(), scene.dimensions, scene.objects.size(), n_frames - 1, n_runs,
                c.algo.c_str());
    std::printf("options: %s\n", describeKnobs(knobs).c_str());
    if (drawing)
        std::printf("draw: OpenGL (%s), %d x %d pixels, the culling camera's view%s\n",
                    draw_timer.rendererName().c_str(), draw_timer.width(), draw_timer.height(),
                    scene.dimensions == 2 ? " (2D: the top-down map)" : "");
    std::fflush(stdout);

    ProgressBar progress((long long)n_frames * n_runs);
    FrameResult result, exact;
    const size_t k = algos.size();
    for (int run = 0; run < n_runs; ++run) {
        for (auto& c : cullers) c->reset(scene);
        for (int f = 0; f < n_frames; ++f) {
            const double t = scene.timeOfFrame(f);
            const Camera camera = cameraAt(scene, t);
            if (run == 0 && quality) {
                oracle->cull(scene, camera, t, exact);
                if (drawing) exact_sets[size_t(f)] = exact.pvs;
            }
            const size_t slot = size_t(run) * size_t(n_frames) + size_t(f);
            for (size_t turn = 0; turn < benches.size(); ++turn) {
                const size_t i = (turn + size_t(f) + size_t(run)) % benches.size();
                AlgoBench& b = benches[i];
                if (i == k) {  // the limit: the exact set drawn, no cull
                    b.draw_ms[slot] = draw_timer.draw(scene, camera, t, exact_sets[size_t(f)]);
                    if (run == 0) {
                        recordFrame(scene, f, exact, &exact, b);
                        b.stats[size_t(f)] = CullStats{};  // the oracle's are not the limit's
                    }
                    continue;
                }
                timedCull(*cullers[i], scene, camera, t, result);
                b.ms[slot] = result.stats.cull_ms;
                if (drawing) b.draw_ms[slot] = draw_timer.draw(scene, camera, t, result.pvs);
                if (run == 0) recordFrame(scene, f, result, quality ? &exact : nullptr, b);
            }
            progress.step();
        }
    }

    std::fputs(formatBenchTable(benches, n_frames, n_runs, baseline, drawing ? int(k) : -1,
                                    c.query_cost_us).c_str(), stdout);
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
