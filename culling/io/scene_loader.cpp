// The scene file's top level: format, dimensions, world, grid, time, seed and
// camera, then objects and generators (scene_loader_objects.cpp,
// scene_generators_read.cpp), ids, and random walks.
#include "culling/io/scene_loader.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>

#include <glm/geometric.hpp>

#include "culling/io/scene_loader_internal.h"
#include "culling/scene/random_walk.h"

namespace gridcull {

glm::ivec3 defaultResolution(int dimensions, const Aabb& world) {
    const int axes = dimensions == 2 ? 2 : 3;
    const glm::dvec3 extent = world.extent();
    double longest = 0.0;
    for (int axis = 0; axis < axes; ++axis) longest = std::max(longest, extent[axis]);
    constexpr double kMinLongestAxis = 16.0, kMaxLongestAxis = 256.0;
    const int64_t max_voxels = dimensions == 2 ? (int64_t(1) << 20) : (int64_t(1) << 21);
    double voxel = 1.0;
    if (longest > 0.0 && longest / voxel < kMinLongestAxis) voxel = longest / kMinLongestAxis;
    if (longest / voxel > kMaxLongestAxis) voxel = longest / kMaxLongestAxis;
    glm::ivec3 resolution{1, 1, 1};
    for (;;) {
        int64_t count = 1;
        for (int axis = 0; axis < axes; ++axis) {
            const double cells = voxel > 0.0 ? std::ceil(extent[axis] / voxel - 1e-9) : 1.0;
            resolution[axis] = int(std::clamp(cells, 1.0, kMaxLongestAxis));
            count *= resolution[axis];
        }
        if (count <= max_voxels) break;
        voxel *= 1.05;  // a few steps at most: the longest axis is already <= 256
    }
    return resolution;
}

namespace {

bool readWorld(JsonObjectReader& root, SceneLoadContext& c) {
    if (!root.require("world", "an object { \"min\": [...], \"max\": [...] }")) return false;
    JsonObjectReader world(*root.find("world"), "world", c.errors);
    if (!world.ok()) return false;
    world.checkKeys({"min", "max"});
    Aabb box;
    const bool has_min = world.vector("min", true, c.dimensions, box.min);
    const bool has_max = world.vector("max", true, c.dimensions, box.max);
    if (!has_min || !has_max) return false;
    bool good = true;
    for (int axis = 0; axis < c.dimensions; ++axis) {
        if (box.max[axis] > box.min[axis]) continue;
        c.errors.add(indexPath("world.max", size_t(axis)),
                     "must be greater than world.min[" + std::to_string(axis) + "] = " +
                         formatNumber(box.min[axis]) + ", got " + formatNumber(box.max[axis]));
        good = false;
    }
    if (good) c.scene.grid.world = box;
    return good;
}

void readGrid(JsonObjectReader& root, SceneLoadContext& c, bool world_ok) {
    c.scene.grid.dimensions = c.dimensions;
    const Json* grid_value = root.find("grid");
    if (grid_value) {
        JsonObjectReader grid(*grid_value, "grid", c.errors);
        if (!grid.ok()) return;
        grid.checkKeys({"resolution"});
        if (grid.has("resolution")) {
            int64_t r[3] = {1, 1, 1};
            if (!grid.integers("resolution", true, c.dimensions, 1, INT_MAX, "integers >= 1", r))
                return;
            const glm::ivec3 resolution{int(r[0]), int(r[1]), c.dimensions == 2 ? 1 : int(r[2])};
            const std::string problem = checkResolution(c.dimensions, resolution);
            if (!problem.empty()) {
                c.errors.add("grid.resolution", "must fit in memory: " + problem + ", got " +
                                                    describe(*grid.find("resolution")));
                return;
            }
            c.scene.grid.resolution = resolution;
            return;
        }
    }
    if (world_ok) c.scene.grid.resolution = defaultResolution(c.dimensions, c.scene.grid.world);
}

void readTime(JsonObjectReader& root, SceneLoadContext& c) {
    const Json* time_value = root.find("time");
    if (!time_value) return;
    JsonObjectReader time(*time_value, "time", c.errors);
    if (!time.ok()) return;
    time.checkKeys({"frames", "dt"});
    int64_t frames = c.scene.frames;
    if (time.integer("frames", false, 1, kMaxSceneFrames,
                     "an integer in [1, " + std::to_string(kMaxSceneFrames) + "]", frames))
        c.scene.frames = int(frames);
    NumberRule positive{"a finite number > 0", 0.0, true};
    time.number("dt", false, positive, c.scene.dt);
}

bool readCameraKey(const Json& value, const std::string& path, SceneLoadContext& c,
                   CameraKey& key) {
    JsonObjectReader k(value, path, c.errors);
    if (!k.ok()) return false;
    if (c.dimensions == 3) {
        k.checkKeys({"t", "position", "target", "up"});
    } else {
        k.checkKeys({"t", "position", "target"}, "in a 2D scene");
    }
    bool good = k.number("t", true, NumberRule{}, key.t);
    good = k.vector("position", true, c.dimensions, key.position) && good;
    good = k.vector("target", true, c.dimensions, key.target) && good;
    if (c.dimensions == 3 && k.has("up")) {
        if (k.vector("up", true, 3, key.up)) {
            if (!(glm::length(key.up) > 0.0)) {
                c.errors.add(k.pathOf("up"),
                             "must be a non-zero vector, got " + describe(*k.find("up")));
                good = false;
            }
        } else {
            good = false;
        }
    }
    return good;
}

void readCamera(JsonObjectReader& root, SceneLoadContext& c) {
    if (!root.require("camera", "an object with \"path\" and optional fov_deg, aspect, near, far"))
        return;
    JsonObjectReader camera(*root.find("camera"), "camera", c.errors);
    if (!camera.ok()) return;
    camera.checkKeys({"fov_deg", "aspect", "near", "far", "path"});
    CameraSpec& spec = c.scene.camera;
    if (c.dimensions == 3) {
        camera.number("fov_deg", false,
                      NumberRule{"a number of degrees in (0, 180)", 0.0, true, 180.0, true},
                      spec.fov_deg);
    } else {
        camera.number("fov_deg", false,
                      NumberRule{"a number of degrees in (0, 360]", 0.0, true, 360.0, false},
                      spec.fov_deg);
    }
    const NumberRule positive{"a finite number > 0", 0.0, true};
    camera.number("aspect", false, positive, spec.aspect);
    const bool near_ok = camera.number("near", false, positive, spec.near);
    const bool far_ok = camera.number("far", false, positive, spec.far);
    if (near_ok && far_ok && !(spec.near < spec.far)) {
        c.errors.add("camera.near", "must be less than camera.far = " + formatNumber(spec.far) +
                                        ", got " + formatNumber(spec.near));
    }
    if (!camera.require("path", "an array of at least one key { \"t\", \"position\", \"target\" }"))
        return;
    const Json& path = *camera.find("path");
    if (!path.is_array() || path.empty() || path.size() > kMaxPathKeys) {
        c.errors.add("camera.path", "must be an array of 1 to " + std::to_string(kMaxPathKeys) +
                                        " keys, got " + describe(path));
        return;
    }
    spec.path.clear();
    for (size_t i = 0; i < path.size(); ++i) {
        const std::string key_path = indexPath("camera.path", i);
        CameraKey key;
        if (!readCameraKey(path[i], key_path, c, key)) continue;
        if (!spec.path.empty() && !(key.t > spec.path.back().t)) {
            c.errors.add(childPath(key_path, "t"), "keys must be in increasing t, got " +
                                                       formatNumber(key.t) + " after " +
                                                       formatNumber(spec.path.back().t));
        }
        spec.path.push_back(key);
    }
}

// Numbers objects without an id after the largest given id, in file order.
bool numberListedIds(std::vector<ListedObject>& listed, SceneLoadContext& c, int& next_id) {
    int64_t largest = -1;
    for (const ListedObject& l : listed)
        if (l.has_id) largest = std::max<int64_t>(largest, l.object.id);
    int64_t next = largest + 1;
    for (ListedObject& l : listed) {
        if (l.has_id) continue;
        if (next > INT_MAX) {
            c.errors.add(l.path,
                         "cannot be given an id: the ids after the largest given id run "
                         "past " +
                             std::to_string(INT_MAX));
            return false;
        }
        l.object.id = int(next++);
    }
    next_id = int(std::min<int64_t>(next, INT_MAX));
    return true;
}

// Precomputes the walk of every random object (random_walk.h), keeping the
// total number of segments within kMaxRandomSegments.
void buildRandomWalks(Scene& scene) {
    int64_t random_objects = 0;
    for (const SceneObject& o : scene.objects)
        if (o.motion.kind == MotionKind::Random) ++random_objects;
    if (random_objects == 0) return;
    const double duration = std::max(scene.frames * scene.dt, kRandomSegmentSeconds);
    const int64_t wanted = int64_t(std::ceil(duration / kRandomSegmentSeconds - 1e-9));
    const int64_t budget = std::max<int64_t>(
        1, std::min(kMaxRandomSegmentsPerObject, kMaxRandomSegments / random_objects));
    const int64_t segments = std::clamp<int64_t>(wanted, 1, budget);
    const double seconds = std::max(kRandomSegmentSeconds, duration / double(segments));
    for (SceneObject& o : scene.objects) {
        if (o.motion.kind != MotionKind::Random) continue;
        buildRandomWalk(o.motion, scene.dimensions, scene.seed, o.id, int(segments), seconds);
    }
}

std::string stemOf(const std::string& file) {
    const size_t slash = file.find_last_of("/\\");
    std::string name = slash == std::string::npos ? file : file.substr(slash + 1);
    const size_t dot = name.rfind('.');
    if (dot != std::string::npos && dot > 0) name = name.substr(0, dot);
    return name;
}

SceneLoadResult loadScene(const std::string& text, const std::string& display_name,
                          const std::string& base_dir) {
    SceneLoadResult result;
    ErrorList errors(display_name);
    auto fail = [&]() {
        result.errors = errors.take();
        return result;
    };
    Json root;
    if (!parseJson(text, errors, root)) return fail();
    JsonObjectReader top(root, "", errors);
    if (!top.ok()) return fail();
    // "description" is an addition of ours: free text that says what a scene is for.
    top.checkKeys({"format", "name", "description", "dimensions", "world", "grid", "time", "seed",
                   "camera", "objects", "generators"});
    std::string format;
    if (top.string("format", true, format) && format != "gridcull-scene/1")
        errors.add("format", "must be \"gridcull-scene/1\", got " + describe(*top.find("format")));
    int64_t dimensions = 0;
    if (!top.integer("dimensions", true, 2, 3, "2 or 3", dimensions)) {
        // Every vector's length depends on it: checking further would only
        // produce misleading messages.
        return fail();
    }

    Scene scene;
    scene.dimensions = int(dimensions);
    scene.source_path = "";
    SceneLoadContext c{errors, base_dir, int(dimensions), scene, {}};
    scene.name = stemOf(display_name);
    top.string("name", false, scene.name);
    std::string description;
    top.string("description", false, description);

    const bool world_ok = readWorld(top, c);
    readGrid(top, c, world_ok);
    readTime(top, c);
    top.unsignedInteger("seed", false, scene.seed);
    readCamera(top, c);

    std::vector<ListedObject> listed;
    if (const Json* objects = top.find("objects")) {
        if (!objects->is_array()) {
            errors.add("objects", "must be an array of objects, got " + describe(*objects));
        } else if (int64_t(objects->size()) > kMaxSceneObjects) {
            errors.add("objects", "must hold at most " + std::to_string(kMaxSceneObjects) +
                                      " objects, got " + std::to_string(objects->size()));
        } else {
            readObjects(*objects, c, listed);
        }
    }
    std::vector<GeneratorPlan> plans;
    if (const Json* generators = top.find("generators")) {
        if (!generators->is_array()) {
            errors.add("generators", "must be an array of objects, got " + describe(*generators));
        } else {
            readGenerators(*generators, c, plans);
        }
    }
    if (!errors.empty()) return fail();

    int64_t total = int64_t(listed.size());
    for (const GeneratorPlan& plan : plans) total += plan.count;
    if (total > kMaxSceneObjects) {
        errors.add("generators", "would make the scene " + std::to_string(total) +
                                     " objects, more than the limit of " +
                                     std::to_string(kMaxSceneObjects));
        return fail();
    }
    int next_id = 0;
    if (!numberListedIds(listed, c, next_id)) return fail();
    scene.objects.reserve(size_t(total));
    for (ListedObject& l : listed) scene.objects.push_back(std::move(l.object));
    if (next_id > INT_MAX - int(total - int64_t(listed.size()))) {
        errors.add("generators", "cannot number generated objects: ids would run past " +
                                     std::to_string(INT_MAX));
        return fail();
    }
    for (size_t g = 0; g < plans.size(); ++g) runGenerator(plans[g], g, scene, next_id);
    if (!errors.empty()) return fail();

    buildRandomWalks(scene);
    scene.finalize();
    result.scene = std::move(scene);
    return result;
}

}  // namespace

SceneLoadResult loadSceneText(const std::string& text, const std::string& display_name,
                              const std::string& base_dir) {
    // Nothing may escape the library: whatever goes wrong becomes a message.
    try {
        return loadScene(text, display_name, base_dir);
    } catch (const std::bad_alloc&) {
        return {std::nullopt, {display_name + ": out of memory while loading the scene"}};
    } catch (const std::exception& e) {
        return {std::nullopt, {display_name + ": cannot load the scene: " + e.what()}};
    } catch (...) {
        return {std::nullopt, {display_name + ": cannot load the scene: unknown error"}};
    }
}

SceneLoadResult loadSceneFile(const std::string& path) {
    try {
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec))
            return {std::nullopt, {path + ": is a directory, not a scene file"}};
        std::ifstream in(path, std::ios::binary);
        if (!in) return {std::nullopt, {path + ": cannot open the scene file"}};
        std::ostringstream text;
        text << in.rdbuf();
        if (in.bad()) return {std::nullopt, {path + ": cannot read the scene file"}};
        const size_t slash = path.find_last_of('/');
        const std::string base_dir = slash == std::string::npos ? "." : path.substr(0, slash);
        SceneLoadResult result = loadSceneText(text.str(), path, base_dir.empty() ? "/" : base_dir);
        if (result.scene) result.scene->source_path = path;
        return result;
    } catch (const std::exception& e) {
        return {std::nullopt, {path + ": cannot load the scene: " + e.what()}};
    } catch (...) {
        return {std::nullopt, {path + ": cannot load the scene: unknown error"}};
    }
}

}  // namespace gridcull
