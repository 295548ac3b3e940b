// `gridcull cull SCENE --algo A [--frames N] [--out FILE]`: culling headless,
// one JSON line per frame.
#include <cstdio>
#include <iostream>

#include "app/app_cullers.h"
#include "app/cli.h"
#include "app/cli_commands.h"
#include "app/frame_json.h"
#include "app/output_file.h"
#include "culling/registry/registry.h"

namespace gridcull {

CLI::App* addCullCommand(CLI::App& app, CullCommand& c) {
    CLI::App* cmd = app.add_subcommand(
        "cull",
        "Runs algorithm A over frames 0..N-1 of SCENE and writes one JSON line per frame:\n"
        "frame, t, algo, camera, the sorted pvs, and stats (cull_ms and the algorithm's\n"
        "counters). Without --out the lines go to standard output. The file appears only\n"
        "when complete.");
    cmd->add_option("SCENE", c.scene, "the scene file")->required()->type_name("");
    cmd->add_option("--algo", c.algo, "one algorithm (listed below)")->required()->type_name("A");
    cmd->add_option("--frames", c.frames,
                    "frames to run, 1 to 100000000 (default: the scene's time.frames)")
        ->check(CLI::Range(1LL, 100000000LL).description(""))
        ->type_name("N");
    c.out_option =
        cmd->add_option("--out", c.out, "write to FILE instead of standard output")->type_name("FILE");
    c.knobs.addTo(*cmd, false);
    cmd->footer(cullingHelpFooter(appAlgorithmNames()));
    return cmd;
}

int runCull(const CullCommand& c) {
    std::vector<std::string> algos;
    std::string error;
    if (!splitAlgorithms(c.algo, algos, error, appAlgorithmNames()))
        return usageError("cull", error);
    if (algos.size() != 1) return usageError("cull", "--algo takes one algorithm here");
    KnobValues knobs, view_flags;
    if (!c.knobs.read(knobs, view_flags, error)) return usageError("cull", error);

    Scene scene;
    if (!loadSceneOrReport(c.scene, scene)) return kExitSceneRejected;
    const long long frames = c.frames < 0 ? scene.frames : c.frames;
    if (!algorithmFits(registryAlgorithmOf(algos[0]), scene, error))
        return usageError("cull", c.scene + ": " + error);
    printUnusedNotes("cull", c.knobs, {registryAlgorithmOf(algos[0])});

    std::unique_ptr<Culler> culler = makeAppCuller(algos[0], knobs, error);
    if (!culler) {
        std::cerr << "gridcull cull: " << error << "\n";
        return kExitFailure;
    }
    OutputFile file;
    std::FILE* out = stdout;
    const bool to_file = c.out_option->count() > 0;
    if (to_file) {
        if (!file.open(c.out, error)) {
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
    if (to_file && !file.commit(error)) {
        std::cerr << "gridcull cull: " << error << "\n";
        return kExitFailure;
    }
    std::fflush(stdout);
    return kExitOk;
}

}  // namespace gridcull
