#include "app/debugger_session.h"

#include <algorithm>
#include <cassert>

#include "app/object_states.h"
#include "culling/lazy_grid/lazy_grid_culler.h"
#include "culling/rgvc/rgvc_culler.h"

namespace gridcull {

namespace {

constexpr const char* kOracleName = "exact";

bool makeCullers(const std::string& algo, const CullerOptions& options,
                 std::unique_ptr<Culler>& culler, std::unique_ptr<Culler>& exact,
                 std::string& error) {
    culler = makeCuller(algo, options, error);
    if (!culler) return false;
    // The window draws rgvc's matrices and traversal and the lazy grid's cells and
    // tests; only those cullers pay for their snapshots.
    if (auto* rgvc = dynamic_cast<RgvcCuller*>(culler.get())) rgvc->setSnapshotEnabled(true);
    if (auto* lazy = dynamic_cast<LazyGridCuller*>(culler.get())) lazy->setSnapshotEnabled(true);
    exact.reset();
    if (algo != kOracleName) {
        exact = makeCuller(kOracleName, options, error);
        if (!exact) return false;
    }
    return true;
}

}  // namespace

bool DebuggerSession::open(Scene scene, const std::string& source_file, const std::string& algo,
                           std::string& error) {
    std::unique_ptr<Culler> culler, exact;
    if (!makeCullers(algo, options_, culler, exact, error)) return false;
    scene_ = std::make_unique<Scene>(std::move(scene));
    scene_file_ = source_file;
    ++scene_generation_;
    algo_ = algo;
    culler_ = std::move(culler);
    exact_ = std::move(exact);
    frozen_from_ = -1;
    history_.resize(std::max(scene_->frames, 1));
    restart();
    return true;
}

bool DebuggerSession::selectAlgorithm(const std::string& algo, std::string& error) {
    return replaceCullers(algo, options_, error);
}

bool DebuggerSession::setCullerOptions(const CullerOptions& options, std::string& error) {
    return replaceCullers(algo_, options, error);
}

bool DebuggerSession::replaceCullers(const std::string& algo, const CullerOptions& options,
                                     std::string& error) {
    assert(isOpen());
    std::unique_ptr<Culler> culler, exact;
    if (!makeCullers(algo, options, culler, exact, error)) return false;
    algo_ = algo;
    options_ = options;
    culler_ = std::move(culler);
    exact_ = std::move(exact);
    const int target = frame_;
    restart();
    seek(target);
    return true;
}

void DebuggerSession::restart() {
    culler_->reset(*scene_);
    if (exact_) exact_->reset(*scene_);
    runFrame(0);
}

void DebuggerSession::seek(int frame) {
    assert(isOpen());
    frame = std::clamp(frame, 0, std::max(scene_->frames - 1, 0));
    if (frame < frame_) restart();
    for (int f = frame_ + 1; f <= frame; ++f) runFrame(f);
}

bool DebuggerSession::step() {
    if (frame_ + 1 >= scene_->frames) return false;
    runFrame(frame_ + 1);
    return true;
}

void DebuggerSession::setCullingCameraFrozen(bool frozen) {
    if (frozen == cullingCameraFrozen()) return;
    if (frozen) {
        // The current frame was culled from exactly this camera, so nothing re-runs.
        frozen_camera_ = culling_camera_;
        frozen_from_ = frame_ + 1;
        return;
    }
    frozen_from_ = -1;
    const int target = frame_;
    restart();
    seek(target);
}

const RgvcSnapshot* DebuggerSession::rgvcSnapshot() const {
    if (!scene_ || scene_->dimensions != 2) return nullptr;
    const auto* rgvc = dynamic_cast<const RgvcCuller*>(culler_.get());
    if (!rgvc || !rgvc->snapshot().valid) return nullptr;
    return &rgvc->snapshot();
}

const LazyGridSnapshot* DebuggerSession::lazyGridSnapshot() const {
    if (!scene_ || scene_->dimensions != 3) return nullptr;
    const auto* lazy = dynamic_cast<const LazyGridCuller*>(culler_.get());
    if (!lazy || !lazy->snapshot().valid) return nullptr;
    return &lazy->snapshot();
}

void DebuggerSession::recordDrawMs(double ms) {
    history_.draw_ms[size_t(frame_)] = float(ms);
}

Camera DebuggerSession::cameraOfFrame(int frame) const {
    if (frozen_from_ >= 0 && frame >= frozen_from_) return frozen_camera_;
    return cameraAt(*scene_, scene_->timeOfFrame(frame));
}

void DebuggerSession::runFrame(int frame) {
    frame_ = frame;
    const double t = scene_->timeOfFrame(frame);
    culling_camera_ = cameraOfFrame(frame);
    timedCull(*culler_, *scene_, culling_camera_, t, result_);
    if (exact_) timedCull(*exact_, *scene_, culling_camera_, t, exact_result_);
    const FrameResult& exact = exactResult();
    classifyObjects(*scene_, result_.pvs, exact.pvs, states_, false_culled_);

    const size_t slot = size_t(frame);
    history_.pvs_size[slot] = float(result_.pvs.size());
    history_.exact_visible[slot] = float(exact.pvs.size());
    history_.false_culls[slot] = float(false_culled_.size());
    history_.cull_ms[slot] = float(result_.stats.cull_ms);
    history_.draw_ms[slot] = 0.0f;
}

}  // namespace gridcull
