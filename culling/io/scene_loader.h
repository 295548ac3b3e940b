// Loads and validates a scene file (docs/scene-format.md).
// Bad input never throws out of here and never crashes: every problem found is
// returned as one message "FILE: json.path: what was expected, got what".
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "culling/scene/scene.h"
#include "culling/scene/scene_limits.h"

namespace gridcull {

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
