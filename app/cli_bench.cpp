// `gridcull bench SCENE --algo A[,B...]`: algorithms timed side by side on the same
// frames. Each run resets every culler and replays frames 0..N-1; within a frame the
// algorithms take turns, starting with a different one each frame, so that machine
// noise falls on all of them alike. Quality (PVS against the exact visible set) is
// measured in the first run by a separate, untimed oracle.
#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "app/app_cullers.h"
#include "app/bench_table.h"
#include "app/cli.h"
#include "app/cli_args.h"
#include "app/output_file.h"
#include "culling/scene/object_triangles.h"

namespace gridcull {

namespace {

const char* const kBenchHelp =
    "usage: gridcull bench SCENE --algo A[,B...] [--frames N] [--runs R] [--csv FILE]\n"
    "\n"
    "Times the algorithms on the same frames of SCENE, side by side in one process,\n"
    "R runs (default 5), and prints one row per algorithm: the median and 95th\n"
    "percentile cull time per frame (each frame's median over runs), the ratio to the\n"
    "first algorithm listed, the mean PVS size, the mean exact visible count, PVS/exact,\n"
    "the false culls (ids the exact oracle sees that the PVS lacks) and the frames\n"
    "that had any, the mean triangles of the PVS (culling/scene/object_triangles.h), and\n"
    "each algorithm's counters per frame.\n"
    "An --algo entry may set culler options for itself: NAME:FLAG=VALUE[:FLAG=VALUE],\n"
    "e.g. lazy-grid:cell-size=8,lazy-grid:cell-size=64 times two cell sizes side by side.\n"
    "Quote ratios, not milliseconds: the machine may be shared.\n"
    "\n"
    "  --algo A[,B...]    algorithms, comma-separated:";

const char* const kBenchHelpTail =
    "\n"
    "  --frames N         frames to run (default: the scene's time.frames)\n"
    "  --runs R           repetitions (default 5)\n"
    "  --csv FILE         also write one row per algorithm and frame to FILE\n"
    "  --no-quality       skip the exact oracle (pvs only, faster)\n";

class ProgressBar {
public:
    explicit ProgressBar(long long total) : total_(total), enabled_(::isatty(2) != 0) {}
    void step() {
        ++done_;
        if (!enabled_) return;
        const int percent = int(done_ * 100 / total_);
        if (percent == last_percent_) return;
        last_percent_ = percent;
        const int width = 40, filled = percent * width / 100;
        std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled,
                     "########################################", width - filled, "", percent);
        if (done_ == total_) std::fputs("\n", stderr);
        std::fflush(stderr);
    }

private:
    long long total_;
    long long done_ = 0;
    int last_percent_ = -1;
    bool enabled_;
};

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

}  // namespace

int runBenchCommand(int argc, char** argv, int first) {
    CliArgs args(withCullerOptionFlags({"algo", "frames", "runs", "csv"}), {"help", "no-quality"});
    if (!args.parse(argc, argv, first)) return usageError("bench", args.error());
    if (args.has("help")) {
        std::string names;
        for (const auto& n : appCullerNames()) names += " " + n;
        std::printf("%s%s%s%s", kBenchHelp, names.c_str(), kBenchHelpTail, kCullerOptionsHelp);
        return kExitOk;
    }
    if (args.positional().size() != 1) return usageError("bench", "expected one SCENE file");
    if (!args.has("algo")) return usageError("bench", "--algo is required");
    std::string error;
    CullerOptions options;
    long long frames = -1, runs = 5;
    if (!args.integer("frames", 1, 1000000, frames) || !args.integer("runs", 1, 1000, runs) ||
        !readCullerOptions(args, options))
        return usageError("bench", args.error());
    std::vector<AlgoVariant> algos;
    if (!parseAlgoVariants(args.text("algo", ""), options, algos, error))
        return usageError("bench", error);

    Scene scene;
    if (!loadSceneOrReport(args.positional()[0], scene)) return kExitSceneRejected;
    if (frames < 0) frames = scene.frames;
    const int n_frames = int(frames), n_runs = int(runs);
    const bool quality = !args.has("no-quality");

    std::vector<std::unique_ptr<Culler>> cullers;
    std::vector<AlgoBench> benches(algos.size());
    for (size_t i = 0; i < algos.size(); ++i) {
        cullers.push_back(makeAppCuller(algos[i].name, algos[i].options, error));
        if (!cullers.back() || !cullers.back()->supports(scene, error)) {
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
        oracle = makeCuller("exact", options, error);
        if (!oracle) {
            std::cerr << "gridcull bench: " << error << "\n";
            return kExitFailure;
        }
        oracle->reset(scene);
    }

    std::printf("scene: %s (%dD, %zu objects), frames 0..%d, %d runs, algorithms: %s\n",
                scene.name.c_str(), scene.dimensions, scene.objects.size(), n_frames - 1, n_runs,
                args.text("algo", "").c_str());
    std::printf("options: %s\n", describeCullerOptions(options).c_str());
    std::fflush(stdout);

    ProgressBar progress(frames * runs);
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
    if (args.has("csv")) {
        OutputFile csv;
        const std::string text = formatBenchCsv(benches, n_frames, n_runs, scene.dt);
        bool ok = csv.open(args.text("csv", ""), error);
        if (ok && std::fwrite(text.data(), 1, text.size(), csv.stream()) != text.size()) {
            error = "writing '" + args.text("csv", "") + "' failed";
            ok = false;
        }
        if (!ok || !csv.commit(error)) {
            std::cerr << "gridcull bench: " << error << "\n";
            return kExitFailure;
        }
        std::printf("csv: %s\n", args.text("csv", "").c_str());
    }
    return kExitOk;
}

}  // namespace gridcull
