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
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "culling/api/culler.h"
#include "culling/api/knobs.h"
#include "culling/scene/camera.h"
#include "culling/scene/scene.h"
#include "ui/culler_checkpoints.h"
#include "ui/frame_snapshot.h"
#include "ui/object_state.h"

namespace gridcull {

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
    int frame() const { return frame_; }
    double t() const { return scene_->timeOfFrame(frame_); }
    const std::string& algo() const { return algo_; }
    bool cullingCameraFrozen() const { return frozen_from_ >= 0; }
    // The camera the cullers used for the current frame.
    const Camera& cullingCamera() const { return culling_camera_; }
    const FrameResult& result() const { return result_; }
    const FrameResult& exactResult() const { return exact_ ? exact_result_ : result_; }
    const std::vector<ObjectState>& states() const { return states_; }  // by object index
    const std::vector<int>& falseCulled() const { return false_culled_; }
    const FrameHistory& history() const { return history_; }
    // Frames the selected culler culled for the last seek() or step() (1 for a
    // step forward; a step back: up to the checkpoint interval).
    int lastReplayedFrames() const { return replayed_frames_; }
    const CullerCheckpoints& checkpoints() const { return checkpoints_; }
    // The selected culler's internal state at the current frame (its debug
    // capture is on), or null for a culler with nothing to show. Valid until the
    // next frame is culled.
    const DebugSnapshot* debugSnapshot() const {
        return culler_ ? culler_->debugSnapshot() : nullptr;
    }

private:
    // Makes the cullers for algo and options and re-runs up to the current frame;
    // on failure keeps the current ones.
    bool replaceCullers(const std::string& algo, const KnobValues& knobs, std::string& error);
    void restart();  // reset both cullers, run frame 0
    // Culls `frame` with the selected culler; with `full` also with the oracle,
    // and records the frame's states and statistics.
    void runFrame(int frame, bool full = true);
    // Runs frames first..last in order; only `last` (and frames whose
    // statistics are not known yet) in full.
    void runFrames(int first, int last);
    Camera cameraOfFrame(int frame) const;

    KnobValues knobs_;
    std::unique_ptr<Scene> scene_;
    std::string scene_file_;
    int scene_generation_ = 0;
    std::string algo_;
    std::unique_ptr<Culler> culler_;
    std::unique_ptr<Culler> exact_;  // null when the selected culler is the oracle
    int frame_ = 0;
    int frozen_from_ = -1;  // first frame culled from frozen_camera_, or -1
    Camera frozen_camera_;
    Camera culling_camera_;
    FrameResult result_;
    FrameResult exact_result_;
    std::vector<ObjectState> states_;
    std::vector<int> false_culled_;
    FrameHistory history_;
    int known_until_ = -1;  // history slots 0..known_until_ hold this culler's frames
    CullerCheckpoints checkpoints_;
    int replayed_frames_ = 0;
};

}  // namespace gridcull
