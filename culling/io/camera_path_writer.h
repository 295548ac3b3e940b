// Writes a flown camera path into a scene file: its camera.path replaced by the
// keys, time.frames set to the frames the path spans at the scene's dt, every
// other key of the file kept in its order. The old file is kept beside it as
// FILE~, the new one is checked by the scene loader before it replaces the old
// one, and written whole or not at all.
#pragma once
#include <string>
#include <vector>

#include "culling/scene/scene.h"

namespace gridcull {

// `keys`: at least one, t increasing from 0; `dt`: the scene's time step.
// False and `error` (naming the file) when the file cannot be read, parsed,
// or written, or the result would not load.
bool writeCameraPath(const std::string& scene_file, const std::vector<CameraKey>& keys, double dt,
                     std::string& error);

}  // namespace gridcull
