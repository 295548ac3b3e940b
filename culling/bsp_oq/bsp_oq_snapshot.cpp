// The bsp family's debug snapshot kind and the names the window and tests give
// its node states and modes (culling/bsp_oq/bsp_oq_snapshot.h).
#include "culling/bsp_oq/bsp_oq_snapshot.h"

namespace gridcull {

const DebugSnapshotKind BspOqSnapshot::kKind{"bsp"};

const char* bspNodeStateName(BspNodeState state) {
    switch (state) {
        case BspNodeState::NotReached:
            return "not reached";
        case BspNodeState::FrustumCulled:
            return "outside the frustum";
        case BspNodeState::Empty:
            return "empty";
        case BspNodeState::ViewerInside:
            return "viewer inside";
        case BspNodeState::InFrustum:
            return "in the frustum";
        case BspNodeState::AssumedVisible:
            return "assumed visible";
        case BspNodeState::QueriedVisible:
            return "queried visible";
        case BspNodeState::QueriedHidden:
            return "queried hidden";
    }
    return "?";
}

const char* bspOqModeName(BspOqMode mode) {
    switch (mode) {
        case BspOqMode::Full:
            return "Full";
        case BspOqMode::Simple:
            return "Simple OC";
        case BspOqMode::Vfc:
            return "VFC only";
    }
    return "?";
}

}  // namespace gridcull
