// What culling a frame changes in the debugger (the cullers, the frame's
// results and object states), and the one function that culls frames: the
// session runs it on the UI thread, a background seek (ui/background_seek.h) on
// a worker over copies, so that both run a frame exactly alike.
#pragma once
#include <atomic>
#include <memory>
#include <vector>

#include "culling/api/culler.h"
#include "culling/scene/camera.h"
#include "culling/scene/scene.h"
#include "ui/culler_checkpoints.h"
#include "ui/frame_snapshot.h"
#include "ui/object_state.h"

namespace gridcull {

struct CullingRun {
    std::unique_ptr<Culler> culler;  // the selected one, debug capture on
    std::unique_ptr<Culler> exact;   // the oracle; null when the culler is the oracle
    int frame = 0;                   // the frame last culled
    Camera culling_camera;           // the camera it was culled from
    FrameResult result;
    FrameResult exact_result;
    std::vector<ObjectState> states;  // by object index
    std::vector<int> false_culled;
    int known_until = -1;  // history slots 0..known_until hold this culler's frames
    int replayed = 0;      // frames the culler culled for the last seek or step

    const FrameResult& exactResult() const { return exact ? exact_result : result; }
};

// What frames are culled against. A frozen culling camera: every frame from
// frozen_from on (when >= 0) is culled from frozen_camera.
struct RunContext {
    const Scene* scene = nullptr;
    CullerCheckpoints* checkpoints = nullptr;  // null: none offered
    FrameHistory* history = nullptr;
    int frozen_from = -1;
    Camera frozen_camera;

    Camera cameraOfFrame(int frame) const;
};

// Culls `frame` with run.culler, offering its state to the checkpoints first;
// with `full` also with the oracle, and records the object states and the
// frame's statistics in the history.
void runFrame(CullingRun& run, const RunContext& context, int frame, bool full);

// Culls frames first..last in order, in full only `last` and the frames whose
// statistics are not known yet (the oracle keeps nothing between frames, so
// the frames between need the selected culler alone). Counts each frame done
// in `done` and stops early (returning false) once `cancel` is set, when given.
bool runFrames(CullingRun& run, const RunContext& context, int first, int last,
               const std::atomic<bool>* cancel = nullptr, std::atomic<int>* done = nullptr);

}  // namespace gridcull
