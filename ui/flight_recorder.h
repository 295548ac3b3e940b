// A camera path flown in the window: while recording, the observer's fly
// camera is kept as a camera key every scene time step (the first at once),
// so that saved into the scene file (culling/io/camera_path_writer.h) the
// culling camera replays the flight frame for frame. Pure state: the window
// feeds it the observer's eye and direction.
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "culling/scene/scene.h"

namespace gridcull {

class FlightRecorder {
public:
    // Starts a new flight (the keys of the last one are dropped).
    void start();
    // Stops; the keys stay until discard() or start().
    void stop() { recording_ = false; }
    void discard();
    bool recording() const { return recording_; }
    const std::vector<CameraKey>& keys() const { return keys_; }
    // Seconds flown since start() (the last key's t, at most).
    double seconds() const { return keys_.empty() ? 0.0 : keys_.back().t; }

    // `seconds` of wall time went by with the observer at `eye` looking along
    // unit `forward`: keys every `period` seconds, each target `look`
    // ahead of its eye. Stops by itself at kMaxPathKeys keys.
    void sample(double seconds, double period, const glm::dvec3& eye, const glm::dvec3& forward,
                double look);

private:
    bool recording_ = false;
    double clock_ = 0.0;  // seconds since the last key
    std::vector<CameraKey> keys_;
};

}  // namespace gridcull
