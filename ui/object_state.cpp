#include "ui/object_state.h"

namespace gridcull {

const char* objectStateName(ObjectState state) {
    switch (state) {
        case ObjectState::Visible:
            return "visible";
        case ObjectState::Hidden:
            return "hidden";
        case ObjectState::Culled:
            return "culled";
        case ObjectState::FalseCulled:
            return "false-culled";
        case ObjectState::SubSample:
            return "sub-sample";
    }
    return "?";
}

const char* objectStateMeaning(ObjectState state) {
    switch (state) {
        case ObjectState::Visible:
            return "in the PVS, seen by exact";
        case ObjectState::Hidden:
            return "in the PVS, hidden (extra work)";
        case ObjectState::Culled:
            return "culled, truly invisible";
        case ObjectState::FalseCulled:
            return "culled but exact sees it: BUG";
        case ObjectState::SubSample:
            return "culled; shows only between pixel centres, or undecided there";
    }
    return "?";
}

Rgb objectStateColor(ObjectState state) {
    // Okabe-Ito blue, sky blue and vermillion stay apart for every common colour
    // vision deficiency; culled objects are a dim neutral grey so they recede.
    switch (state) {
        case ObjectState::Visible:
            return swatchColor(Swatch::Blue);
        case ObjectState::Hidden:
            return swatchColor(Swatch::SkyBlue);
        case ObjectState::Culled:
            return swatchColor(Swatch::DimGrey);
        case ObjectState::FalseCulled:
            return swatchColor(Swatch::Vermillion);
        case ObjectState::SubSample:
            return swatchColor(Swatch::Orange);
    }
    return swatchColor(Swatch::White);
}

Rgb cullingCameraColor() {
    return swatchColor(Swatch::Yellow);
}

}  // namespace gridcull
