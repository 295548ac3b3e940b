// The desktop debugger and its off-screen twin. Both draw the same frame the same
// way, so `gridcull shot` is a picture of what the window shows.
#pragma once
#include <cstdint>
#include <string>

#include "culling/api/culler.h"
#include "culling/scene/scene.h"

namespace gridcull {

struct ViewOptions {
    std::string algo = "vfc";   // the culler whose PVS colours the objects
    int width = 1280;           // window / image size in pixels
    int height = 720;
    int frame = 0;              // first frame shown (shot: the frame drawn)
    std::string view = "main";  // shot: which view to draw, see viewNames()
    CullerOptions culler;       // passed to every culler the window makes
    bool play = false;          // window: start playing instead of paused
    int exit_after_frames = 0;  // window: close by itself after this many frames (0: never)
    int64_t rgvc_layer = -1;    // rgvc, 2D: traversal shown up to this chess layer (-1: all)
    int rgvc_occluder = -1;     // rgvc, 2D: the picked extended occluder (-1: none)
    // lazy / busy grid, 3D: the object (scene id) whose deciding test the overlay
    // and panel show when nothing is under the mouse (-1: none).
    int lazy_object = -1;
};

// The names `shot --view` accepts ("main": the whole window with its panels, ...).
const char* viewNamesHelp();

// Opens the window on `scene` and runs until it is closed. Returns the process
// exit status (0, or 1 with a message on stderr when no window can be opened).
int runWindow(const Scene& scene, const ViewOptions& options);

// Renders frame options.frame exactly as the window would show it (culling run
// from frame 0 up to it, fixed ImGui state, mouse far away) to a PNG at out_png.
// Returns false and sets `error` when it cannot (no display, bad view name, file).
// Never leaves a partial PNG behind.
bool renderShot(const Scene& scene, const ViewOptions& options, const std::string& out_png,
                std::string& error);

}  // namespace gridcull
