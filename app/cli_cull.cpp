// `gridcull cull SCENE --algo A [--frames N] [--out FILE]`: culling headless,
// one JSON line per frame.
#include <cstdio>
#include <iostream>

#include "app/app_cullers.h"
#include "app/cli.h"
#include "app/cli_args.h"
#include "app/frame_json.h"
#include "app/output_file.h"

namespace gridcull {

namespace {

const char* const kCullHelp =
    "usage: gridcull cull SCENE --algo A [--frames N] [--out FILE] [options]\n"
    "\n"
    "Runs algorithm A over frames 0..N-1 of SCENE and writes one JSON line per frame:\n"
    "frame, t, algo, camera, the sorted pvs, and stats (cull_ms and the algorithm's\n"
    "counters). Without --out the lines go to standard output. The file appears only\n"
    "when complete.\n"
    "\n"
    "  --algo A           one algorithm (gridcull bench --help lists them)\n"
    "  --frames N         frames to run (default: the scene's time.frames)\n"
    "  --out FILE         write to FILE instead of standard output\n";

}  // namespace

int runCullCommand(int argc, char** argv, int first) {
    CliArgs args(withCullerOptionFlags({"algo", "frames", "out"}), {"help"});
    if (!args.parse(argc, argv, first)) return usageError("cull", args.error());
    if (args.has("help")) {
        std::printf("%s%s", kCullHelp, kCullerOptionsHelp);
        return kExitOk;
    }
    if (args.positional().size() != 1) return usageError("cull", "expected one SCENE file");
    if (!args.has("algo")) return usageError("cull", "--algo is required");
    std::vector<std::string> algos;
    std::string error;
    if (!splitAlgorithms(args.text("algo", ""), algos, error, appCullerNames()))
        return usageError("cull", error);
    if (algos.size() != 1) return usageError("cull", "--algo takes one algorithm here");
    CullerOptions options;
    long long frames = -1;
    if (!args.integer("frames", 1, 100000000, frames) || !readCullerOptions(args, options))
        return usageError("cull", args.error());

    Scene scene;
    if (!loadSceneOrReport(args.positional()[0], scene)) return kExitSceneRejected;
    if (frames < 0) frames = scene.frames;

    std::unique_ptr<Culler> culler = makeAppCuller(algos[0], options, error);
    if (!culler) {
        std::cerr << "gridcull cull: " << error << "\n";
        return kExitFailure;
    }
    if (!culler->supports(scene, error)) {
        std::cerr << "gridcull cull: " << algos[0] << ": " << error << "\n";
        return kExitFailure;
    }
    OutputFile file;
    std::FILE* out = stdout;
    if (args.has("out")) {
        if (!file.open(args.text("out", ""), error)) {
            std::cerr << "gridcull cull: " << error << "\n";
            return kExitFailure;
        }
        out = file.stream();
    }

    culler->reset(scene);
    FrameResult result;
    std::string line;
    for (int frame = 0; frame < int(frames); ++frame) {
        const double t = scene.timeOfFrame(frame);
        const Camera camera = cameraAt(scene, t);
        timedCull(*culler, scene, camera, t, result);
        line.clear();
        appendFrameJson(line, frame, t, culler->name(), camera, result);
        std::fwrite(line.data(), 1, line.size(), out);
    }
    if (args.has("out") && !file.commit(error)) {
        std::cerr << "gridcull cull: " << error << "\n";
        return kExitFailure;
    }
    std::fflush(stdout);
    return kExitOk;
}

}  // namespace gridcull
