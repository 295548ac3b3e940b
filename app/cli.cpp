#include "app/cli.h"

#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>

#include "app/cli_args.h"
#include "app/window.h"
#include "culling/scene_loader.h"

namespace gridcull {

namespace {

const char* const kTopHelp =
    "gridcull: see occlusion culling work, frame by frame.\n"
    "\n"
    "usage:\n"
    "  gridcull                       open the window on the built-in default scene\n"
    "  gridcull view SCENE            open the window on a scene file\n"
    "  gridcull cull SCENE --algo A   run culling headless, one JSON line per frame\n"
    "  gridcull bench SCENE --algo A[,B...]\n"
    "                                 time algorithms side by side, print a table\n"
    "  gridcull shot SCENE --frame F --out FILE.png\n"
    "                                 render one frame of the window to a PNG\n"
    "  gridcull CMD --help            help for one command\n"
    "  gridcull --version\n"
    "\n"
    "exit status: 0 done, 2 bad command line, 3 scene rejected, 1 anything else.\n";

}  // namespace

const char* const kCullerOptionsHelp =
    "  --oracle-res N     exact, 3D: pixels on the long side of the ID buffer (default 1024)\n"
    "  --oracle-rays N    exact, 2D: rays per full turn of the sweep (default 16384)\n";

bool readCullerOptions(CliArgs& args, CullerOptions& options) {
    long long res = options.oracle_resolution;
    long long rays = options.oracle_rays_per_turn;
    if (!args.integer("oracle-res", 16, 8192, res)) return false;
    if (!args.integer("oracle-rays", 64, 1 << 22, rays)) return false;
    options.oracle_resolution = int(res);
    options.oracle_rays_per_turn = int(rays);
    return true;
}

bool splitAlgorithms(const std::string& list, std::vector<std::string>& names,
                     std::string& error) {
    names.clear();
    const std::vector<std::string> known = cullerNames();
    std::stringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        bool found = false;
        for (const auto& k : known) found = found || k == name;
        if (!found) {
            std::string all;
            for (const auto& k : known) all += (all.empty() ? "" : ", ") + k;
            error = "unknown algorithm '" + name + "' (known: " + all + ")";
            return false;
        }
        names.push_back(name);
    }
    if (names.empty()) {
        error = "--algo needs at least one algorithm name";
        return false;
    }
    return true;
}

bool loadSceneOrReport(const std::string& path, Scene& scene) {
    SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.scene) {
        for (const auto& message : loaded.errors) std::cerr << message << "\n";
        if (loaded.errors.empty()) std::cerr << path << ": scene rejected\n";
        return false;
    }
    scene = std::move(*loaded.scene);
    return true;
}

int usageError(const char* command, const std::string& message) {
    std::cerr << "gridcull " << command << ": " << message << "\n"
              << "try 'gridcull " << command << " --help'\n";
    return kExitUsage;
}

static int dispatch(int argc, char** argv) {
    if (argc < 2) {
        ViewOptions options;
        return runWindow(defaultScene(), options);
    }
    const std::string command = argv[1];
    if (command == "--help" || command == "-h" || command == "help") {
        std::fputs(kTopHelp, stdout);
        return kExitOk;
    }
    if (command == "--version") {
        std::printf("gridcull %s\n", GRIDCULL_VERSION);
        return kExitOk;
    }
    if (command == "cull") return runCullCommand(argc, argv, 2);
    if (command == "bench") return runBenchCommand(argc, argv, 2);
    if (command == "shot") return runShotCommand(argc, argv, 2);
    if (command == "view") return runViewCommand(argc, argv, 2);
    std::cerr << "gridcull: unknown command '" << command << "'\n" << kTopHelp;
    return kExitUsage;
}

int runCli(int argc, char** argv) {
    // The libraries report bad input as values; this catches what is left
    // (out of memory, say) so that the process still ends with a message.
    try {
        return dispatch(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "gridcull: " << e.what() << "\n";
    } catch (...) {
        std::cerr << "gridcull: unexpected error\n";
    }
    return kExitFailure;
}

}  // namespace gridcull
