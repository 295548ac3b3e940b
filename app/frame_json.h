// One frame of `gridcull cull` output as a JSON line (README.md, "Command line"):
// {"frame":F,"t":T,"algo":A,"camera":{"position":[..],"target":[..]},"pvs":[..],"stats":{..}}
// Vectors have the scene's dimension count. Numbers use the shortest text that
// reads back to the same double, so a line can be compared exactly.
#pragma once
#include <string>

#include "culling/api/culler.h"
#include "culling/scene/camera.h"

namespace gridcull {

// Appends the line (with its '\n') to `line`; reuses the string's capacity.
void appendFrameJson(std::string& line, int frame, double t, const char* algo, const Camera& camera,
                     const FrameResult& result);

}  // namespace gridcull
