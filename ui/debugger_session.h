// The culling side of the debugger: one scene, the selected culler and the exact
// oracle run frame by frame from frame 0, the per-object states, the history of
// statistics. It lives beside the panels it feeds but uses no ImGui (and no
// GL), so the window, `shot` and tests share it.
//
// Cullers keep temporal state, so the session only ever feeds them frames in
// order: going forwards runs the frames in between; going backwards restores the
// selected culler's latest checkpoint at or before the target (ui/culler_checkpoints.h)
// and runs on from there, so a step back costs at most a checkpoint interval of
// culls. Frames replayed on the way, whose statistics are known, are culled by
// the selected culler alone: the oracle keeps nothing between frames, so it
// only runs for the frame shown. A culler that cannot be copied (OpenGL) is
// reset and run again from frame 0.
//
// A long seek can run on a worker thread instead (seekInBackground), over copies
// of the cullers, while the session goes on showing the frame it was at; the
// window polls it once per frame, shows its progress and can cancel it. Every
// other call that changes the session cancels a running one first.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "culling/api/culler.h"
#include "culling/api/knobs.h"
#include "culling/scene/camera.h"
#include "culling/scene/scene.h"
#include "ui/background_seek.h"
#include "ui/culler_checkpoints.h"
#include "ui/culling_run.h"
#include "ui/frame_snapshot.h"
#include "ui/object_state.h"
#include "ui/timeline_run.h"

namespace gridcull {

// A seek that culls more frames than this runs in the background when asked to.
constexpr int kForegroundSeekFrames = 8;

class DebuggerSession {
public:
    // `knobs`: the knob values every culler is made with (culling/api/knobs.h).
    explicit DebuggerSession(const KnobValues& knobs) : knobs_(knobs) {}

    // Takes `scene` (must have at least one frame) and starts again at frame 0 with
    // the culler named `algo`. On failure (an unknown algo, or one that does not
    // run on the scene's dimension) returns false, sets `error` and keeps
    // everything as it was.
    bool open(Scene scene, const std::string& source_file, const std::string& algo,
              std::string& error);
    // Switches the culler and re-runs frames 0..frame(). False and `error` for an
    // unknown name or one that does not fit the scene (the current culler stays).
    bool selectAlgorithm(const std::string& algo, std::string& error);
    // Re-creates both cullers with `knobs` (say another cell size) and
    // re-runs frames 0..frame(). False and `error` when a culler cannot be made
    // (the current ones and knobs stay).
    bool setKnobs(const KnobValues& knobs, std::string& error);
    const KnobValues& knobs() const { return knobs_; }

    // Shows `frame`, clamped to the scene's frames.
    void seek(int frame);
    // As seek(), but on a worker thread when it would cull more than
    // kForegroundSeekFrames frames and the culler can be copied. Until pollSeek()
    // adopts it, every accessor still shows the frame the session was at.
    void seekInBackground(int frame);
    // A background seek is running (or done and not yet adopted).
    bool seeking() const { return seek_job_.active(); }
    // Its target frame and the share of its frames culled (0 to 1).
    int seekTarget() const { return seek_job_.target(); }
    double seekProgress() const { return seek_job_.progress(); }
    // Stops a background seek; the session stays where it was.
    void cancelSeek();

    // On: whenever the cullers, knobs or culling camera change, the whole run
    // is computed again ahead on a worker (ui/timeline_run.h) for the timeline
    // (the window; off in shots and tests, whose timeline shows the frames run).
    void setComputeAhead(bool on);
    // Copies the frames computed ahead so far into `history`; returns how many.
    int computedAhead(FrameHistory& history) const { return timeline_.copyTo(history); }
    // Adopts a finished background seek; true when it did (the frame changed).
    bool pollSeek();
    // One frame forward; false (and nothing done) at the last frame.
    bool step();
    // Frozen: the cullers see the culling camera where it is now at every later
    // frame, while objects keep moving. Releasing re-runs from frame 0 as if the
    // camera had never been frozen.
    void setCullingCameraFrozen(bool frozen);
    // Stores the draw time of the current frame in the history.
    void recordDrawMs(double ms);

    bool isOpen() const { return scene_ != nullptr; }
    const Scene& scene() const { return *scene_; }
    const std::string& sceneFile() const { return scene_file_; }
    // Changes whenever open() installs a new scene (renderers re-upload on change).
    int sceneGeneration() const { return scene_generation_; }
    int frame() const { return live_.frame; }
    double t() const { return scene_->timeOfFrame(live_.frame); }
    const std::string& algo() const { return algo_; }
    bool cullingCameraFrozen() const { return frozen_from_ >= 0; }
    // The frame whose camera is frozen (frozen at it, culled from it after), or -1.
    int frozenAt() const { return frozen_from_ - (frozen_from_ >= 0 ? 1 : 0); }
    // The camera the cullers used for the current frame.
    const Camera& cullingCamera() const { return live_.culling_camera; }
    const FrameResult& result() const { return live_.result; }
    const FrameResult& exactResult() const { return live_.exactResult(); }
    const std::vector<ObjectState>& states() const { return live_.states; }  // by object index
    const std::vector<int>& falseCulled() const { return live_.false_culled; }
    const FrameHistory& history() const { return history_; }
    // Frames the selected culler culled for the last seek() or step() (1 for a
    // step forward; a step back: up to the checkpoint interval), background
    // seeks included.
    int lastReplayedFrames() const { return live_.replayed; }
    const CullerCheckpoints& checkpoints() const { return checkpoints_; }
    // The selected culler's internal state at the current frame (its debug
    // capture is on), or null for a culler with nothing to show. Valid until the
    // next frame is culled.
    const DebugSnapshot* debugSnapshot() const {
        return live_.culler ? live_.culler->debugSnapshot() : nullptr;
    }

private:
    // Makes the cullers for algo and options and re-runs up to the current frame;
    // on failure keeps the current ones.
    bool replaceCullers(const std::string& algo, const KnobValues& knobs, std::string& error);
    void restart();  // reset both cullers, run frame 0
    RunContext context();
    // Where a seek to `frame` starts: the frame to cull first and, when that is
    // a checkpoint's, true (false: go on from the current frame, or restart when
    // first is 0).
    bool seekStart(int frame, int& first) const;
    // Starts computing the run ahead (when asked to and the culler can be copied).
    void restartTimeline();

    KnobValues knobs_;
    std::unique_ptr<Scene> scene_;
    std::string scene_file_;
    int scene_generation_ = 0;
    std::string algo_;
    CullingRun live_;       // what the window shows
    int frozen_from_ = -1;  // first frame culled from frozen_camera_, or -1
    Camera frozen_camera_;
    FrameHistory history_;
    CullerCheckpoints checkpoints_;
    bool compute_ahead_ = false;
    // Declared last: stopped before what they use goes.
    BackgroundSeek seek_job_;
    TimelineRun timeline_;
};

}  // namespace gridcull
