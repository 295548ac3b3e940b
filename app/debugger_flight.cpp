// The Debugger recording a camera path flown in the window and saving it as the
// scene's camera path (culling/io/camera_path_writer.h).
#include <algorithm>
#include <cstdio>

#include <glm/geometric.hpp>

#include "app/debugger.h"
#include "culling/io/camera_path_writer.h"

namespace gridcull {

namespace {

// How far ahead of each key its target lies, of the world's diagonal: any
// distance gives the same direction; a tenth keeps the numbers readable.
constexpr double kLookAhead = 0.1;

}  // namespace

void Debugger::toggleFlightRecording() {
    if (flight_.recording()) {
        flight_.stop();
        return;
    }
    if (session_.scene().dimensions != 3) return;  // 2D has no fly camera
    setViewMode(ViewMode::Fly);
    flight_.start();
    sampleFlight(0.0);  // the first key where the flight starts
}

void Debugger::sampleFlight(double seconds) {
    if (!flight_.recording() || view_mode_ != ViewMode::Fly) return;
    const Scene& scene = session_.scene();
    const ViewMatrices m = view_camera_.matrices(ViewMode::Fly, session_.cullingCamera(), 1.0);
    const double look = kLookAhead * glm::length(scene.grid.world.extent());
    flight_.sample(seconds, scene.dt, m.eye, m.forward, std::max(look, 1e-3));
}

bool Debugger::saveFlight() {
    flight_.stop();
    const std::string file = session_.sceneFile();
    std::string error;
    if (file.empty()) {
        scene_errors_ = {"the built-in scene has no file to save the flight into"};
        return false;
    }
    if (!writeCameraPath(file, flight_.keys(), session_.scene().dt, error)) {
        scene_errors_ = {error};
        return false;
    }
    char note[256];
    std::snprintf(note, sizeof note,
                  "saved a flight of %zu keys (%.1f s) as the camera path of %s (old file: %s~); "
                  "the culling camera now flies it",
                  flight_.keys().size(), flight_.seconds(), file.c_str(), file.c_str());
    flight_.discard();
    const ViewMode mode = view_mode_;
    openSceneFile(file);
    setViewMode(mode);
    note_ = note;
    return true;
}

}  // namespace gridcull
