#include "ui/debugger_session.h"

#include <algorithm>
#include <cassert>

#include "culling/registry/registry.h"

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
    cancelSeek();
    std::unique_ptr<Culler> culler, exact;
    if (!makeCullers(scene, algo, knobs_, culler, exact, error)) return false;
    timeline_.stop();  // it reads the scene about to be replaced
    scene_ = std::make_unique<Scene>(std::move(scene));
    scene_file_ = source_file;
    ++scene_generation_;
    algo_ = algo;
    live_ = CullingRun{};
    live_.culler = std::move(culler);
    live_.exact = std::move(exact);
    checkpoints_.clear();
    frozen_from_ = -1;
    history_.resize(std::max(scene_->frames, 1));
    restart();
    restartTimeline();
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
    cancelSeek();
    std::unique_ptr<Culler> culler, exact;
    if (!makeCullers(*scene_, algo, knobs, culler, exact, error)) return false;
    timeline_.stop();  // it offers checkpoints of the cullers being replaced
    algo_ = algo;
    knobs_ = knobs;
    live_.culler = std::move(culler);
    live_.exact = std::move(exact);
    checkpoints_.clear();
    const int target = live_.frame;
    restart();
    seek(target);
    restartTimeline();
    return true;
}

RunContext DebuggerSession::context() {
    RunContext context;
    context.scene = scene_.get();
    context.checkpoints = &checkpoints_;
    context.history = &history_;
    context.frozen_from = frozen_from_;
    context.frozen_camera = frozen_camera_;
    return context;
}

void DebuggerSession::restart() {
    live_.culler->reset(*scene_);
    if (live_.exact) live_.exact->reset(*scene_);
    live_.known_until = -1;
    live_.replayed = 0;
    runFrame(live_, context(), 0, true);
}

bool DebuggerSession::seekStart(int frame, int& first) const {
    const int from = checkpoints_.latestAtOrBefore(frame);
    // Forwards, go on from the current state unless a checkpoint is nearer.
    if (frame > live_.frame && (from < 0 || live_.frame + 1 >= from)) {
        first = live_.frame + 1;
        return false;
    }
    first = std::max(from, 0);
    return from >= 0;
}

void DebuggerSession::seek(int frame) {
    assert(isOpen());
    cancelSeek();
    frame = std::clamp(frame, 0, std::max(scene_->frames - 1, 0));
    live_.replayed = 0;
    checkpoints_.setFocus(frame);
    if (frame == live_.frame) return;
    int first = 0;
    if (seekStart(frame, first)) {
        live_.culler = checkpoints_.restore(first);
        assert(live_.culler);  // it was copied once, so it copies again
        live_.culler->setDebugCapture(true);
    } else if (first == 0) {
        restart();
        first = 1;
    }
    if (first <= frame) runFrames(live_, context(), first, frame);
}

void DebuggerSession::seekInBackground(int frame) {
    assert(isOpen());
    cancelSeek();
    frame = std::clamp(frame, 0, std::max(scene_->frames - 1, 0));
    int first = 0;
    const bool from_checkpoint = seekStart(frame, first);
    const bool restarts = !from_checkpoint && first == 0;
    if (frame == live_.frame || frame - first + 1 <= kForegroundSeekFrames) return seek(frame);
    checkpoints_.setFocus(frame);
    // The worker's copies: the checkpoint's state, or the current one going
    // forwards, or a fresh culler for a restart (copied before its reset).
    CullingRun run;
    run.culler = from_checkpoint ? checkpoints_.restore(first) : live_.culler->clone();
    run.exact = live_.exact ? live_.exact->clone() : nullptr;
    if (!run.culler || (live_.exact && !run.exact)) return seek(frame);
    run.culler->setDebugCapture(true);
    run.frame = live_.frame;
    run.known_until = live_.known_until;
    if (restarts) {
        run.culler->reset(*scene_);
        if (run.exact) run.exact->reset(*scene_);
        run.known_until = -1;
    }
    seek_job_.start(std::move(run), context(), history_, first, frame);
}

void DebuggerSession::cancelSeek() {
    seek_job_.cancel();
}

bool DebuggerSession::pollSeek() {
    if (!seek_job_.active() || !seek_job_.finished()) return false;
    seek_job_.take(live_, history_);
    return true;
}

bool DebuggerSession::step() {
    cancelSeek();
    if (live_.frame + 1 >= scene_->frames) return false;
    checkpoints_.setFocus(live_.frame + 1);
    live_.replayed = 0;
    runFrames(live_, context(), live_.frame + 1, live_.frame + 1);
    return true;
}

void DebuggerSession::setCullingCameraFrozen(bool frozen) {
    if (frozen == cullingCameraFrozen()) return;
    cancelSeek();
    timeline_.stop();  // it offers checkpoints culled from the camera being changed
    if (frozen) {
        // The current frame was culled from exactly this camera, so nothing re-runs.
        frozen_camera_ = live_.culling_camera;
        frozen_from_ = live_.frame + 1;
        checkpoints_.dropAfter(frozen_from_);  // later ones saw the moving camera
        live_.known_until = std::min(live_.known_until, live_.frame);
        restartTimeline();
        return;
    }
    checkpoints_.dropAfter(frozen_from_);  // later ones saw the frozen camera
    frozen_from_ = -1;
    const int target = live_.frame;
    restart();
    seek(target);
    restartTimeline();
}

void DebuggerSession::setComputeAhead(bool on) {
    compute_ahead_ = on;
    if (on && isOpen()) restartTimeline();
    if (!on) timeline_.stop();
}

void DebuggerSession::restartTimeline() {
    timeline_.stop();
    if (!compute_ahead_) return;
    // The state before frame 0 is the first checkpoint (none: the culler
    // cannot be copied, and the timeline shows the frames run only).
    std::unique_ptr<Culler> culler = checkpoints_.restore(0);
    std::unique_ptr<Culler> exact = live_.exact ? live_.exact->clone() : nullptr;
    if (!culler || (live_.exact && !exact)) return;
    culler->setDebugCapture(false);  // numbers only
    // Its checkpoints are the session's too: once it has passed a frame, a
    // seek there replays at most an interval.
    timeline_.start(*scene_, std::move(culler), std::move(exact), frozen_from_, frozen_camera_,
                    &checkpoints_);
}

void DebuggerSession::recordDrawMs(double ms) {
    history_.draw_ms[size_t(live_.frame)] = float(ms);
}

}  // namespace gridcull
