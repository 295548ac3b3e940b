// What the debugger knows about one object at one frame, from comparing the
// selected culler's PVS with the exact visible set of the oracle, and the
// colours (from ui/palette.h) that the renderer, the legend and the hover panel
// all use for it and for the camera.
#pragma once
#include <cstdint>

#include "ui/palette.h"

namespace gridcull {

enum class ObjectState : uint8_t {
    Visible,      // in the PVS and seen by the oracle
    Hidden,       // in the PVS but the oracle sees none of it (conservative extra work)
    Culled,       // dropped by the culler and truly invisible
    FalseCulled,  // dropped by the culler although the oracle sees it: a culling bug
    SubSample,    // dropped by the culler; the oracle saw it only between pixel centres, or
                  // could not decide there (culling/oracle/exact_oracle.h, "Sub-sample objects")
};
constexpr int kObjectStateCount = 5;

const char* objectStateName(ObjectState state);  // "visible", "hidden", "culled", "false-culled", "sub-sample"
// One line saying what the state means, for the legend.
const char* objectStateMeaning(ObjectState state);

Rgb objectStateColor(ObjectState state);
// The colour the culling camera's frustum (3D) or view wedge (2D) is drawn in.
Rgb cullingCameraColor();

}  // namespace gridcull
