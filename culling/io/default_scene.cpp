// The built-in default scene: scenes/default.json, embedded at build time
// (culling/CMakeLists.txt writes it into default_scene_json.h), so the
// executable needs no files to start and the file and the built-in scene
// cannot drift apart.
#include <cassert>

#include "culling/io/scene_loader.h"
#include "default_scene_json.h"

namespace gridcull {

const char* defaultSceneJson() {
    return kDefaultSceneJson;
}

Scene defaultScene() {
    // Loaded once: the file is fixed at build time, so every load gives the same scene.
    static const Scene scene = [] {
        SceneLoadResult loaded = loadSceneText(kDefaultSceneJson, "default.json", "");
        assert(loaded.scene && "scenes/default.json must be a valid scene");
        return loaded.scene ? std::move(*loaded.scene) : Scene{};
    }();
    return scene;
}

}  // namespace gridcull
