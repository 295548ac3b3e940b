#include "app/lesson_file.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "culling/io/scene_json.h"
#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"
#include "ui/registry/family_views.h"

namespace gridcull {

namespace {

// The scenes the steps name, each loaded once: by resolved path, the scene or
// null when it failed (its messages are reported at the first step naming it).
using SceneCache = std::map<std::string, std::optional<Scene>>;

std::string resolve(const std::string& base_dir, const std::string& file) {
    if (file.empty() || file.front() == '/') return file;
    return (std::filesystem::path(base_dir) / file).lexically_normal().string();
}

bool readText(JsonObjectReader& in, const char* key, bool required, ErrorList& errors,
              std::string& out) {
    if (!in.string(key, required, out)) return false;
    if (in.has(key) && out.empty()) {
        errors.add(in.pathOf(key), "must be a non-empty string");
        return false;
    }
    return true;
}

bool readView(JsonObjectReader& in, ErrorList& errors, ViewMode& view) {
    std::string name;
    if (!in.string("view", false, name)) return false;
    if (!in.has("view")) return true;
    static const std::pair<const char*, ViewMode> kViews[] = {
        {"overview", ViewMode::Overview},
        {"fly", ViewMode::Fly},
        {"culling-camera", ViewMode::CullingCamera},
        {"cameras", ViewMode::Cameras},
    };
    for (const auto& [key, mode] : kViews) {
        if (name == key) {
            view = mode;
            return true;
        }
    }
    errors.add(in.pathOf("view"),
               "must be one of overview, fly, culling-camera, cameras, got \"" + name + "\"");
    return false;
}

// A view flag of the lesson: known, of the step's culler's family, in range.
bool checkFlag(const std::string& path, const std::string& flag, double value,
               const std::string& algo, ErrorList& errors) {
    const Knob* knob = findViewFlag(flag);
    if (!knob) {
        errors.add(path, "is no view flag (see gridcull view --help)");
        return false;
    }
    const FamilyEntry* family = familyOfAlgorithm(algo);
    const FamilyViewEntry* owner = familyViewOfFlag(flag);
    if (family && owner && owner->family != family->id) {
        errors.add(path, "is a view flag of the " + owner->family + " family, and the step shows " +
                             algo + " (" + family->id + ")");
        return false;
    }
    std::string why;
    double checked = 0.0;
    if (!parseKnobValue(*knob, formatNumber(value), checked, why)) {
        errors.add(path, why);
        return false;
    }
    return true;
}

bool readFlags(JsonObjectReader& in, const std::string& algo, ErrorList& errors,
               KnobValues& flags) {
    const Json* value = in.find("flags");
    if (!value) return true;
    const std::string path = in.pathOf("flags");
    if (!value->is_object()) {
        errors.add(path, "must be an object of view flags and numbers, got " + describe(*value));
        return false;
    }
    bool ok = true;
    for (const auto& [flag, number] : value->items()) {
        double v = 0.0;
        if (!readNumberValue(number, childPath(path, flag), NumberRule{}, errors, v)) {
            ok = false;
            continue;
        }
        if (checkFlag(childPath(path, flag), flag, v, algo, errors))
            flags.set(flag, v);
        else
            ok = false;
    }
    return ok;
}

bool readAnimation(JsonObjectReader& step, const std::string& algo, ErrorList& errors,
                   LessonAnimation& animate) {
    const Json* value = step.find("animate");
    if (!value) return true;
    JsonObjectReader in(*value, step.pathOf("animate"), errors);
    if (!in.ok() || !in.checkKeys({"flag", "from", "to", "seconds_per_value"})) return false;
    int64_t from = 0, to = 0;
    bool ok = in.string("flag", true, animate.flag);
    ok &= in.integer("from", true, 0, 100000000, "an integer from 0 to 100000000", from);
    ok &= in.integer("to", true, 0, 100000000, "an integer from 0 to 100000000", to);
    ok &= in.number("seconds_per_value", false,
                    NumberRule{"a number of seconds from 0.05 to 60", 0.05, false, 60.0, false},
                    animate.seconds_per_value);
    if (!ok) return false;
    if (to < from) {
        errors.add(in.pathOf("to"), "must be at least \"from\" (" + std::to_string(from) +
                                        "), got " + std::to_string(to));
        return false;
    }
    animate.from = int(from);
    animate.to = int(to);
    return checkFlag(in.pathOf("flag"), animate.flag, double(from), algo, errors) &&
           checkFlag(in.pathOf("flag"), animate.flag, double(to), algo, errors);
}

const Scene* sceneOf(const std::string& file, const Scene* command_line_scene,
                     SceneCache& scenes, ErrorList& errors, const std::string& path) {
    if (command_line_scene && file == command_line_scene->source_path) return command_line_scene;
    auto found = scenes.find(file);
    if (found == scenes.end()) {
        SceneLoadResult loaded = loadSceneFile(file);
        if (!loaded.scene) {
            errors.add(path, "the scene \"" + file + "\" is refused:");
            for (const std::string& message : loaded.errors) errors.addGeneral("  " + message);
        }
        found = scenes.emplace(file, std::move(loaded.scene)).first;
    }
    return found->second ? &*found->second : nullptr;
}

// One step; `previous_algo` is the culler shown before it ("" for the first).
bool readStep(const Json& value, const std::string& path, const Lesson& lesson,
              const std::string& base_dir, const Scene* command_line_scene,
              const std::string& previous_algo, SceneCache& scenes, ErrorList& errors,
              LessonStep& step) {
    JsonObjectReader in(value, path, errors);
    if (!in.ok()) return false;
    bool ok = in.checkKeys({"title", "caption", "section", "scene", "algo", "compare", "frame",
                            "view", "overlays", "flags", "animate", "seconds"},
                           "in a lesson step");
    ok &= readText(in, "title", true, errors, step.title);
    ok &= readText(in, "caption", true, errors, step.caption);
    ok &= readText(in, "section", true, errors, step.section);
    std::string scene_file;
    ok &= readText(in, "scene", false, errors, scene_file);
    step.scene = scene_file.empty() ? lesson.scene : resolve(base_dir, scene_file);
    ok &= readText(in, "algo", false, errors, step.algo);
    if (step.algo.empty()) step.algo = previous_algo;
    ok &= readText(in, "compare", false, errors, step.compare);
    int64_t frame = 0;
    ok &= in.integer("frame", false, 0, 100000000, "a frame number, 0 or more", frame);
    step.frame = int(frame);
    ok &= readView(in, errors, step.view);
    std::string overlays;
    if (in.string("overlays", false, overlays) && in.has("overlays")) {
        step.has_overlays = parseOverlayPreset(overlays, step.overlays);
        if (!step.has_overlays) {
            errors.add(in.pathOf("overlays"),
                       "must be one of " + overlayPresetKeys() + ", got \"" + overlays + "\"");
            ok = false;
        }
    }
    ok &= in.number("seconds", false,
                    NumberRule{"a number of seconds from 1 to 600", 1.0, false, 600.0, false},
                    step.seconds);
    if (step.algo.empty()) {
        errors.add(in.pathOf("algo"), "is missing: the first step names its culler");
        return false;
    }
    ok &= readFlags(in, step.algo, errors, step.flags);
    ok &= readAnimation(in, step.algo, errors, step.animate);
    if (!ok) return false;

    // What the step names must exist in its scene.
    if (step.scene.empty() && !command_line_scene) {
        errors.add(path, "has no scene: name one in the step or the lesson, or give SCENE");
        return false;
    }
    const Scene* scene =
        step.scene.empty() ? command_line_scene
                           : sceneOf(step.scene, command_line_scene, scenes, errors,
                                     scene_file.empty() ? "scene" : in.pathOf("scene"));
    if (step.scene.empty()) step.scene = command_line_scene->source_path;
    if (!scene) return false;
    for (const char* key : {"algo", "compare"}) {
        const std::string& name = key[0] == 'a' ? step.algo : step.compare;
        std::string why;
        if (name.empty() || algorithmFits(name, *scene, why)) continue;
        errors.add(in.pathOf(key), why);
        ok = false;
    }
    if (step.frame >= scene->frames) {
        errors.add(in.pathOf("frame"), "must be below the scene's " +
                                           std::to_string(scene->frames) + " frames, got " +
                                           std::to_string(step.frame));
        ok = false;
    }
    if (scene->dimensions == 2 && step.view != ViewMode::Overview) {
        errors.add(in.pathOf("view"), "must be overview in a 2D scene (a map from above)");
        ok = false;
    }
    return ok;
}

}  // namespace

LessonLoadResult loadLessonText(const std::string& text, const std::string& display_name,
                                const std::string& base_dir, const Scene* command_line_scene) {
    LessonLoadResult result;
    ErrorList errors(display_name);
    Json root;
    if (parseJson(text, errors, root)) {
        Lesson lesson;
        lesson.file = display_name;
        JsonObjectReader in(root, "", errors);
        if (in.ok() && in.checkKeys({"title", "scene", "steps"}, "in a lesson")) {
            readText(in, "title", true, errors, lesson.title);
            std::string scene_file;
            if (readText(in, "scene", false, errors, scene_file))
                lesson.scene = resolve(base_dir, scene_file);
            const Json* steps = in.find("steps");
            const std::string steps_path = in.pathOf("steps");
            if (!steps) {
                errors.add(steps_path, "is missing: a lesson is a list of steps");
            } else if (!steps->is_array() || steps->empty() ||
                       steps->size() > kMaxLessonSteps) {
                errors.add(steps_path, "must be a list of 1 to " +
                                           std::to_string(kMaxLessonSteps) + " steps, got " +
                                           describe(*steps));
            } else {
                SceneCache scenes;
                std::string algo;
                for (size_t k = 0; k < steps->size(); ++k) {
                    LessonStep step;
                    if (readStep((*steps)[k], indexPath(steps_path, k), lesson, base_dir,
                                 command_line_scene, algo, scenes, errors, step))
                        algo = step.algo;
                    lesson.steps.push_back(std::move(step));
                }
            }
        }
        if (errors.empty()) result.lesson = std::move(lesson);
    }
    result.errors = errors.take();
    return result;
}

LessonLoadResult loadLessonFile(const std::string& path, const Scene* command_line_scene) {
    try {
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec))
            return {std::nullopt, {path + ": is a directory, not a lesson file"}};
        std::ifstream in(path, std::ios::binary);
        if (!in) return {std::nullopt, {path + ": cannot open the lesson file"}};
        std::ostringstream text;
        text << in.rdbuf();
        if (in.bad()) return {std::nullopt, {path + ": cannot read the lesson file"}};
        const std::string base_dir = std::filesystem::path(path).parent_path().string();
        return loadLessonText(text.str(), path, base_dir.empty() ? "." : base_dir,
                              command_line_scene);
    } catch (const std::exception& e) {
        return {std::nullopt, {path + ": cannot load the lesson: " + e.what()}};
    } catch (...) {
        return {std::nullopt, {path + ": cannot load the lesson: unknown error"}};
    }
}

}  // namespace gridcull
