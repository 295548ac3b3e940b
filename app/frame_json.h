// One frame of `gridcull cull` output as a JSON line (README.md, "Command line"):
// {"frame":F,"t":T,"algo":A,"camera":{"position":[..],"target":[..]},"pvs":[..],"stats":{..}}
// The 3D oracle adds "sub_sample_visible":[..] and "sub_sample_undecided":[..]
// after "pvs": the ids its finer rays saw between pixel centres, and those they
// could not decide (exact_oracle.h); its counters count them.
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
