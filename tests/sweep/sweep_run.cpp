#include "tests/sweep/sweep_run.h"

#include <atomic>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <mutex>
#include <thread>

#include "culling/io/scene_writer.h"
#include "tests/sweep/sweep_scenes.h"

namespace gridcull::sweep {

int64_t SweepReport::sceneFrames() const {
    int64_t sum = 0;
    for (const AlgorithmTally& t : tallies) sum += t.frames;
    return sum;
}

int64_t SweepReport::falseCulls() const {
    int64_t sum = 0;
    for (const AlgorithmTally& t : tallies) sum += t.false_culls;
    return sum;
}

KnobValues sweepKnobs(int resolution) {
    KnobValues knobs;
    knobs.set("oracle-res", resolution);
    return knobs;
}

std::string replayCommand(const std::string& file, const std::string& algo, int resolution) {
    return "gridcull cull " + file + " --algo " + algo + " --oracle-res " +
           std::to_string(resolution);
}

namespace {

void add(AlgorithmTally& sum, const AlgorithmTally& t) {
    sum.scenes += t.scenes;
    sum.frames += t.frames;
    sum.false_culls += t.false_culls;
    sum.seconds += t.seconds;
}

std::vector<SweepAlgorithm> algorithmsOf(const SweepOptions& options) {
    return options.algorithms.empty() ? conservativeAlgorithms() : options.algorithms;
}

// Adds a checked scene to the report; the caller holds the report's lock.
void merge(const SceneCheck& check, uint64_t seed, const std::string& kind, const std::string& file,
           SweepReport& report) {
    ++report.scenes;
    for (size_t a = 0; a < check.tallies.size(); ++a) add(report.tallies[a], check.tallies[a]);
    add(report.oracle, check.oracle);
    for (const std::string& e : check.errors)
        report.errors.push_back("seed " + std::to_string(seed) + ": " + e);
    for (const FalseCull& cull : check.false_culls)
        report.failures.push_back({seed, kind, file, cull});
}

// The failing scene's file: written once, under the output folder.
std::string keepFailure(const Scene& scene, uint64_t seed, const std::string& out_dir,
                        std::vector<std::string>& errors) {
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    const std::string file =
        std::filesystem::absolute(out_dir + "/sweep-" + std::to_string(seed) + ".json").string();
    std::string error;
    if (!writeSceneFile(scene, file, error)) {
        errors.push_back("seed " + std::to_string(seed) + ": " + error);
        return "";
    }
    return file;
}

}  // namespace

void addScene(const Scene& scene, uint64_t seed, const SweepOptions& options,
              const std::string& given_file, SweepReport& report) {
    if (report.algorithms.empty()) {
        report.algorithms = algorithmsOf(options);
        report.tallies.resize(report.algorithms.size());
    }
    const SceneCheck check = checkScene(scene, report.algorithms, sweepKnobs(options.resolution));
    std::string file = given_file;
    if (!check.false_culls.empty() && file.empty())
        file = keepFailure(scene, seed, options.out_dir, report.errors);
    merge(check, seed, given_file.empty() ? sceneKind(seed) : "file", file, report);
}

SweepReport runSweep(const SweepOptions& options, std::FILE* progress) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const std::clock_t cpu_start = std::clock();
    SweepReport report;
    report.algorithms = algorithmsOf(options);
    report.tallies.resize(report.algorithms.size());
    std::error_code ec;
    std::filesystem::create_directories(options.out_dir, ec);
    std::mutex lock;
    std::atomic<int64_t> next{0};
    std::atomic<int> running{0};
    const KnobValues knobs = sweepKnobs(options.resolution);
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    auto worker = [&](int index) {
        const std::string work = options.out_dir + "/work-" + std::to_string(index) + ".json";
        for (;;) {
            const int64_t n = next.fetch_add(1);
            if (!options.only_seeds.empty() && n >= int64_t(options.only_seeds.size())) break;
            if (options.only_seeds.empty() && options.scenes >= 0 && n >= options.scenes) break;
            if (options.seconds > 0.0 && elapsed() >= options.seconds) break;
            const uint64_t seed = options.only_seeds.empty() ? options.base_seed + uint64_t(n)
                                                             : options.only_seeds[size_t(n)];
            Scene scene;
            std::string error;
            bool rejected = false;
            if (!replayable(generatedScene(seed), work, scene, error, &rejected)) {
                std::lock_guard<std::mutex> guard(lock);
                (rejected ? report.rejected : report.errors)
                    .push_back("seed " + std::to_string(seed) + ": " + error);
                continue;
            }
            const SceneCheck check = checkScene(scene, report.algorithms, knobs);
            std::vector<std::string> errors;
            const std::string file = check.false_culls.empty()
                                         ? std::string()
                                         : keepFailure(scene, seed, options.out_dir, errors);
            std::lock_guard<std::mutex> guard(lock);
            report.errors.insert(report.errors.end(), errors.begin(), errors.end());
            merge(check, seed, sceneKind(seed), file, report);
        }
        --running;
    };
    const int threads = std::max(1, options.threads);
    std::vector<std::thread> pool;
    running = threads;
    for (int i = 0; i < threads; ++i) pool.emplace_back(worker, i);
    double last = 0.0;
    while (running > 0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        if (!progress || options.progress_seconds <= 0.0 ||
            elapsed() - last < options.progress_seconds)
            continue;
        last = elapsed();
        std::lock_guard<std::mutex> guard(lock);
        std::fprintf(progress,
                     "[sweep] %6.0f s: %lld scenes, %lld scene-frames, %lld false culls\n", last,
                     (long long)report.scenes, (long long)report.sceneFrames(),
                     (long long)report.falseCulls());
        std::fflush(progress);
    }
    for (std::thread& t : pool) t.join();
    for (int i = 0; i < threads; ++i) {
        const std::string work = options.out_dir + "/work-" + std::to_string(i);
        for (const auto& entry : std::filesystem::directory_iterator(options.out_dir, ec))
            if (entry.path().string().rfind(work, 0) == 0)
                std::filesystem::remove(entry.path(), ec);
    }
    report.elapsed = elapsed();
    report.cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    return report;
}

