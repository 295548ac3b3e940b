// Lesson files (app/lesson_file.h): the shipped ones load, and every kind of
// mistake is refused with a message naming the file and the JSON path.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "app/lesson_file.h"
#include "run_command.h"

namespace gridcull {
namespace {

// A lesson on the small walls scene, its step's keys given as JSON text.
LessonLoadResult lessonWithStep(const std::string& step_keys) {
    const std::string text = R"({"title": "t", "scene": "scenes/walls-2d.json", "steps": [{
        "title": "s", "caption": "c", "section": "x", "algo": "rgvc", )" +
                             step_keys + "}]}";
    return loadLessonText(text, "test.json", test::sourcePath(""), nullptr);
}

std::string allErrors(const LessonLoadResult& result) {
    std::string all;
    for (const std::string& e : result.errors) all += e + "\n";
    return all;
}

void expectRefused(const std::string& step_keys, const std::string& message) {
    const LessonLoadResult result = lessonWithStep(step_keys);
    EXPECT_FALSE(result.lesson) << step_keys;
    EXPECT_NE(allErrors(result).find(message), std::string::npos)
        << "expected: " << message << "\ngot:\n" << allErrors(result);
}

TEST(LessonFile, EveryShippedLessonLoads) {
    int lessons = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath("lessons"))) {
        if (entry.path().extension() != ".json") continue;
        ++lessons;
        const LessonLoadResult result = loadLessonFile(entry.path().string(), nullptr);
        ASSERT_TRUE(result.lesson) << allErrors(result);
        for (const LessonStep& step : result.lesson->steps) {
            EXPECT_FALSE(step.caption.empty());
            EXPECT_FALSE(step.section.empty());
            EXPECT_TRUE(std::filesystem::exists(step.scene)) << step.scene;
        }
    }
    EXPECT_GE(lessons, 4);
}

TEST(LessonFile, AGoodStepReadsAsWritten) {
    const LessonLoadResult result = lessonWithStep(
        R"("frame": 7, "compare": "vfc", "overlays": "traversal", "flags": {"rgvc-occluder": 2},
           "animate": {"flag": "rgvc-layer", "from": 1, "to": 9, "seconds_per_value": 0.1},
           "seconds": 3)");
    ASSERT_TRUE(result.lesson) << allErrors(result);
    const LessonStep& step = result.lesson->steps[0];
    EXPECT_EQ(step.frame, 7);
    EXPECT_EQ(step.compare, "vfc");
    EXPECT_TRUE(step.has_overlays);
    EXPECT_EQ(step.overlays, OverlayPreset::Traversal);
    EXPECT_EQ(step.flags.set_values().at("rgvc-occluder"), 2.0);
    EXPECT_EQ(step.animate.flag, "rgvc-layer");
    EXPECT_EQ(step.animate.to, 9);
    EXPECT_DOUBLE_EQ(step.seconds, 3.0);
    EXPECT_EQ(step.scene, test::sourcePath("scenes/walls-2d.json"));
}

TEST(LessonFile, MistakesAreRefusedNamingThePath) {
    expectRefused(R"("colour": 1)", "test.json: steps[0].colour: unknown key in a lesson step");
    expectRefused(R"("overlays": "layers")",
                  "steps[0].overlays: must be one of occlusion, traversal, tbvs, all");
    expectRefused(R"("flags": {"lazy-object": 1})",
                  "steps[0].flags.lazy-object: is a view flag of the lazy-grid family");
    expectRefused(R"("flags": {"rgvc-nothing": 1})", "steps[0].flags.rgvc-nothing: is no view flag");
    expectRefused(R"("flags": {"rgvc-slice-axis": 5})", "steps[0].flags.rgvc-slice-axis:");
    expectRefused(R"("frame": 100000)", "steps[0].frame: must be below the scene's");
    expectRefused(R"("view": "culling-camera")", "steps[0].view: must be overview in a 2D scene");
    expectRefused(R"("view": "sideways")", "steps[0].view: must be one of overview");
    expectRefused(R"("compare": "lazy-grid")", "steps[0].compare:");
    expectRefused(R"("animate": {"flag": "rgvc-layer", "from": 5, "to": 2})",
                  "steps[0].animate.to: must be at least");
    expectRefused(R"("caption": "")", "steps[0].caption: must be a non-empty string");
    expectRefused(R"("scene": "scenes/none.json")", "the scene");
}

TEST(LessonFile, TheFirstStepNamesItsCullerAndEveryStepAScene) {
    LessonLoadResult result = loadLessonText(
        R"({"title": "t", "scene": "scenes/walls-2d.json",
            "steps": [{"title": "s", "caption": "c", "section": "x"}]})",
        "test.json", test::sourcePath(""), nullptr);
    EXPECT_NE(allErrors(result).find("steps[0].algo: is missing"), std::string::npos)
        << allErrors(result);
    result = loadLessonText(
        R"({"title": "t", "steps": [{"title": "s", "caption": "c", "section": "x", "algo": "vfc"}]})",
        "test.json", test::sourcePath(""), nullptr);
    EXPECT_NE(allErrors(result).find("steps[0]: has no scene"), std::string::npos)
        << allErrors(result);
}

TEST(LessonFile, BrokenJsonAndEmptyListsAreRefused) {
    LessonLoadResult result = loadLessonText("{\"title\": ", "test.json", ".", nullptr);
    EXPECT_FALSE(result.lesson);
    EXPECT_NE(allErrors(result).find("test.json:1:"), std::string::npos) << allErrors(result);
    result = loadLessonText(R"({"title": "t", "steps": []})", "test.json", ".", nullptr);
    EXPECT_NE(allErrors(result).find("steps: must be a list of 1 to 500 steps"),
              std::string::npos)
        << allErrors(result);
    result = loadLessonFile(test::sourcePath("lessons/none.json"), nullptr);
    EXPECT_NE(allErrors(result).find("cannot open the lesson file"), std::string::npos);
}

}  // namespace
}  // namespace gridcull
