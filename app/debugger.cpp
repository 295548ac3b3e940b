#include "app/debugger.h"

#include <algorithm>
#include <iostream>

#include "app/hover_pick.h"
#include "culling/scene/ray_pick.h"
#include "culling/io/scene_loader.h"

namespace gridcull {

namespace {

// Frames played per call at most; beyond that playback runs slower than real time.
constexpr int kMaxFramesPerAdvance = 4;

int indexOfName(const std::vector<std::string>& names, const std::string& name) {
    const auto found = std::find(names.begin(), names.end(), name);
    return found == names.end() ? -1 : int(found - names.begin());
}

}  // namespace

bool Debugger::init(const Scene& scene, std::string& error) {
    algo_names_ = cullerNames();
    if (!renderer_.init(error)) return false;
    if (!session_.open(scene, scene.source_path, options_.algo, error)) return false;
    renderer_.setScene(session_.scene());
    view_camera_.frameScene(session_.scene());
    if (options_.lazy_object >= 0)
        lazy_pinned_index_ = session_.scene().indexOf(options_.lazy_object);
    session_.seek(options_.frame);
    if (options_.play) togglePlay();
    return true;
}

void Debugger::updateHover(double x, double y, bool inside, const WindowRect& view) {
    hovered_index_ = -1;
    hovered_distance_ = 0.0;
    voxel_hovered_ = false;
    if (!inside || !view.contains(x, y)) return;
    const Scene& scene = session_.scene();
    const ViewMatrices m = view_camera_.matrices(view_mode_, session_.cullingCamera(),
                                                 double(view.width) / std::max(view.height, 1));
    glm::dvec3 origin, dir;
    viewRay(m, x - view.x, y - view.y, view.width, view.height, origin, dir);
    if (scene.dimensions == 2) {
        const glm::ivec3 voxel = scene.grid.voxelOf(origin);
        voxel_hovered_ = true;
        hovered_voxel_ = {voxel.x, voxel.y};
        hovered_index_ = pickObject2d(scene, session_.t(), origin, session_.states());
        return;
    }
    double distance = 0.0;
    const int id = pickObject(scene, session_.t(), origin, dir, &distance);
    if (id >= 0) {
        hovered_index_ = scene.indexOf(id);
        hovered_distance_ = distance;
    }
}

void Debugger::advancePlayback(double seconds) {
    if (!playing_) return;
    const double dt = session_.scene().dt;
    play_clock_ += seconds;
    int steps = 0;
    while (play_clock_ >= dt && steps < kMaxFramesPerAdvance) {
        play_clock_ -= dt;
        ++steps;
        if (!session_.step()) {
            playing_ = false;
            break;
        }
    }
    if (steps == kMaxFramesPerAdvance) play_clock_ = 0.0;
}

void Debugger::togglePlay() {
    playing_ = !playing_;
    play_clock_ = 0.0;
    // Play at the last frame means play again from the start.
    if (playing_ && session_.frame() + 1 >= session_.scene().frames) session_.seek(0);
}

void Debugger::stepForward() {
    playing_ = false;
    session_.step();
}

void Debugger::stepBack() {
    playing_ = false;
    session_.seek(session_.frame() - 1);
}

void Debugger::toggleFreeze() {
    session_.setCullingCameraFrozen(!session_.cullingCameraFrozen());
}

void Debugger::pickRgvcOccluder() {
    const RgvcSnapshot* rgvc = session_.rgvcSnapshot();
    if (!rgvc || !voxel_hovered_) return;
    rgvc_view_.occluder = rgvcOccluderAt(*rgvc, hovered_voxel_);
}

void Debugger::pickLazyObject() {
    if (session_.lazyGridSnapshot()) lazy_pinned_index_ = hovered_index_;
}

FrameSnapshot Debugger::snapshot() const {
    FrameSnapshot s;
    s.scene = &session_.scene();
    s.frame = session_.frame();
    s.t = session_.t();
    s.playing = playing_;
    s.algo_names = &algo_names_;
    s.algo_index = indexOfName(algo_names_, session_.algo());
    s.result = &session_.result();
    s.exact = &session_.exactResult();
    s.false_culled = &session_.falseCulled();
    s.history = &session_.history();
    s.hover = describeObject(session_.scene(), hovered_index_, session_.t(), session_.states(),
                             hovered_distance_);
    s.draw_ms = last_draw_ms_;
    s.show_timings = show_timings_;
    s.view_mode = view_mode_;
    s.culling_camera_frozen = session_.cullingCameraFrozen();
    s.scene_file = &session_.sceneFile();
    s.scene_errors = &scene_errors_;
    s.rgvc = session_.rgvcSnapshot();
    s.rgvc_view = rgvc_view_;
    if (s.rgvc && voxel_hovered_) s.rgvc_voxel = &rgvc_voxel_;
    s.lazy_grid = session_.lazyGridSnapshot();
    s.lazy_view = lazy_view_;
    s.lazy_object = lazyObject();
    s.lazy_object_pinned = hovered_index_ < 0 && lazy_pinned_index_ >= 0;
    return s;
}

UiActions Debugger::drawUi(const WindowLayout& layout) {
    if (const RgvcSnapshot* rgvc = session_.rgvcSnapshot(); rgvc && voxel_hovered_)
        describeRgvcVoxel(*rgvc, session_.scene(), hovered_voxel_, rgvc_voxel_);
    return drawDebuggerUi(snapshot(), ui_state_, layout);
}

void Debugger::setViewMode(ViewMode mode) {
    if (mode == ViewMode::Fly && view_mode_ != ViewMode::Fly) view_camera_.startFlyingFromOrbit();
    view_mode_ = mode;
}

void Debugger::openSceneFile(const std::string& path) {
    SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.scene) {
        scene_errors_ = loaded.errors;
        if (scene_errors_.empty()) scene_errors_.push_back(path + ": scene rejected");
        return;
    }
    std::string error;
    if (!session_.open(std::move(*loaded.scene), path, session_.algo(), error)) {
        scene_errors_ = {error};
        return;
    }
    scene_errors_.clear();
    playing_ = false;
    hovered_index_ = -1;
    lazy_pinned_index_ = -1;  // an id of the scene it was given for
    renderer_.setScene(session_.scene());
    view_camera_.frameScene(session_.scene());
}

