// `gridcull shot` (one frame of the window to a PNG) and `gridcull view` (the window).
#include <cstdio>
#include <iostream>

#include "app/cli.h"
#include "app/cli_commands.h"
#include "app/window.h"
#include "culling/registry/registry.h"
#include "ui/registry/family_views.h"

namespace gridcull {

void addWindowOptions(CLI::App& cmd, WindowCommand& c) {
    cmd.add_option("SCENE", c.scene, "the scene file")->required()->type_name("");
    cmd.add_option("--algo", c.algo,
                   std::string("the algorithm whose PVS colours the objects, listed below; "
                               "default ") +
                       defaultAlgorithm() +
                       ", which `gridcull` alone opens with, for view and shot alike so that a "
                       "shot pictures what the window shows (--algo vfc: a picture no occlusion "
                       "culler's changes move)")
        ->type_name("A");
    cmd.add_option("--width", c.width, "window width in pixels, 64 to 8192 (default 1280)")
        ->check(CLI::Range(64LL, 8192LL).description(""))
        ->type_name("N");
    cmd.add_option("--height", c.height, "window height in pixels, 64 to 8192 (default 720)")
        ->check(CLI::Range(64LL, 8192LL).description(""))
        ->type_name("N");
    cmd.add_option("--ui-scale", c.ui_scale,
                   "the panels' font and sizes, 0.5 to 4 (default 1; 2 for a 1080p projector); "
                   "in the window Ctrl+plus and Ctrl+minus change it")
        ->check(CLI::Range(kMinUiScale, kMaxUiScale).description(""))
        ->type_name("S");
    c.knobs.addTo(cmd, true);
    cmd.footer(cullingHelpFooter(algorithmNames()));
}

int prepareWindowCommand(const std::string& command, const WindowCommand& c, Scene& scene,
                         ViewOptions& view) {
    std::string error;
    std::vector<std::string> names;
    if (!splitAlgorithms(c.algo, names, error, algorithmNames())) return usageError(command, error);
    if (names.size() != 1) return usageError(command, "--algo takes one algorithm here");
    if (!c.knobs.read(view.knobs, view.view_flags, error)) return usageError(command, error);
    if (!loadSceneOrReport(c.scene, scene)) return kExitSceneRejected;
    if (!algorithmFits(c.algo, scene, error)) return usageError(command, c.scene + ": " + error);
    if (!checkViewFlags(view.view_flags, scene, error)) return usageError(command, error);
    if (c.frame >= scene.frames)
        return usageError(command, "--frame " + std::to_string(c.frame) +
                                       " is past the scene's last frame " +
                                       std::to_string(scene.frames - 1));
    // The window can switch to any culler later, so only a shot notes what is unused.
    if (command == "shot") printUnusedNotes(command, c.knobs, names);
    view.algo = c.algo;
    view.width = int(c.width);
    view.height = int(c.height);
    view.frame = int(c.frame);
    view.view = c.view;
    view.ui_scale = c.ui_scale;
    return kExitOk;
}

CLI::App* addShotCommand(CLI::App& app, WindowCommand& c) {
    CLI::App* cmd = app.add_subcommand(
        "shot",
        "Renders frame F of SCENE exactly as the window shows it (culling run from frame 0,\n"
        "so temporal state is as in the window) and writes a PNG. Needs an X display: on a\n"
        "headless machine run it under xvfb-run.");
    cmd->add_option("--frame", c.frame, "the frame to draw (0-based)")
        ->required()
        ->check(CLI::Range(0LL, 100000000LL).description(""))
        ->type_name("N");
    cmd->add_option("--out", c.out, "where to write; the file appears only when complete")
        ->required()
        ->type_name("FILE.png");
    cmd->add_option("--view", c.view, viewNamesHelp())->type_name("V");
    addWindowOptions(*cmd, c);
    return cmd;
}

int runShot(const WindowCommand& c) {
    Scene scene;
    ViewOptions view;
    if (const int status = prepareWindowCommand("shot", c, scene, view); status != kExitOk)
        return status;
    std::string error;
    if (!renderShot(scene, view, c.out, error)) {
        std::cerr << "gridcull shot: " << error << "\n";
        return kExitFailure;
    }
    return kExitOk;
}

CLI::App* addViewCommand(CLI::App& app, WindowCommand& c) {
    CLI::App* cmd = app.add_subcommand(
        "view",
        "Opens the debugger window on SCENE. `gridcull` alone opens the built-in default\n"
        "scene (the same as scenes/default.json).");
    cmd->add_option("--frame", c.frame, "start at frame F")
        ->check(CLI::Range(0LL, 100000000LL).description(""))
        ->type_name("N");
    cmd->add_flag("--play", c.play, "start playing instead of paused");
    cmd->add_option("--exit-after", c.exit_after,
                    "close by itself after N frames (for scripted runs)")
        ->check(CLI::Range(0LL, 100000000LL).description(""))
        ->type_name("N");
    addWindowOptions(*cmd, c);
    return cmd;
}

int runView(const WindowCommand& c) {
    Scene scene;
    ViewOptions view;
    if (const int status = prepareWindowCommand("view", c, scene, view); status != kExitOk)
        return status;
    view.play = c.play;
    view.exit_after_frames = int(c.exit_after);
    return runWindow(scene, view);
}

}  // namespace gridcull
