#include "ui/debugger_session.h"

#include <algorithm>
#include <cassert>

#include "culling/registry/registry.h"
#include "ui/object_states.h"

namespace gridcull {

namespace {

bool makeCullers(const Scene& scene, const std::string& algo, const KnobValues& knobs,
                 std::unique_ptr<Culler>& culler, std::unique_ptr<Culler>& exact,
                 std::string& error) {
    if (!algorithmFits(algo, scene, error)) return false;
    culler = makeCuller(algo, knobs, error);
    if (!culler) return false;
    // The window draws the selected culler's internal state; only it pays for
    // capturing it, the oracle does not.
    culler->setDebugCapture(true);
    exact.reset();
    if (algo != referenceAlgorithm()) {
        exact = makeCuller(referenceAlgorithm(), knobs, error);
        if (!exact) return false;
    }
    return true;
}

}  // namespace

bool DebuggerSession::open(Scene scene, const std::string& source_file, const std::string& algo,
                           std::string& error) {
    std::unique_ptr<Culler> culler, exact;
    if (!makeCullers(scene, algo, knobs_, culler, exact, error)) return false;
    scene_ = std::make_unique<Scene>(std::move(scene));
    scene_file_ = source_file;
    ++scene_generation_;
    algo_ = algo;
    culler_ = std::move(culler);
    exact_ = std::move(exact);
    checkpoints_.clear();
    frozen_from_ = -1;
    history_.resize(std::max(scene_->frames, 1));
    restart();
    return true;
}

bool DebuggerSession::selectAlgorithm(const std::string& algo, std::string& error) {
    return replaceCullers(algo, knobs_, error);
}

bool DebuggerSession::setKnobs(const KnobValues& knobs, std::string& error) {
    return replaceCullers(algo_, knobs, error);
}

bool DebuggerSession::replaceCullers(const std::string& algo, const KnobValues& knobs,
                                     std::string& error) {
    assert(isOpen());
    std::unique_ptr<Culler> culler, exact;
    if (!makeCullers(*scene_, algo, knobs, culler, exact, error)) return false;
    algo_ = algo;
    knobs_ = knobs;
    culler_ = std::move(culler);
    exact_ = std::move(exact);
    checkpoints_.clear();
    const int target = frame_;
    restart();
    seek(target);
    return true;
}

void DebuggerSession::restart() {
    culler_->reset(*scene_);
    if (exact_) exact_->reset(*scene_);
    known_until_ = -1;
    replayed_frames_ = 0;
    runFrame(0);
}

void DebuggerSession::seek(int frame) {
    assert(isOpen());
    frame = std::clamp(frame, 0, std::max(scene_->frames - 1, 0));
    replayed_frames_ = 0;
    if (frame == frame_) return;
    const CullerCheckpoint* from = checkpoints_.latestAtOrBefore(frame);
    // Forwards, go on from the current state unless a checkpoint is nearer.
    if (frame > frame_ && (!from || frame_ + 1 >= from->frame)) {
        runFrames(frame_ + 1, frame);
        return;
    }
    if (!from) {
        restart();
        if (frame > 0) runFrames(1, frame);
        return;
    }
    culler_ = from->culler->clone();
    assert(culler_);  // it was copied once, so it copies again
    culler_->setDebugCapture(true);
    runFrames(from->frame, frame);
}

bool DebuggerSession::step() {
    if (frame_ + 1 >= scene_->frames) return false;
    replayed_frames_ = 0;
    runFrames(frame_ + 1, frame_ + 1);
    return true;
}

void DebuggerSession::runFrames(int first, int last) {
    for (int f = first; f <= last; ++f) runFrame(f, f == last || f > known_until_);
}

void DebuggerSession::setCullingCameraFrozen(bool frozen) {
    if (frozen == cullingCameraFrozen()) return;
    if (frozen) {
        // The current frame was culled from exactly this camera, so nothing re-runs.
        frozen_camera_ = culling_camera_;
        frozen_from_ = frame_ + 1;
        checkpoints_.dropAfter(frozen_from_);  // later ones saw the moving camera
        known_until_ = std::min(known_until_, frame_);
        return;
    }
    checkpoints_.dropAfter(frozen_from_);  // later ones saw the frozen camera
    frozen_from_ = -1;
    const int target = frame_;
    restart();
    seek(target);
}

void DebuggerSession::recordDrawMs(double ms) {
    history_.draw_ms[size_t(frame_)] = float(ms);
}

Camera DebuggerSession::cameraOfFrame(int frame) const {
    if (frozen_from_ >= 0 && frame >= frozen_from_) return frozen_camera_;
    return cameraAt(*scene_, scene_->timeOfFrame(frame));
}

void DebuggerSession::runFrame(int frame, bool full) {
    checkpoints_.offer(frame, *culler_);
    frame_ = frame;
    ++replayed_frames_;
    const double t = scene_->timeOfFrame(frame);
    culling_camera_ = cameraOfFrame(frame);
    timedCull(*culler_, *scene_, culling_camera_, t, result_);
    if (!full) return;
    known_until_ = std::max(known_until_, frame);
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