void Debugger::apply(const UiActions& actions) {
    const PlaybackAction& playback = actions.playback;
    if (playback.toggle_play) togglePlay();
    if (playback.step) stepForward();
    if (playback.seek_frame >= 0) {
        playing_ = false;
        session_.seek(playback.seek_frame);
    }
    const AlgorithmAction& algorithm = actions.algorithm;
    if (algorithm.select_algo && *algorithm.select_algo >= 0 &&
        *algorithm.select_algo < int(algo_names_.size())) {
        std::string error;
        if (!session_.selectAlgorithm(algo_names_[size_t(*algorithm.select_algo)], error))
            scene_errors_ = {error};
    }
    if (algorithm.freeze_culling) session_.setCullingCameraFrozen(*algorithm.freeze_culling);
    if (algorithm.view_mode) setViewMode(*algorithm.view_mode);
    if (actions.scene.open) openSceneFile(actions.scene.path);
    if (actions.rgvc.view) rgvc_view_ = *actions.rgvc.view;
    if (actions.lazy_grid.view) lazy_view_ = *actions.lazy_grid.view;
    if (actions.lazy_grid.cell_size) {
        CullerOptions options = session_.cullerOptions();
        options.lazy_cell_size = *actions.lazy_grid.cell_size;
        std::string error;
        if (!session_.setCullerOptions(options, error)) scene_errors_ = {error};
    }
}

bool Debugger::throughCullingCamera() const {
    return session_.scene().dimensions == 3 && view_mode_ == ViewMode::CullingCamera;
}

void Debugger::drawScene(const WindowLayout& layout, int framebuffer_height, double scale) {
    SceneDrawInput input;
    input.scene = &session_.scene();
    input.t = session_.t();
    input.states = &session_.states();
    input.culling_camera = session_.cullingCamera();
    const bool through_camera = throughCullingCamera();
    input.show_culling_camera = !through_camera;
    const WindowRect& v = layout.scene_view;
    input.viewport = {int(v.x * scale), int(v.y * scale), int(v.width * scale),
                      int(v.height * scale)};
    input.framebuffer_height = framebuffer_height;
    input.view = view_camera_.matrices(view_mode_, session_.cullingCamera(),
                                       double(v.width) / std::max(v.height, 1));
    input.hovered_index = hovered_index_;
    input.rgvc = session_.rgvcSnapshot();
    input.rgvc_view = rgvc_view_;
    // The grid is the culling camera's image, so it lies on the objects only when
    // the view looks through that camera.
    input.lazy_grid = through_camera ? session_.lazyGridSnapshot() : nullptr;
    input.lazy_view = lazy_view_;
    input.lazy_object = lazyObject();
    // A picked object is outlined as if it were under the mouse.
    if (session_.lazyGridSnapshot()) input.hovered_index = lazyObject();
    last_draw_ms_ = renderer_.draw(input);
    session_.recordDrawMs(last_draw_ms_);
}

}  // namespace gridcull
