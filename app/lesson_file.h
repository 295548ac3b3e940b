// Reads and checks a lesson file (docs/lesson-format.md) the way scene files
// are checked: every problem is one message "FILE: json.path: what was
// expected, got what", and a lesson with any is refused whole. Beyond its
// shape, each step is checked against what it names: its scene loads, its
// cullers exist and run on the scene's dimension, its frame is one of the
// scene's, its view flags are view flags of the culler's family and in range.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "culling/scene/scene.h"
#include "ui/lesson.h"

namespace gridcull {

struct LessonLoadResult {
    std::optional<Lesson> lesson;     // set when there are no errors
    std::vector<std::string> errors;  // one line each, prefixed by the file name
};

// `command_line_scene` (may be null) is the scene of steps that name none in a
// lesson that names none either; its path (Scene::source_path, "" for the
// built-in scene) is what such steps open.
LessonLoadResult loadLessonFile(const std::string& path, const Scene* command_line_scene);
LessonLoadResult loadLessonText(const std::string& text, const std::string& display_name,
                                const std::string& base_dir, const Scene* command_line_scene);

// Longest lesson accepted; a lesson is read aloud, not generated.
constexpr size_t kMaxLessonSteps = 500;

}  // namespace gridcull
