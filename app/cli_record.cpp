// `gridcull record SCENE --algo A --from F --to G --out FILE`: the window over a
// range of frames, drawn off screen exactly as `shot` draws one (panels and
// overlays included, wall-clock times hidden), culled once in order from frame
// 0. FILE.gif: an animated GIF at the scene's speed (app/gif_writer.h).
// Anything else: a folder of PNGs frame-NNNNN.png (NNNNN the scene frame),
// made beside it and renamed into place when complete, so that an interrupted
// recording leaves nothing that looks finished.
#include <filesystem>
#include <iostream>

#include "app/cli.h"
#include "app/cli_commands.h"
#include "app/gif_writer.h"
#include "app/offscreen_window.h"
#include "app/output_file.h"
#include "app/png_file.h"
#include "app/progress_bar.h"

namespace gridcull {

namespace {

bool endsWith(const std::string& text, const std::string& end) {
    return text.size() >= end.size() &&
           text.compare(text.size() - end.size(), end.size(), end) == 0;
}

std::string frameFileName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%05d.png", frame);
    return name;
}

// Removes a half-written PNG folder unless released.
struct PartialFolder {
    std::filesystem::path path;
    bool keep = false;
    ~PartialFolder() {
        std::error_code ignored;
        if (!keep && !path.empty()) std::filesystem::remove_all(path, ignored);
    }
};

// Every step of the lesson the debugger plays, from the first: one image per
// value of the step's animation, then the step as it ends, each held as long
// as the lesson holds it. `record(seconds, file name)` draws and writes one.
template <typename Record>
bool recordLesson(Debugger& debugger, Record& record) {
    const int steps = debugger.lesson().stepCount();
    ProgressBar progress(steps);
    bool ok = true;
    for (int k = 0; ok && k < steps; ++k) {
        debugger.goToLessonStep(k);
        const LessonStep& step = debugger.lesson().step();
        for (int image = 0; ok; ++image) {
            char name[64];
            std::snprintf(name, sizeof name, "step-%03d-%04d.png", k + 1, image);
            const bool animating = debugger.lesson().animating();
            ok = record(animating ? step.animate.seconds_per_value : step.seconds, name);
            if (!animating) break;
            debugger.advancePlayback(step.animate.seconds_per_value);
        }
        progress.step();
    }
    return ok;
}

}  // namespace

CLI::App* addRecordCommand(CLI::App& app, RecordCommand& c) {
    CLI::App* cmd = app.add_subcommand(
        "record",
        "Draws the window (3D / 2D view and panels, as shot draws it) at every frame from F\n"
        "to G and writes them as an animated GIF (--out FILE.gif, at the scene's speed) or\n"
        "as a folder of PNGs frame-NNNNN.png (any other --out). Needs an X display: on a\n"
        "headless machine run it under xvfb-run.");
    cmd->add_option("--from", c.from, "the first frame (0-based, default 0)")
        ->check(CLI::Range(0LL, 100000000LL).description(""))
        ->type_name("F");
    cmd->add_option("--to", c.to, "the last frame (default the scene's last)")
        ->check(CLI::Range(0LL, 100000000LL).description(""))
        ->type_name("G");
    cmd->add_option("--out", c.out, "FILE.gif, or a folder for PNGs (made; must not exist)")
        ->required()
        ->type_name("FILE");
    cmd->add_option("--view", c.window.view, viewNamesHelp())->type_name("V");
    addWindowOptions(*cmd, c.window);
    cmd->get_option("--lesson")
        ->description(
            "record a lesson file (docs/lesson-format.md) instead of a frame range: every "
            "step from the first, one image per value of its animation, each shown as long "
            "as the lesson shows it, captions and overlays included (no --from, --to)");
    return cmd;
}

int runRecord(const RecordCommand& c) {
    Scene scene;
    ViewOptions view;
    WindowCommand window = c.window;
    window.frame = c.from;
    const bool lesson = !window.lesson.empty();
    if (lesson && (c.from != 0 || c.to >= 0))
        return usageError("record", "--lesson records the lesson's own frames: no --from, --to");
    if (const int status = prepareWindowCommand("record", window, scene, view); status != kExitOk)
        return status;
    const int last = int(c.to < 0 ? scene.frames - 1 : c.to);
    if (!lesson && (last < int(c.from) || last >= scene.frames))
        return usageError("record", "--to " + std::to_string(last) + " must lie from --from " +
                                        std::to_string(c.from) + " to the scene's last frame " +
                                        std::to_string(scene.frames - 1));
    const bool gif = endsWith(c.out, ".gif");
    namespace fs = std::filesystem;
    std::error_code exists_error;
    if (!gif && fs::exists(c.out, exists_error))
        return usageError(
            "record", "--out '" + c.out + "' exists: PNGs go into a new folder (or give FILE.gif)");

    std::string error;
    OffscreenWindow offscreen;
    GifWriter writer;
    PartialFolder folder;
    bool ok = offscreen.open(scene, view, error);
    if (ok && gif) ok = writer.open(c.out, offscreen.width(), offscreen.height(), error);
    if (ok && !gif) {
        folder.path = temporarySibling(c.out);
        ok = fs::create_directories(folder.path, exists_error);
        if (!ok) error = "cannot make the folder '" + folder.path.string() + "'";
    }
    std::vector<uint8_t> rgba;
    // One image: drawn, then added to the GIF for `seconds` or written as `name`.
    auto record = [&](double seconds, const std::string& name) {
        ok = offscreen.draw(rgba, error);
        // GIF players show 2 hundredths at the least.
        const int delay_cs = std::max(int(seconds * 100.0 + 0.5), 2);
        if (ok && gif) ok = writer.addFrame(rgba, delay_cs, error);
        if (ok && !gif)
            ok = writePngFile((folder.path / name).string(), offscreen.width(), offscreen.height(),
                              rgba, error);
        return ok;
    };
    if (lesson) {
        ok = ok && recordLesson(offscreen.debugger(), record);
    } else {
        ProgressBar progress(last - int(c.from) + 1);
        for (int frame = int(c.from); ok && frame <= last; ++frame) {
            if (frame > c.from) offscreen.debugger().session().step();
            record(scene.dt, frameFileName(frame));
            progress.step();
        }
    }
    if (ok && gif) ok = writer.close(error);
    if (ok && !gif) {
        fs::rename(folder.path, c.out, exists_error);
        ok = !exists_error;
        if (ok)
            folder.keep = true;
        else
            error = "cannot rename '" + folder.path.string() + "' to '" + c.out + "'";
    }
    if (!ok) {
        std::cerr << "gridcull record: " << error << "\n";
        return kExitFailure;
    }
    if (lesson)
        std::printf("recorded the lesson %s: %s\n", window.lesson.c_str(), c.out.c_str());
    else
        std::printf("recorded frames %lld to %d of %s: %s\n", c.from, last, scene.name.c_str(),
                    c.out.c_str());
    return kExitOk;
}

}  // namespace gridcull
