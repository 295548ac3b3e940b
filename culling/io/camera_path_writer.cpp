#include "culling/io/camera_path_writer.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "culling/io/scene_loader.h"
#include "culling/scene/scene_limits.h"

namespace gridcull {

namespace {

// ordered_json keeps the file's keys in their order, so the file reads as before.
using OrderedJson = nlohmann::ordered_json;

// A position as the scene's dimension writes it: 2D scenes give x and y only.
OrderedJson vec(const glm::dvec3& v, int dimensions) {
    return dimensions == 2 ? OrderedJson::array({v.x, v.y}) : OrderedJson::array({v.x, v.y, v.z});
}

bool readFile(const std::string& path, std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream out;
    out << in.rdbuf();
    text = out.str();
    return !in.bad();
}

bool writeFile(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    return bool(out);
}

}  // namespace

bool writeCameraPath(const std::string& scene_file, const std::vector<CameraKey>& keys, double dt,
                     std::string& error) {
    if (keys.empty() || keys.size() > kMaxPathKeys || !(dt > 0.0)) {
        error = scene_file + ": no camera path to write";
        return false;
    }
    std::string text;
    if (!readFile(scene_file, text)) {
        error = scene_file + ": cannot read the scene file";
        return false;
    }
    OrderedJson root = OrderedJson::parse(text, nullptr, false);
    if (root.is_discarded() || !root.is_object() || !root.contains("camera") ||
        !root["camera"].is_object()) {
        error = scene_file + ": is not a scene file with a camera any more";
        return false;
    }
    const OrderedJson* given = root.contains("dimensions") ? &root["dimensions"] : nullptr;
    const int dimensions = given && given->is_number_integer() && *given == 2 ? 2 : 3;
    OrderedJson path = OrderedJson::array();
    for (const CameraKey& key : keys) {
        OrderedJson k = {{"t", key.t},
                         {"position", vec(key.position, dimensions)},
                         {"target", vec(key.target, dimensions)}};
        if (dimensions == 3 && key.up != glm::dvec3(0.0, 1.0, 0.0)) k["up"] = vec(key.up, 3);
        path.push_back(std::move(k));
    }
    root["camera"]["path"] = std::move(path);
    // Frames 0 .. the last key's: the run flies the whole path, no further.
    const double frames = std::floor(keys.back().t / dt + 1e-9) + 1.0;
    if (!root.contains("time") || !root["time"].is_object()) root["time"] = OrderedJson::object();
    root["time"]["frames"] = int64_t(std::min(frames, double(kMaxSceneFrames)));
    if (!root["time"].contains("dt")) root["time"]["dt"] = dt;
    const std::string written = root.dump(2) + "\n";

    namespace fs = std::filesystem;
    const fs::path file(scene_file);
    const std::string base_dir = file.parent_path().empty() ? "." : file.parent_path().string();
    const SceneLoadResult check = loadSceneText(written, scene_file, base_dir);
    if (!check.scene) {
        error = scene_file + ": the flown path would not load: " +
                (check.errors.empty() ? std::string("rejected") : check.errors.front());
        return false;
    }
    const std::string temporary = scene_file + ".writing";
    std::error_code ec;
    if (!writeFile(temporary, written)) {
        fs::remove(temporary, ec);
        error = scene_file + ": cannot write beside the scene file";
        return false;
    }
    fs::copy_file(file, scene_file + "~", fs::copy_options::overwrite_existing, ec);
    if (ec) {
        fs::remove(temporary, ec);
        error = scene_file + ": cannot keep the old file as " + scene_file + "~";
        return false;
    }
    fs::rename(temporary, file, ec);
    if (ec) {
        fs::remove(temporary, ec);
        error = scene_file + ": cannot replace the scene file";
        return false;
    }
    return true;
}

}  // namespace gridcull
