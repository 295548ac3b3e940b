// `gridcull shot` (one frame of the window to a PNG) and `gridcull view` (the window).
#include <cstdio>
#include <iostream>
#include <limits>

#include "app/cli.h"
#include "app/cli_args.h"
#include "app/window.h"

namespace gridcull {

namespace {

const char* const kShotHelp =
    "usage: gridcull shot SCENE --frame F --out FILE.png [--view V] [--algo A]\n"
    "                     [--width W] [--height H] [--layer N] [--occluder K]\n"
    "                     [--lazy-object ID]\n"
    "\n"
    "Renders frame F of SCENE exactly as the window shows it (culling run from frame 0,\n"
    "so temporal state is as in the window) and writes a PNG. Needs an X display: on a\n"
    "headless machine run it under xvfb-run.\n"
    "\n"
    "  --frame F          the frame to draw (0-based)\n"
    "  --out FILE.png     where to write; the file appears only when complete\n"
    "  --view V           ";

const char* const kShotRgvcHelp =
    "  --layer N          rgvc, 2D: show the traversal up to chess layer N, that layer\n"
    "                     and its seed highlighted (default: every layer)\n"
    "  --occluder K       rgvc, 2D: pick extended occluder K (0-based, in the order the\n"
    "                     traversal found them) and draw its extension steps and\n"
    "                     occlusion polygon (default: none)\n";

const char* const kShotLazyHelp =
    "  --lazy-object ID   the lazy / busy grids, 3D: pick object ID (its scene\n"
    "                     id) as a click in the window does: the cells its\n"
    "                     deciding test touched and its screen rectangle over the\n"
    "                     view through the culling camera (--view camera or\n"
    "                     main-camera), the step that decided it in the panel\n"
    "                     (default: none)\n";

const char* const kViewHelp =
    "usage: gridcull view SCENE [--algo A] [--frame F] [--width W] [--height H]\n"
    "\n"
    "Opens the debugger window on SCENE. `gridcull` alone opens the built-in default\n"
    "scene (the same as scenes/default.json).\n"
    "\n"
    "  --algo A           the algorithm whose PVS colours the objects (default vfc)\n"
    "  --frame F          start at frame F\n"
    "  --play             start playing instead of paused\n"
    "  --exit-after N     close by itself after N frames (for scripted runs)\n";

const char* const kWindowFlagsHelp =
    "  --width W, --height H   window size in pixels (default 1280x720)\n";

bool readViewOptions(CliArgs& args, ViewOptions& view) {
    long long frame = view.frame, width = view.width, height = view.height;
    long long exit_after = view.exit_after_frames;
    if (!args.integer("frame", 0, 100000000, frame) || !args.integer("width", 64, 8192, width) ||
        !args.integer("height", 64, 8192, height) ||
        !args.integer("exit-after", 0, 100000000, exit_after) ||
        !readCullerOptions(args, view.culler))
        return false;
    view.frame = int(frame);
    view.width = int(width);
    view.height = int(height);
    view.exit_after_frames = int(exit_after);
    view.algo = args.text("algo", view.algo);
    view.view = args.text("view", view.view);
    return true;
}

bool checkAlgo(const ViewOptions& view, std::string& error) {
    std::vector<std::string> names;
    if (!splitAlgorithms(view.algo, names, error)) return false;
    if (names.size() != 1) {
        error = "--algo takes one algorithm here";
        return false;
    }
    return true;
}

}  // namespace

int runShotCommand(int argc, char** argv, int first) {
    CliArgs args(withCullerOptionFlags({"frame", "out", "view", "algo", "width", "height", "layer",
                                        "occluder", "lazy-object"}),
                 {"help"});
    if (!args.parse(argc, argv, first)) return usageError("shot", args.error());
    if (args.has("help")) {
        std::printf(
            "%s%s\n  --algo A           the algorithm that colours the objects "
            "(default vfc)\n%s%s%s%s",
            kShotHelp, viewNamesHelp(), kShotRgvcHelp, kShotLazyHelp, kWindowFlagsHelp,
            kCullerOptionsHelp);
        return kExitOk;
    }
    if (args.positional().size() != 1) return usageError("shot", "expected one SCENE file");
    if (!args.has("out")) return usageError("shot", "--out FILE.png is required");
    if (!args.has("frame")) return usageError("shot", "--frame F is required");
    ViewOptions view;
    std::string error;
    if (!readViewOptions(args, view)) return usageError("shot", args.error());
    if (!checkAlgo(view, error)) return usageError("shot", error);
    long long layer = view.rgvc_layer, occluder = view.rgvc_occluder;
    long long lazy_object = view.lazy_object;
    if (!args.integer("layer", 0, 100000000, layer) ||
        !args.integer("occluder", 0, 100000000, occluder) ||
        !args.integer("lazy-object", 0, std::numeric_limits<int>::max(), lazy_object))
        return usageError("shot", args.error());
    view.rgvc_layer = layer;
    view.rgvc_occluder = int(occluder);
    view.lazy_object = int(lazy_object);

    Scene scene;
    if (!loadSceneOrReport(args.positional()[0], scene)) return kExitSceneRejected;
    if (view.frame >= scene.frames) {
        return usageError("shot", "--frame " + std::to_string(view.frame) +
                                      " is past the scene's last frame " +
                                      std::to_string(scene.frames - 1));
    }
    if (view.lazy_object >= 0 && scene.indexOf(view.lazy_object) < 0) {
        return usageError("shot", "--lazy-object " + std::to_string(view.lazy_object) +
                                      ": the scene has no object with that id");
    }
    if (!renderShot(scene, view, args.text("out", ""), error)) {
        std::cerr << "gridcull shot: " << error << "\n";
        return kExitFailure;
    }
    return kExitOk;
}

int runViewCommand(int argc, char** argv, int first) {
    CliArgs args(withCullerOptionFlags({"frame", "algo", "width", "height", "exit-after"}),
                 {"help", "play"});
    if (!args.parse(argc, argv, first)) return usageError("view", args.error());
    if (args.has("help")) {
        std::printf("%s%s%s", kViewHelp, kWindowFlagsHelp, kCullerOptionsHelp);
        return kExitOk;
    }
    if (args.positional().size() != 1) return usageError("view", "expected one SCENE file");
    ViewOptions view;
    std::string error;
    if (!readViewOptions(args, view)) return usageError("view", args.error());
    if (!checkAlgo(view, error)) return usageError("view", error);
    view.play = args.has("play");
    Scene scene;
    if (!loadSceneOrReport(args.positional()[0], scene)) return kExitSceneRejected;
    return runWindow(scene, view);
}

}  // namespace gridcull
