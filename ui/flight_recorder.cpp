#include "ui/flight_recorder.h"

#include <algorithm>

#include "culling/scene/scene_limits.h"

namespace gridcull {

void FlightRecorder::start() {
    keys_.clear();
    clock_ = 0.0;
    recording_ = true;
}

void FlightRecorder::discard() {
    keys_.clear();
    recording_ = false;
}

void FlightRecorder::sample(double seconds, double period, const glm::dvec3& eye,
                            const glm::dvec3& forward, double look) {
    if (!recording_ || period <= 0.0) return;
    auto keep = [&](double t) {
        CameraKey key;
        key.t = t;
        key.position = eye;
        key.target = eye + forward * look;
        keys_.push_back(key);
        if (keys_.size() >= kMaxPathKeys) recording_ = false;
    };
    if (keys_.empty()) {
        keep(0.0);
        return;
    }
    clock_ += std::max(seconds, 0.0);
    // A slow frame keeps one key per period it spanned, all at the same place.
    while (recording_ && clock_ >= period) {
        clock_ -= period;
        keep(keys_.back().t + period);
    }
}

}  // namespace gridcull
