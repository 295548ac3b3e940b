#include "ui/object_state.h"

namespace gridcull {

const char* objectStateName(ObjectState state) {
    switch (state) {
    case ObjectState::Visible: return "visible";
    case ObjectState::Hidden: return "hidden";
    case ObjectState::Culled: return "culled";
    case ObjectState::FalseCulled: return "false-culled";
    }
    return "?";
}

const char* objectStateMeaning(ObjectState state) {
    switch (state) {
    case ObjectState::Visible: return "in the PVS, seen by exact";
    case ObjectState::Hidden: return "in the PVS, hidden (extra work)";
    case ObjectState::Culled: return "culled, truly invisible";
    case ObjectState::FalseCulled: return "culled but exact sees it: BUG";
    }
    return "?";
}

Rgb objectStateColor(ObjectState state) {
    // Okabe-Ito blue, sky blue and vermillion stay apart for every common colour
    // vision deficiency; culled objects are a dim neutral grey so they recede.
    switch (state) {
    case ObjectState::Visible: return {0.00f, 0.45f, 0.70f};
    case ObjectState::Hidden: return {0.34f, 0.71f, 0.91f};
    case ObjectState::Culled: return {0.36f, 0.36f, 0.38f};
    case ObjectState::FalseCulled: return {0.84f, 0.37f, 0.00f};
    }
    return {1.0f, 1.0f, 1.0f};
}

Rgb cullingCameraColor() { return {0.94f, 0.89f, 0.26f}; }  // Okabe-Ito yellow

}  // namespace gridcull
