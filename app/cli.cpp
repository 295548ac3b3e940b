#include "app/cli.h"

#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>

#include "app/app_cullers.h"
#include "app/cli_args.h"
#include "app/window.h"
#include "culling/oracle/exact_oracle.h"
#include "culling/io/scene_loader.h"

namespace gridcull {

namespace {

// The smallest --oracle-res and --oracle-rays accepted: below them the oracle
// resolves too little to be worth calling exact.
constexpr int kMinOracleResolutionFlag = 16;
constexpr int kMinOracleRaysFlag = 64;
// rgvc's knobs: a TBV valid for less than a millisecond or longer than a day
// means nothing in a scene of frames; 8192 is the 2D grid budget's side.
constexpr double kMinRgvcValidity = 0.001;
constexpr double kMaxRgvcValidity = 86400.0;
constexpr int kMaxGridResFlag = 8192;
// The lazy grid's cells: one pixel is the finest possible, 1024 more than any
// view needs (a cell larger than the image is one cell).
constexpr int kMaxCellSizeFlag = 1024;

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

namespace {

// Built from the constants that enforce the limits, so help cannot drift from
// them (docs/LIMITS.md lists them all). Every culling command prints it.
std::string cullerOptionsHelpText() {
    char text[4096];
    std::snprintf(
        text, sizeof text,
        "  --oracle-res N     exact, 3D: pixels on the long side of the ID buffer,\n"
        "                     %d..%d (default 1024)\n"
        "  --oracle-rays N    exact, 2D: rays per full turn of the sweep, %d..%d\n"
        "                     (default 16384)\n"
        "  --rgvc-validity S  rgvc: validity period of a TBV in seconds, %g..%g\n"
        "                     (default 0.5; shorter: fewer revealed TBVs, more updates)\n"
        "  --grid-res N       rgvc: voxels along the world's longest axis, 1..%d\n"
        "                     (default: the scene's grid.resolution)\n"
        "  --lazy-res N       the lazy / busy grids: pixels on the long side of their\n"
        "                     software buffers, %d..%d (default: the --oracle-res\n"
        "                     value, so that false culls compare like with like)\n"
        "  --cell-size N      lazy / busy grid: cell side in pixels, 1..%d (default 32;\n"
        "                     smaller: more cells to read, fewer pixels per query)\n"
        "  --lazy-prob P      lazy / busy grid, section 6: rate a cell free without a\n"
        "                     pixel query while less than P of it was drawn into, 0..1\n"
        "                     (default 0, off)\n"
        "  --lazy-border-whole F\n"
        "                     lazy / busy grid, section 6: query a border cell whole\n"
        "                     when the box covers more than F of it, 0..1 (default 0, off)\n"
        "  --lazy-large-box F lazy / busy grid, section 6: border cells count as\n"
        "                     internal for a box over F of the image, 0..1 (default 0, off)\n"
        "\n"
        "scene limits (docs/LIMITS.md); a file beyond them is rejected, exit status 3:\n"
        "  every number       finite and at most %.0f in magnitude (coordinates,\n"
        "                     sizes, speeds, times)\n"
        "  grid.resolution    at most %lld voxels in all (2D: 8192 x 8192; 3D: 406^3)\n"
        "  camera.fov_deg     3D: in (0, 180); 2D: in (0, 360]\n"
        "  camera.near, far   0 < near < far; aspect > 0\n"
        "  objects            at most %lld, listed and generated together\n"
        "  time.frames        1 to %lld; time.dt > 0\n",
        kMinOracleResolutionFlag, kMaxOracleResolution, kMinOracleRaysFlag, kMaxOracleRaysPerTurn,
        kMinRgvcValidity, kMaxRgvcValidity, kMaxGridResFlag, kMinOracleResolutionFlag,
        kMaxOracleResolution, kMaxCellSizeFlag, kMaxSceneCoordinate, (long long)kMaxGridVoxels,
        (long long)kMaxSceneObjects, (long long)kMaxSceneFrames);
    return text;
}

const std::string& cullerOptionsHelp() {
    static const std::string text = cullerOptionsHelpText();
    return text;
}

}  // namespace

const char* const kCullerOptionsHelp = cullerOptionsHelp().c_str();

bool readCullerOptions(CliArgs& args, CullerOptions& options) {
    long long res = options.oracle_resolution;
    long long rays = options.oracle_rays_per_turn;
    if (!args.integer("oracle-res", kMinOracleResolutionFlag, kMaxOracleResolution, res))
        return false;
    if (!args.integer("oracle-rays", kMinOracleRaysFlag, kMaxOracleRaysPerTurn, rays)) return false;
    long long grid_res = options.rgvc_grid_resolution;
    if (!args.number("rgvc-validity", kMinRgvcValidity, kMaxRgvcValidity,
                     options.rgvc_validity_s) ||
        !args.integer("grid-res", 1, kMaxGridResFlag, grid_res))
        return false;
    long long lazy_res = options.lazy_resolution, cell_size = options.lazy_cell_size;
    if (args.has("lazy-res") &&
        !args.integer("lazy-res", kMinOracleResolutionFlag, kMaxOracleResolution, lazy_res))
        return false;
    if (!args.integer("cell-size", 1, kMaxCellSizeFlag, cell_size) ||
        !args.number("lazy-prob", 0.0, 1.0, options.lazy_probability_threshold) ||
        !args.number("lazy-border-whole", 0.0, 1.0, options.lazy_border_whole_fraction) ||
        !args.number("lazy-large-box", 0.0, 1.0, options.lazy_large_box_fraction))
        return false;
    options.oracle_resolution = int(res);
    options.oracle_rays_per_turn = int(rays);
    options.rgvc_grid_resolution = int(grid_res);
    options.lazy_resolution = int(lazy_res);
    options.lazy_cell_size = int(cell_size);
    return true;
}

std::set<std::string> withCullerOptionFlags(std::set<std::string> own) {
    own.insert({"oracle-res", "oracle-rays", "rgvc-validity", "grid-res", "lazy-res", "cell-size",
                "lazy-prob", "lazy-border-whole", "lazy-large-box"});
    return own;
}

std::string describeCullerOptions(const CullerOptions& options) {
    char text[512];
    std::snprintf(
        text, sizeof text,
        "oracle-res=%d oracle-rays=%d rgvc-validity=%g grid-res=%s lazy-res=%s "
        "cell-size=%d lazy-prob=%g lazy-border-whole=%g lazy-large-box=%g",
        options.oracle_resolution, options.oracle_rays_per_turn, options.rgvc_validity_s,
        options.rgvc_grid_resolution > 0 ? std::to_string(options.rgvc_grid_resolution).c_str()
                                         : "scene",
        options.lazy_resolution > 0 ? std::to_string(options.lazy_resolution).c_str() : "oracle",
        options.lazy_cell_size, options.lazy_probability_threshold,
        options.lazy_border_whole_fraction, options.lazy_large_box_fraction);
    return text;
}

bool splitAlgorithms(const std::string& list, std::vector<std::string>& names, std::string& error,
                     const std::vector<std::string>& known) {
    names.clear();
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

bool parseAlgoVariants(const std::string& list, const CullerOptions& base,
                       std::vector<AlgoVariant>& variants, std::string& error) {
    variants.clear();
    std::stringstream in(list);
    std::string entry;
    while (std::getline(in, entry, ',')) {
        std::vector<std::string> parts;
        std::stringstream fields(entry);
        std::string field;
        while (std::getline(fields, field, ':')) parts.push_back(field);
        if (parts.empty()) parts.push_back("");
        std::vector<std::string> names;
        if (!splitAlgorithms(parts[0], names, error, appCullerNames())) return false;
        AlgoVariant variant{entry, parts[0], base};
        std::vector<std::string> flags;
        for (size_t i = 1; i < parts.size(); ++i) {
            if (parts[i].find('=') == std::string::npos) {
                error = "--algo entry '" + entry + "': expected FLAG=VALUE after ':', got '" +
                        parts[i] + "'";
                return false;
            }
            flags.push_back("--" + parts[i]);
        }
        std::vector<char*> argv;
        for (std::string& f : flags) argv.push_back(f.data());
        CliArgs args(withCullerOptionFlags({}), {});
        if (!args.parse(int(argv.size()), argv.data(), 0) ||
            !readCullerOptions(args, variant.options)) {
            error = "--algo entry '" + entry + "': " + args.error();
            return false;
        }
        variants.push_back(std::move(variant));
    }
    if (variants.empty()) {
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
