// The limits every scene stays within (docs/LIMITS.md). The loader checks them
// before anything is allocated or generated, so that a small file cannot ask for
// an unbounded amount of memory or time; generators size what they make by them.
#pragma once
#include <cstddef>
#include <cstdint>

namespace gridcull {

constexpr int64_t kMaxSceneObjects = 1'000'000;  // listed plus generated
// Every coordinate, size, speed and time in a file must be at most this in
// magnitude. Beyond it a scene spans more than about 1e7 of its smallest
// details, which the renderer's float depth and positions cannot resolve, and
// products of such numbers (areas, speed times duration) head for overflow.
constexpr double kMaxSceneCoordinate = 1e7;
constexpr int64_t kMaxSceneFrames = 1'000'000;  // time.frames
constexpr size_t kMaxPolygonPoints = 4096;      // the simplicity check is O(n^2)
constexpr size_t kMaxPathKeys = 100'000;        // camera.path and motion.keys each
// Random motion is precomputed as one velocity per segment of this length
// (seconds) over the scene's duration; when the scene has very many random
// objects or a very long duration, segments get longer so that all of them
// together stay within kMaxRandomSegments (about 48 bytes each).
constexpr double kRandomSegmentSeconds = 0.5;
constexpr int64_t kMaxRandomSegmentsPerObject = 4096;
constexpr int64_t kMaxRandomSegments = 1'000'000;

}  // namespace gridcull
