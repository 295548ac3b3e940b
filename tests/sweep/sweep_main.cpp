// `sweep`: every conservative algorithm of the family registry against the
// exact oracle on fresh seeded random scenes until the time is up
// (scripts/sweep.sh MINUTES runs it; docs/ARCHITECTURE.md, "The long sweep").
//
//   sweep [MINUTES] [--seed N] [--scenes N] [--scene SEED]... [--file SCENE]
//         [--res R] [--threads T] [--out DIR]
//
// Exit status: 0 with no false cull, 1 with one or more (or a scene that could
// not be written, or a PVS out of order), 2 on a bad command line. Generated
// scenes the loader refuses are listed as not checked; they do not change it.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>

#include "culling/io/scene_loader.h"
#include "tests/sweep/sweep_run.h"

namespace {

using gridcull::sweep::SweepOptions;

int usage(const std::string& message) {
    std::fprintf(stderr,
                 "sweep: %s\n"
                 "usage: sweep [MINUTES] [--seed N] [--scenes N] [--scene SEED]... [--file SCENE]\n"
                 "             [--res R] [--threads T] [--out DIR]\n"
                 "  MINUTES      run for this long (default 1 unless --scenes, --scene or --file)\n"
                 "  --seed N     base seed: scene k has seed N + k (default: from the clock)\n"
                 "  --scenes N   stop after N scenes\n"
                 "  --scene S    check scene seed S only (repeatable): replays a failure\n"
                 "  --file F     check the scene file F only\n"
                 "  --res R      the oracle's resolution, 16 to 8192; image-space cullers match it "
                 "(default 160)\n"
                 "  --threads T  1 to 64 worker threads (default 2)\n"
                 "  --out DIR    where failing scenes are written (default sweep-out)\n",
                 message.c_str());
    return 2;
}

// A whole non-negative number in [lo, hi], or false.
bool number(const char* text, double lo, double hi, double& out) {
    char* end = nullptr;
    out = std::strtod(text, &end);
    return end != text && *end == '\0' && out >= lo && out <= hi;
}

}  // namespace

int main(int argc, char** argv) {
    SweepOptions options;
    options.base_seed =
        uint64_t(std::chrono::system_clock::now().time_since_epoch().count()) % 1000000000000ull;
    std::string file;
    double minutes = -1.0;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            usage("every conservative algorithm against the exact oracle on random scenes");
            return 0;
        }
        const bool has_value = i + 1 < argc;
        double v = 0.0;
        if (arg == "--seed" || arg == "--scenes" || arg == "--scene" || arg == "--res" ||
            arg == "--threads" || arg == "--out" || arg == "--file") {
            if (!has_value) return usage(arg + " needs a value");
            const char* value = argv[++i];
            if (arg == "--out") {
                options.out_dir = value;
            } else if (arg == "--file") {
                file = value;
            } else if (arg == "--res") {
                if (!number(value, 16, 8192, v) || v != double(int(v)))
                    return usage("--res: expected an integer from 16 to 8192, got " +
                                 std::string(value));
                options.resolution = int(v);
            } else if (arg == "--threads") {
                if (!number(value, 1, 64, v) || v != double(int(v)))
                    return usage("--threads: expected an integer from 1 to 64, got " +
                                 std::string(value));
                options.threads = int(v);
            } else {
                char* end = nullptr;
                const unsigned long long n = std::strtoull(value, &end, 10);
                if (end == value || *end != '\0' || value[0] == '-')
                    return usage(arg + ": expected a whole number >= 0, got " + value);
                if (arg == "--seed") options.base_seed = n;
                if (arg == "--scenes") options.scenes = int64_t(n);
                if (arg == "--scene") options.only_seeds.push_back(n);
            }
        } else if (minutes < 0 && number(arg.c_str(), 0.001, 100000, v)) {
            minutes = v;
        } else {
            return usage("unexpected argument '" + arg + "'");
        }
    }
    if (minutes < 0 && options.scenes < 0 && options.only_seeds.empty() && file.empty())
        minutes = 1.0;
    options.seconds = minutes > 0 ? minutes * 60.0 : 0.0;

    // The output folder is where every scene is written before it is checked:
    // one that cannot be made stops the run before it starts.
    std::error_code ec;
    std::filesystem::create_directories(options.out_dir, ec);
    if (!std::filesystem::is_directory(options.out_dir, ec))
        return usage("--out " + options.out_dir + ": cannot create the folder");

    gridcull::sweep::SweepReport report;
    if (!file.empty()) {
        gridcull::SceneLoadResult loaded = gridcull::loadSceneFile(file);
        if (!loaded.scene) {
            for (const std::string& e : loaded.errors) std::fprintf(stderr, "%s\n", e.c_str());
            return 2;
        }
        std::printf("sweep: checking %s at --oracle-res %d\n", file.c_str(), options.resolution);
        const auto start = std::chrono::steady_clock::now();
        const std::clock_t cpu_start = std::clock();
        gridcull::sweep::addScene(*loaded.scene, loaded.scene->seed, options, file, report);
        report.elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        report.cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    } else {
        std::printf(
            "sweep: base seed %llu (--seed %llu repeats this run), --oracle-res %d, "
            "%d threads, ",
            (unsigned long long)options.base_seed, (unsigned long long)options.base_seed,
            options.resolution, options.threads);
        if (options.seconds > 0)
            std::printf("%.1f minutes\n", minutes);
        else
            std::printf("%lld scenes\n", (long long)(options.only_seeds.empty()
                                                         ? options.scenes
                                                         : int64_t(options.only_seeds.size())));
        std::fflush(stdout);
        report = gridcull::sweep::runSweep(options, stdout);
    }
    gridcull::sweep::printReport(report, options, stdout);
    return report.falseCulls() > 0 || !report.errors.empty() ? 1 : 0;
}