void printReport(const SweepReport& report, const SweepOptions& options, std::FILE* out) {
    std::fprintf(out, "\n%-18s %10s %14s %12s %10s\n", "algorithm", "scenes", "scene-frames",
                 "false culls", "time s");
    for (size_t a = 0; a < report.algorithms.size(); ++a) {
        const AlgorithmTally& t = report.tallies[a];
        std::fprintf(out, "%-18s %10lld %14lld %12lld %10.1f\n", report.algorithms[a].name.c_str(),
                     (long long)t.scenes, (long long)t.frames, (long long)t.false_culls, t.seconds);
    }
    std::fprintf(out, "%-18s %10lld %14lld %12s %10.1f  (the reference)\n", "exact (oracle)",
                 (long long)report.oracle.scenes, (long long)report.oracle.frames, "-",
                 report.oracle.seconds);
    // On a shared machine the wall clock says what this run got; the CPU time
    // says what the frames cost, so both are printed.
    std::fprintf(
        out,
        "\ntotal: %lld scenes, %lld scene-frames checked, %lld false culls, %.1f s "
        "elapsed, %.1f s CPU (%.0f scene-frames a minute, %.0f a CPU minute)\n",
        (long long)report.scenes, (long long)report.sceneFrames(), (long long)report.falseCulls(),
        report.elapsed, report.cpu_seconds,
        report.elapsed > 0 ? 60.0 * double(report.sceneFrames()) / report.elapsed : 0.0,
        report.cpu_seconds > 0 ? 60.0 * double(report.sceneFrames()) / report.cpu_seconds : 0.0);
    for (const std::string& e : report.errors) std::fprintf(out, "error: %s\n", e.c_str());
    for (const std::string& r : report.rejected)
        std::fprintf(out, "not checked, the loader refuses the generated scene: %s\n", r.c_str());
    for (const SweepFailure& f : report.failures) {
        std::string ids;
        for (const int id : f.cull.ids) ids += (ids.empty() ? "" : " ") + std::to_string(id);
        std::fprintf(out,
                     "\nFALSE CULL: %s, seed %llu (%s), frame %d (t = %g): oracle sees {%s}, "
                     "the PVS lacks them\n",
                     f.cull.algo.c_str(), (unsigned long long)f.seed, f.kind.c_str(), f.cull.frame,
                     f.cull.t, ids.c_str());
        if (!f.file.empty()) {
            std::fprintf(out, "  replay: %s\n",
                         replayCommand(f.file, f.cull.algo, options.resolution).c_str());
            std::fprintf(out, "  oracle: %s\n",
                         replayCommand(f.file, "exact", options.resolution).c_str());
        }
        std::fprintf(out, "  or by seed: sweep --scene %llu --res %d\n", (unsigned long long)f.seed,
                     options.resolution);
    }
}

}  // namespace gridcull::sweep
