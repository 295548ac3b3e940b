#include "culling/io/scene_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unordered_map>

#include <nlohmann/json.hpp>

namespace gridcull {

namespace {

// ordered_json keeps the keys in the order of docs/scene-format.md, so a
// written file reads like a hand-written one.
using OrderedJson = nlohmann::ordered_json;

// A vector as the scene's dimension writes it: 2D scenes give x and y only.
OrderedJson vec(const glm::dvec3& v, int dimensions) {
    return dimensions == 2 ? OrderedJson::array({v.x, v.y}) : OrderedJson::array({v.x, v.y, v.z});
}

OrderedJson motionJson(const Motion& m, int dimensions) {
    OrderedJson j;
    switch (m.kind) {
        case MotionKind::Static:
            return j;
        case MotionKind::Linear:
            j = {{"type", "linear"}, {"velocity", vec(m.velocity, dimensions)}};
            break;
        case MotionKind::Keyframes: {
            OrderedJson keys = OrderedJson::array();
            for (const PositionKey& k : m.keys)
                keys.push_back({{"t", k.t}, {"position", vec(k.position, dimensions)}});
            j = {{"type", "keyframes"}, {"keys", std::move(keys)}};
            break;
        }
        case MotionKind::Random:
            j = {{"type", "random"}};
            break;
    }
    // Always declared: a culler's temporal bounding volumes grow with it, so the
    // replay must see the same value even where it exceeds the real speed.
    j["max_speed"] = m.max_speed;
    return j;
}

OrderedJson objectJson(const SceneObject& o, int dimensions, const std::string& mesh_file) {
    OrderedJson j = {{"id", o.id}, {"shape", shapeName(o.shape, dimensions)}};
    switch (o.shape) {
        case ShapeKind::Sphere:
            j["center"] = vec(o.center, dimensions);
            j["radius"] = o.radius;
            break;
        case ShapeKind::Box:
            j["min"] = vec(o.box.min, dimensions);
            j["max"] = vec(o.box.max, dimensions);
            break;
        case ShapeKind::Polygon: {
            OrderedJson points = OrderedJson::array();
            for (const glm::dvec3& p : o.points) points.push_back(vec(p, dimensions));
            j["points"] = std::move(points);
            break;
        }
        case ShapeKind::Mesh:
            j["file"] = mesh_file;
            j["position"] = vec(o.center, dimensions);
            break;
    }
    if (o.motion.kind != MotionKind::Static) j["motion"] = motionJson(o.motion, dimensions);
    return j;
}

OrderedJson cameraJson(const CameraSpec& camera, int dimensions) {
    OrderedJson path = OrderedJson::array();
    for (const CameraKey& key : camera.path) {
        OrderedJson k = {{"t", key.t},
                         {"position", vec(key.position, dimensions)},
                         {"target", vec(key.target, dimensions)}};
        if (dimensions == 3) k["up"] = vec(key.up, 3);
        path.push_back(std::move(k));
    }
    return {{"fov_deg", camera.fov_deg},
            {"aspect", camera.aspect},
            {"near", camera.near},
            {"far", camera.far},
            {"path", std::move(path)}};
}

bool writeText(const std::string& path, const std::string& text, std::string& error) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) error = path + ": cannot be written";
    return bool(out);
}

}  // namespace

std::vector<const TriangleMesh*> meshesOf(const Scene& scene) {
    std::vector<const TriangleMesh*> meshes;
    for (const SceneObject& o : scene.objects) {
        if (o.shape != ShapeKind::Mesh || !o.mesh) continue;
        if (std::find(meshes.begin(), meshes.end(), o.mesh.get()) == meshes.end())
            meshes.push_back(o.mesh.get());
    }
    return meshes;
}

std::string sceneJsonText(const Scene& scene, const std::vector<std::string>& mesh_files) {
    const int d = scene.dimensions;
    const std::vector<const TriangleMesh*> meshes = meshesOf(scene);
    std::unordered_map<const TriangleMesh*, std::string> file_of;
    for (size_t k = 0; k < meshes.size() && k < mesh_files.size(); ++k)
        file_of[meshes[k]] = mesh_files[k];
    const glm::ivec3 r = scene.grid.resolution;
    OrderedJson root = {
        {"format", "gridcull-scene/1"},
        {"name", scene.name},
        {"dimensions", d},
        {"world", {{"min", vec(scene.grid.world.min, d)}, {"max", vec(scene.grid.world.max, d)}}},
        {"grid",
         {{"resolution",
           d == 2 ? OrderedJson::array({r.x, r.y}) : OrderedJson::array({r.x, r.y, r.z})}}},
        {"time", {{"frames", scene.frames}, {"dt", scene.dt}}},
        {"seed", scene.seed},
        {"camera", cameraJson(scene.camera, d)}};
    OrderedJson objects = OrderedJson::array();
    for (const SceneObject& o : scene.objects) {
        const auto file = o.mesh ? file_of.find(o.mesh.get()) : file_of.end();
        objects.push_back(objectJson(o, d, file == file_of.end() ? "" : file->second));
    }
    root["objects"] = std::move(objects);
    return root.dump(2) + "\n";
}

std::string objText(const TriangleMesh& mesh) {
    std::string text;
    char line[160];
    // 17 digits: the same double through a correctly rounded reader, and the
    // same float through the OBJ reader (its error is far below a float's step).
    for (const glm::dvec3& v : mesh.vertices) {
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v.x, v.y, v.z);
        text += line;
    }
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::snprintf(line, sizeof line, "f %u %u %u\n", mesh.indices[t] + 1,
                      mesh.indices[t + 1] + 1, mesh.indices[t + 2] + 1);
        text += line;
    }
    return text;
}

bool writeSceneFile(const Scene& scene, const std::string& path, std::string& error) {
    namespace fs = std::filesystem;
    const fs::path file(path);
    const std::vector<const TriangleMesh*> meshes = meshesOf(scene);
    std::vector<std::string> names;
    for (size_t k = 0; k < meshes.size(); ++k) {
        names.push_back(file.stem().string() + "-mesh" + std::to_string(k) + ".obj");
        if (!writeText((file.parent_path() / names.back()).string(), objText(*meshes[k]), error))
            return false;
    }
    return writeText(path, sceneJsonText(scene, names), error);
}

}  // namespace gridcull
