// Loads and validates a scene file (shared/spec/scene-format.md).
// Bad input never throws out of here and never crashes: every problem found is
// returned as one message "FILE: json.path: what was expected, got what".
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "culling/scene.h"

namespace gridcull {

// Limits checked before anything is allocated or generated, so that a small file
// cannot ask for an unbounded amount of memory or time.
constexpr int64_t kMaxSceneObjects = 1'000'000;  // listed plus generated
// Every coordinate, size, speed and time in a file must be at most this in
// magnitude. Beyond it a scene spans more than about 1e7 of its smallest
// details, which the renderer's float depth and positions cannot resolve, and
// products of such numbers (areas, speed times duration) head for overflow.
constexpr double kMaxSceneCoordinate = 1e7;
constexpr int64_t kMaxSceneFrames = 1'000'000;   // time.frames
constexpr size_t kMaxPolygonPoints = 4096;       // the simplicity check is O(n^2)
constexpr size_t kMaxPathKeys = 100'000;         // camera.path and motion.keys each
// Random motion is precomputed as one velocity per segment of this length
// (seconds) over the scene's duration; when the scene has very many random
// objects or a very long duration, segments get longer so that all of them
// together stay within kMaxRandomSegments (about 48 bytes each).
constexpr double kRandomSegmentSeconds = 0.5;
constexpr int64_t kMaxRandomSegmentsPerObject = 4096;
constexpr int64_t kMaxRandomSegments = 1'000'000;

struct SceneLoadResult {
    std::optional<Scene> scene;       // set when there are no errors
    std::vector<std::string> errors;  // one line each, already prefixed by the file name
};

// Reads `path`; mesh files are resolved relative to the scene file's folder.
SceneLoadResult loadSceneFile(const std::string& path);
// Parses JSON text. `display_name` prefixes messages; `base_dir` resolves meshes.
SceneLoadResult loadSceneText(const std::string& text, const std::string& display_name,
                              const std::string& base_dir);

// The grid resolution used when a file has no grid.resolution: cubic voxels
// (square in 2D) of one world unit, made coarser when the longest axis would get
// more than 256 voxels or the grid more than 2^21 voxels (128^3; 2^20 in 2D),
// and finer when the longest axis would get fewer than 16. Every axis gets at
// least one voxel. The result always passes checkResolution.
glm::ivec3 defaultResolution(int dimensions, const Aabb& world);

// The built-in default scene (a 3D sphere cluster after Batagelo & Wu), the same
// as scenes/default.json.
Scene defaultScene();
// The JSON text of the default scene.
const char* defaultSceneJson();

}  // namespace gridcull
