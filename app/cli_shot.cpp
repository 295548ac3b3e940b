// `gridcull shot` (one frame of the window to a PNG) and `gridcull view` (the window).
#include <cstdio>
#include <iostream>

#include "app/cli.h"
#include "app/cli_commands.h"
#include "app/lesson_file.h"
#include "app/window.h"
#include "culling/registry/registry.h"
#include "ui/registry/family_views.h"

namespace gridcull {

void addWindowOptions(CLI::App& cmd, WindowCommand& c) {
    cmd.add_option("SCENE", c.scene,
                   "the scene file (with --lesson, may be left out: the lesson's first scene)")
        ->type_name("");
    cmd.add_option("--algo", c.algo,
                   std::string("the algorithm whose PVS colours the objects, listed below; "
                               "default ") +
                       defaultAlgorithm() +
                       ", which `gridcull` alone opens with, for view and shot alike so that a "
                       "shot pictures what the window shows (--algo vfc: a picture no occlusion "
                       "culler's changes move)")
        ->type_name("A");
    cmd.add_option("--compare", c.compare,
                   "a second algorithm shown beside the first on the same frame, the view "
                   "split in two, objects in one PVS only outlined in both halves")
        ->type_name("B");
    cmd.add_option("--lesson", c.lesson,
                   "play a lesson file (docs/lesson-format.md): steps with captions, each "
                   "setting the scene, cullers, frame, view and overlays")
        ->type_name("FILE");
    cmd.add_option("--overlays", c.overlays,
                   "the overlay preset family views start with: " + overlayPresetKeys() +
                       " (default: each family's first; a family that does not offer the one "
                       "given starts with its first); view flags set after it override it")
        ->type_name("PRESET");
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

namespace {

// Reads the lesson (with the command line's scene, when given, for the steps
// that name none), and loads its first step's scene when SCENE was left out.
int prepareLesson(const std::string& command, const WindowCommand& c, Scene& scene,
                  ViewOptions& view) {
    const bool have_scene = !c.scene.empty();
    LessonLoadResult loaded = loadLessonFile(c.lesson, have_scene ? &scene : nullptr);
    if (!loaded.lesson) {
        for (const auto& message : loaded.errors) std::cerr << message << "\n";
        return kExitSceneRejected;
    }
    if (c.step < 1 || c.step > int(loaded.lesson->steps.size()))
        return usageError(command, "--step " + std::to_string(c.step) + ": the lesson has steps 1 to " +
                                       std::to_string(loaded.lesson->steps.size()));
    if (!have_scene && !loadSceneOrReport(loaded.lesson->steps.front().scene, scene))
        return kExitSceneRejected;
    view.lesson = std::make_shared<const Lesson>(std::move(*loaded.lesson));
    view.lesson_step = int(c.step) - 1;
    return kExitOk;
}

}  // namespace

int prepareWindowCommand(const std::string& command, const WindowCommand& c, Scene& scene,
                         ViewOptions& view) {
    std::string error;
    std::vector<std::string> names;
    if (!splitAlgorithms(c.algo, names, error, algorithmNames())) return usageError(command, error);
    if (names.size() != 1) return usageError(command, "--algo takes one algorithm here");
    if (!c.knobs.read(view.knobs, view.view_flags, error)) return usageError(command, error);
    if (c.scene.empty() && c.lesson.empty())
        return usageError(command, "SCENE is required (or a --lesson that names its scenes)");
    if (!c.scene.empty() && !loadSceneOrReport(c.scene, scene)) return kExitSceneRejected;
    if (!c.lesson.empty()) {
        if (const int status = prepareLesson(command, c, scene, view); status != kExitOk)
            return status;
    }
    if (!c.overlays.empty()) {
        OverlayPreset preset{};
        if (!parseOverlayPreset(c.overlays, preset))
            return usageError(command, "--overlays '" + c.overlays + "': use one of " +
                                           overlayPresetKeys());
        view.overlays = preset;
    }
    const std::string where = c.scene.empty() ? scene.source_path : c.scene;
    if (!algorithmFits(c.algo, scene, error)) return usageError(command, where + ": " + error);
    if (!c.compare.empty() && !algorithmFits(c.compare, scene, error))
        return usageError(command, "--compare: " + where + ": " + error);
    if (!checkViewFlags(view.view_flags, scene, error)) return usageError(command, error);
    if (c.frame >= scene.frames)
        return usageError(command, "--frame " + std::to_string(c.frame) +
                                       " is past the scene's last frame " +
                                       std::to_string(scene.frames - 1));
    // The window can switch to any culler later, so only a shot notes what is unused.
    if (command == "shot") printUnusedNotes(command, c.knobs, names);
    view.algo = c.algo;
    view.compare = c.compare;
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
    c.frame_option = cmd->add_option("--frame", c.frame,
                                     "the frame to draw (0-based); required unless --lesson "
                                     "gives it")
        ->check(CLI::Range(0LL, 100000000LL).description(""))
        ->type_name("N");
    cmd->add_option("--out", c.out, "where to write; the file appears only when complete")
        ->required()
        ->type_name("FILE.png");
    cmd->add_option("--view", c.view, viewNamesHelp())->type_name("V");
    cmd->add_option("--step", c.step,
                    "with --lesson: the step to draw, from 1, as it ends (its animation done); "
                    "the step sets the frame, so --frame is not needed")
        ->check(CLI::Range(1LL, 100000LL).description(""))
        ->type_name("N");
    addWindowOptions(*cmd, c);
    return cmd;
}

int runShot(const WindowCommand& c) {
    if (c.lesson.empty() && c.frame_option && c.frame_option->count() == 0)
        return usageError("shot", "--frame is required (or --lesson, whose step sets the frame)");
    Scene scene;
    ViewOptions view;
    if (const int status = prepareWindowCommand("shot", c, scene, view); status != kExitOk)
        return status;
    view.lesson_step_finished = true;
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
