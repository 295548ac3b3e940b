// The properties the scene-loader fuzzer checks on every input, shared with
// the regression test that replays the inputs it found
// (tests/culling/io/scene_fuzz_regression_test.cpp). Each returns "" when the
// property holds, else what was violated.
//  - checkLoadResult: a scene or at least one error message, never both and
//    never neither; every message starts with the display name; a loaded scene
//    is what the loader promises (dimensions, frames, dt, near < far, a camera
//    path, a resolution within the voxel budget, unique ids that indexOf finds,
//    finite object bounds).
//  - checkCulling: every algorithm the registry offers for the scene's dimension runs
//    the first, second and last frame (the oracle at a coarse 32 pixels / 256
//    rays); every PVS is sorted and unique and contains the oracle's. Only for
//    small scenes (fuzzScenesSmallEnoughToCull): culling costs grow with
//    objects, mesh triangles and grid voxels, and the fuzzer's point is the
//    loader.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include "culling/api/culler.h"
#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"

namespace gridcull::fuzz {

constexpr size_t kMaxCulledObjects = 256;
constexpr size_t kMaxCulledTriangles = 20000;  // 5 bunnies; 80 took a second under ASan
constexpr int64_t kMaxCulledVoxels = int64_t(1) << 16;

inline bool finiteBox(const Aabb& box) {
    for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(box.min[axis]) || !std::isfinite(box.max[axis])) return false;
        if (box.min[axis] > box.max[axis]) return false;
    }
    return true;
}

inline std::string checkScene(const Scene& scene) {
    if (scene.dimensions != 2 && scene.dimensions != 3) return "dimensions not 2 or 3";
    if (scene.frames < 1 || scene.frames > kMaxSceneFrames) return "frames out of range";
    if (!(scene.dt > 0.0) || !std::isfinite(scene.dt)) return "dt not finite and > 0";
    if (scene.camera.path.empty()) return "empty camera path";
    if (!(scene.camera.near > 0.0) || !(scene.camera.near < scene.camera.far)) return "near/far";
    if (!checkResolution(scene.dimensions, scene.grid.resolution).empty())
        return "resolution beyond the budget";
    if (!finiteBox(scene.grid.world)) return "world box not finite";
    if (int64_t(scene.objects.size()) > kMaxSceneObjects) return "too many objects";
    std::unordered_set<int> ids;
    for (const SceneObject& o : scene.objects) {
        if (o.id < 0 || !ids.insert(o.id).second) return "ids not unique and >= 0";
        const int index = scene.indexOf(o.id);
        if (index < 0 || scene.objects[size_t(index)].id != o.id) return "indexOf";
        if (!finiteBox(o.bounds)) return "object bounds not finite";
    }
    return {};
}

inline std::string checkLoadResult(const SceneLoadResult& result, const std::string& display_name) {
    if (result.scene.has_value() == !result.errors.empty())
        return "not exactly one of scene, errors";
    for (const std::string& message : result.errors)
        if (message.compare(0, display_name.size(), display_name) != 0)
            return "message without the file name: " + message;
    return result.scene ? checkScene(*result.scene) : std::string();
}

inline bool smallEnoughToCull(const Scene& scene) {
    size_t triangles = 0;
    for (const SceneObject& o : scene.objects)
        if (o.mesh) triangles += o.mesh->indices.size() / 3;
    return scene.objects.size() <= kMaxCulledObjects && triangles <= kMaxCulledTriangles &&
           scene.grid.voxelCount() <= kMaxCulledVoxels;
}

inline std::string checkCulling(const Scene& scene) {
    KnobValues options;
    options.set("oracle-res", 32);
    options.set("oracle-rays", 256);
    std::string error;
    std::unique_ptr<Culler> oracle = makeCuller("exact", options, error);
    if (!oracle) return "cannot make the oracle: " + error;
    std::vector<int> frames = {0, 1, scene.frames - 1};
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    frames.erase(
        std::remove_if(frames.begin(), frames.end(), [&](int f) { return f >= scene.frames; }),
        frames.end());
    std::vector<std::vector<int>> reference;
    oracle->reset(scene);
    FrameResult out;
    for (const int frame : frames) {
        const double t = scene.timeOfFrame(frame);
        oracle->cull(scene, cameraAt(scene, t), t, out);
        reference.push_back(out.pvs);
    }
    for (const std::string& name : algorithmNames(scene.dimensions)) {
        std::unique_ptr<Culler> culler = makeCuller(name, options, error);
        if (!culler) return "cannot make " + name + ": " + error;
        culler->reset(scene);
        for (size_t i = 0; i < frames.size(); ++i) {
            const double t = scene.timeOfFrame(frames[i]);
            culler->cull(scene, cameraAt(scene, t), t, out);
            if (std::adjacent_find(out.pvs.begin(), out.pvs.end(),
                                   [](int a, int b) { return a >= b; }) != out.pvs.end())
                return name + ": PVS not sorted and unique at frame " + std::to_string(frames[i]);
            if (!std::includes(out.pvs.begin(), out.pvs.end(), reference[i].begin(),
                               reference[i].end()))
                return name + ": false cull (misses an id the oracle sees) at frame " +
                       std::to_string(frames[i]);
        }
    }
    return {};
}

}  // namespace gridcull::fuzz
