// The hzb family's debug snapshot kind and the names the window and tests give
// its states and outcomes (culling/hzb_tbv/hzb_tbv_snapshot.h).
#include "culling/hzb_tbv/hzb_tbv_snapshot.h"

namespace gridcull {

const DebugSnapshotKind HzbTbvSnapshot::kKind{"hzb"};

const char* hzbObjectStatusName(HzbObjectStatus status) {
    switch (status) {
        case HzbObjectStatus::Visible:
            return "visible";
        case HzbObjectStatus::Hidden:
            return "under a TBV";
        case HzbObjectStatus::Expired:
            return "expired";
        case HzbObjectStatus::Revealed:
            return "revealed";
        case HzbObjectStatus::Violated:
            return "violated";
        case HzbObjectStatus::Culled:
            return "culled";
    }
    return "?";
}

const char* hzbNodeOutcomeName(HzbNodeOutcome outcome) {
    switch (outcome) {
        case HzbNodeOutcome::FrustumCulled:
            return "frustum-culled";
        case HzbNodeOutcome::ZCulled:
            return "Z-culled";
        case HzbNodeOutcome::Entered:
            return "entered";
    }
    return "?";
}

}  // namespace gridcull
