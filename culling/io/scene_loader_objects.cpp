// The `objects` array of a scene file: shapes, ids and motion
// (scene-format.md, "Objects" and "Motion").
#include <algorithm>
#include <climits>
#include <cmath>
#include <filesystem>
#include <map>

#include <glm/geometric.hpp>

#include "culling/io/mesh_loader.h"
#include "culling/io/scene_loader.h"
#include "culling/io/scene_loader_internal.h"
#include "culling/scene/polygon2d.h"

namespace gridcull {

namespace {

const NumberRule kPositive{"a finite number > 0", 0.0, true};
const NumberRule kNonNegative{"a finite number >= 0", 0.0, false};

// A declared max_speed may exceed the real one; rounding in the real one's
// computation must not make an exact declaration fail.
constexpr double kSpeedTolerance = 1e-9;

bool readKeyframes(JsonObjectReader& m, SceneLoadContext& c, Motion& motion, double& real_speed) {
    if (!m.require("keys", "an array of at least one key { \"t\", \"position\" }")) return false;
    const Json& keys = *m.find("keys");
    const std::string keys_path = m.pathOf("keys");
    if (!keys.is_array() || keys.empty() || keys.size() > kMaxPathKeys) {
        c.errors.add(keys_path, "must be an array of 1 to " + std::to_string(kMaxPathKeys) +
                                    " keys { \"t\", \"position\" }, got " + describe(keys));
        return false;
    }
    bool good = true;
    motion.keys.clear();
    for (size_t i = 0; i < keys.size(); ++i) {
        JsonObjectReader k(keys[i], indexPath(keys_path, i), c.errors);
        if (!k.ok()) {
            good = false;
            continue;
        }
        k.checkKeys({"t", "position"});
        PositionKey key;
        bool key_ok = k.number("t", true, NumberRule{}, key.t);
        key_ok = k.vector("position", true, c.dimensions, key.position) && key_ok;
        if (!key_ok) {
            good = false;
            continue;
        }
        if (!motion.keys.empty() && !(key.t > motion.keys.back().t)) {
            c.errors.add(k.pathOf("t"), "keys must be in increasing t, got " + formatNumber(key.t) +
                                            " after " + formatNumber(motion.keys.back().t));
            good = false;
            continue;
        }
        motion.keys.push_back(key);
    }
    if (!good) return false;
    real_speed = keyframeSpeed(motion.keys);
    if (!(real_speed <= kMaxMagnitude)) {
        c.errors.add(keys_path, "imply a speed of " + formatNumber(real_speed) +
                                    ", more than the limit of " + formatNumber(kMaxMagnitude));
        return false;
    }
    return true;
}

}  // namespace

bool readMotion(const Json& value, const std::string& path, SceneLoadContext& c, Motion& motion) {
    JsonObjectReader m(value, path, c.errors);
    if (!m.ok()) return false;
    std::string type;
    if (!m.string("type", true, type)) return false;
    double real_speed = 0.0;
    bool good = true;
    if (type == "static") {
        motion.kind = MotionKind::Static;
        good = m.checkKeys({"type"}, "for motion 'static'");
    } else if (type == "linear") {
        motion.kind = MotionKind::Linear;
        good = m.checkKeys({"type", "velocity", "max_speed"}, "for motion 'linear'");
        good = m.vector("velocity", true, c.dimensions, motion.velocity) && good;
        real_speed = glm::length(motion.velocity);
    } else if (type == "keyframes") {
        motion.kind = MotionKind::Keyframes;
        good = m.checkKeys({"type", "keys", "max_speed"}, "for motion 'keyframes'");
        good = readKeyframes(m, c, motion, real_speed) && good;
    } else if (type == "random") {
        motion.kind = MotionKind::Random;
        good = m.checkKeys({"type", "max_speed"}, "for motion 'random'");
        good = m.number("max_speed", true, kNonNegative, real_speed) && good;
        motion.max_speed = real_speed;
        return good;
    } else {
        c.errors.add(m.pathOf("type"), "must be one of static, linear, keyframes, random, got " +
                                           describe(*m.find("type")));
        return false;
    }
    motion.max_speed = real_speed;
    if (good && m.has("max_speed")) {
        double declared = 0.0;
        if (!m.number("max_speed", true, kNonNegative, declared)) return false;
        if (declared < real_speed * (1.0 - kSpeedTolerance)) {
            c.errors.add(m.pathOf("max_speed"), "must be at least the real maximum speed " +
                                                    formatNumber(real_speed) + " of this " + type +
                                                    " motion, got " + formatNumber(declared));
            return false;
        }
        motion.max_speed = std::max(declared, real_speed);
    }
    return good;
}

namespace {

bool readBox(JsonObjectReader& r, SceneLoadContext& c, Aabb& box) {
    const bool has_min = r.vector("min", true, c.dimensions, box.min);
    const bool has_max = r.vector("max", true, c.dimensions, box.max);
    if (!has_min || !has_max) return false;
    bool good = true;
    for (int axis = 0; axis < c.dimensions; ++axis) {
        if (box.max[axis] > box.min[axis]) continue;
        c.errors.add(indexPath(r.pathOf("max"), size_t(axis)),
                     "must be greater than min[" + std::to_string(axis) + "] = " +
                         formatNumber(box.min[axis]) + ", got " + formatNumber(box.max[axis]));
        good = false;
    }
    return good;
}

bool readPolygon(JsonObjectReader& r, SceneLoadContext& c, std::vector<glm::dvec3>& points) {
    const std::string expected = "an array of 3 to " + std::to_string(kMaxPolygonPoints) +
                                 " points [x, y], a simple polygon in counter-clockwise order";
    if (!r.require("points", expected)) return false;
    const Json& value = *r.find("points");
    const std::string path = r.pathOf("points");
    if (!value.is_array() || value.size() < 3 || value.size() > kMaxPolygonPoints) {
        c.errors.add(path, "must be " + expected + ", got " + describe(value));
        return false;
    }
    points.assign(value.size(), glm::dvec3(0.0));
    bool good = true;
    for (size_t i = 0; i < value.size(); ++i)
        good = readVectorValue(value[i], indexPath(path, i), 2, c.errors, points[i]) && good;
    if (!good) return false;
    const std::string problem = checkSimpleCounterClockwise(points);
    if (!problem.empty()) {
        c.errors.add(path, "must be a simple polygon in counter-clockwise order, but " + problem);
        return false;
    }
    return true;
}

}  // namespace

std::shared_ptr<const TriangleMesh> loadSceneMeshFile(const std::string& file, double scale,
                                                      const glm::dvec3& rotation_deg,
                                                      const std::string& path,
                                                      SceneLoadContext& c) {
    const std::filesystem::path full =
        std::filesystem::path(file).is_absolute() || c.base_dir.empty()
            ? std::filesystem::path(file)
            : std::filesystem::path(c.base_dir) / file;
    const MeshKey key{full.lexically_normal().string(), scale, rotation_deg};
    const auto found = c.meshes.find(key);
    if (found != c.meshes.end()) return found->second;
    MeshLoadResult loaded = loadObjMesh(key.path, file, scale, rotation_deg);
    if (!loaded.mesh) {
        c.errors.add(path, "cannot be loaded: " + loaded.error);
        return nullptr;
    }
    const Aabb& b = loaded.mesh->bounds;
    const double reach = std::max(glm::length(b.min), glm::length(b.max));
    if (!(reach <= kMaxMagnitude)) {
        c.errors.add(path, "mesh reaches " + formatNumber(reach) +
                               " from its position once scaled, more than the limit of " +
                               formatNumber(kMaxMagnitude));
        return nullptr;
    }
    std::shared_ptr<const TriangleMesh> mesh = std::move(loaded.mesh);
    c.meshes.emplace(key, mesh);
    return mesh;
}

std::shared_ptr<const TriangleMesh> loadSceneMesh(JsonObjectReader& r, SceneLoadContext& c,
                                                  const char* scale_key) {
    std::string file;
    double scale = 1.0;
    glm::dvec3 rotation{0.0};
    bool good = r.string("file", true, file);
    if (good && file.empty()) {
        c.errors.add(r.pathOf("file"), "must name an OBJ file, got \"\"");
        good = false;
    }
    if (scale_key) good = r.number(scale_key, false, kPositive, scale) && good;
    if (r.has("rotation_deg")) good = r.vector("rotation_deg", true, 3, rotation) && good;
    if (!good) return nullptr;
    return loadSceneMeshFile(file, scale, rotation, r.pathOf("file"), c);
}

namespace {

// Reads one entry of `objects`; false when it is unusable (problems reported).
bool readObject(const Json& value, const std::string& path, SceneLoadContext& c,
                ListedObject& out) {
    JsonObjectReader r(value, path, c.errors);
    if (!r.ok()) return false;
    SceneObject& o = out.object;
    out.path = path;
    // The id first, so that duplicates are found even in objects with other problems.
    bool id_ok = true;
    if (r.has("id")) {
        int64_t id = -1;
        id_ok = r.integer("id", true, 0, INT_MAX,
                          "a non-negative integer (at most " + std::to_string(INT_MAX) + ")", id);
        if (id_ok) {
            o.id = int(id);
            out.has_id = true;
        }
    }
    std::string shape;
    const bool is_3d = c.dimensions == 3;
    const char* shapes = is_3d ? "sphere, box, mesh (the scene is 3D)"
                               : "circle (or sphere), box, polygon (the scene is 2D)";
    if (!r.string("shape", true, shape)) {
        r.checkKeys({"id", "shape", "motion", "center", "radius", "min", "max", "points", "file",
                     "position", "scale", "rotation_deg"});
        return false;
    }
    bool good = id_ok;
    const std::string context = "for shape '" + shape + "'";
    if (shape == "sphere" || (shape == "circle" && !is_3d)) {
        o.shape = ShapeKind::Sphere;
        good = r.checkKeys({"id", "shape", "motion", "center", "radius"}, context);
        good = r.vector("center", true, c.dimensions, o.center) && good;
        good = r.number("radius", true, kPositive, o.radius) && good;
    } else if (shape == "box") {
        o.shape = ShapeKind::Box;
        good = r.checkKeys({"id", "shape", "motion", "min", "max"}, context);
        good = readBox(r, c, o.box) && good;
    } else if (shape == "polygon" && !is_3d) {
        o.shape = ShapeKind::Polygon;
        good = r.checkKeys({"id", "shape", "motion", "points"}, context);
        good = readPolygon(r, c, o.points) && good;
    } else if (shape == "mesh" && is_3d) {
        o.shape = ShapeKind::Mesh;
        good = r.checkKeys({"id", "shape", "motion", "file", "position", "scale", "rotation_deg"},
                           context);
        good = r.vector("position", true, 3, o.center) && good;
        if (good) {
            o.mesh = loadSceneMesh(r, c, "scale");
            good = o.mesh != nullptr;
        }
    } else {
        const bool other_dimension = shape == "circle" || shape == "polygon" || shape == "mesh";
        c.errors.add(
            r.pathOf("shape"),
            (other_dimension ? "shape '" + shape + "' does not exist in a " +
                                   std::to_string(c.dimensions) + "D scene; must be one of "
                             : std::string("must be one of ")) +
                shapes + ", got " + describe(*r.find("shape")));
        return false;
    }
    if (const Json* motion = r.find("motion"))
        good = readMotion(*motion, r.pathOf("motion"), c, o.motion) && good;
    if (!good) return false;
    computeAnchorAndBounds(o, c.dimensions);
    return true;
}

}  // namespace

void readObjects(const Json& objects, SceneLoadContext& c, std::vector<ListedObject>& out) {
    std::map<int, std::string> path_of_id;
    out.reserve(objects.size());
    for (size_t i = 0; i < objects.size(); ++i) {
        const std::string path = indexPath("objects", i);
        ListedObject listed;
        const bool usable = readObject(objects[i], path, c, listed);
        if (listed.has_id) {
            const auto [it, inserted] = path_of_id.emplace(listed.object.id, path);
            if (!inserted) {
                c.errors.add(childPath(path, "id"), "must be unique, but id " +
                                                        std::to_string(listed.object.id) +
                                                        " is also used by " + it->second);
                continue;
            }
        }
        if (usable) out.push_back(std::move(listed));
    }
}

}  // namespace gridcull
