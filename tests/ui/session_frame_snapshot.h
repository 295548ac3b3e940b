// The FrameSnapshot fields every panel test fills from a DebuggerSession: the
// scene, frame, time, results, history and scene-file fields, borrowing from the
// session and the given lists, which must outlive the snapshot's use.
#pragma once
#include <string>
#include <vector>

#include "ui/debugger_session.h"
#include "ui/frame_snapshot.h"

namespace gridcull::test {

inline FrameSnapshot snapshotOfSession(const DebuggerSession& session,
                                       const std::vector<std::string>& algo_names,
                                       const std::string& scene_file,
                                       const std::vector<std::string>& scene_errors) {
    FrameSnapshot snapshot;
    snapshot.scene = &session.scene();
    snapshot.frame = session.frame();
    snapshot.t = session.t();
    snapshot.algo_names = &algo_names;
    snapshot.result = &session.result();
    snapshot.exact = &session.exactResult();
    snapshot.false_culled = &session.falseCulled();
    snapshot.history = &session.history();
    snapshot.scene_file = &scene_file;
    snapshot.scene_errors = &scene_errors;
    return snapshot;
}

}  // namespace gridcull::test
