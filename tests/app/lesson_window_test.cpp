// Every lesson in lessons/ played to its last step in the window, driven headless
// with synthetic key taps (PageDown, as a presentation clicker sends, and N / P),
// each step checked in the snapshot the panels are shown: the step, its scene,
// culler, compared culler, frame and view. Needs an X display (xvfb-run).
#include <filesystem>

#include <GLFW/glfw3.h>

#include <gtest/gtest.h>

#include "app/debugger.h"
#include "app/gl_context.h"
#include "app/imgui_runtime.h"
#include "app/input_queue.h"
#include "app/lesson_file.h"
#include "app/window_frame.h"
#include "culling/io/scene_loader.h"
#include "run_command.h"

namespace gridcull {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

class LessonWindowTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(window_.create(kWidth, kHeight, "gridcull test", false, error)) << error;
        ASSERT_TRUE(imgui_.init(window_.get(), error)) << error;
        InputQueue::install(window_.get(), &input_);
    }
    void frames(Debugger& debugger, int count) {
        for (int i = 0; i < count; ++i)
            drawWindowFrame(debugger, window_.get(), input_, kWidth, kHeight, kWidth, kHeight);
    }
    void tap(int key) {
        input_.push(key, true);
        input_.push(key, false);
    }
    // What the snapshot says against what `step` asks for.
    static void expectShows(const Debugger& debugger, const LessonStep& step, int index) {
        const FrameSnapshot shown = debugger.snapshot();
        ASSERT_NE(shown.lesson, nullptr);
        EXPECT_EQ(shown.lesson->stepIndex(), index);
        EXPECT_EQ(*shown.scene_file, step.scene) << "step " << index + 1;
        EXPECT_EQ(shown.frame, step.frame) << "step " << index + 1;
        ASSERT_GE(shown.algo_index, 0);
        EXPECT_EQ((*shown.algo_names)[size_t(shown.algo_index)], step.algo);
        if (step.compare.empty()) {
            EXPECT_EQ(shown.compare_index, -1) << "step " << index + 1;
        } else {
            ASSERT_GE(shown.compare_index, 0) << "step " << index + 1;
            EXPECT_EQ((*shown.algo_names)[size_t(shown.compare_index)], step.compare);
            // Both cullers on the step's frame, the split view captioned.
            ASSERT_NE(debugger.compareSession(), nullptr);
            EXPECT_EQ(debugger.compareSession()->frame(), step.frame);
            ASSERT_NE(shown.panes, nullptr);
            EXPECT_EQ(shown.panes->size(), 2u);
        }
        EXPECT_EQ(shown.view_mode, step.view) << "step " << index + 1;
        EXPECT_TRUE(shown.scene_errors->empty()) << shown.scene_errors->front();
    }

    GlWindow window_;
    ImGuiRuntime imgui_;
    InputQueue input_;
};

TEST_F(LessonWindowTest, EveryLessonPlaysToItsLastStep) {
    int played = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourcePath("lessons"))) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        const LessonLoadResult loaded = loadLessonFile(entry.path().string(), nullptr);
        ASSERT_TRUE(loaded.lesson);
        const Lesson& lesson = *loaded.lesson;
        SceneLoadResult scene = loadSceneFile(lesson.steps.front().scene);
        ASSERT_TRUE(scene.scene);
        ViewOptions options;
        options.knobs.set("oracle-res", 128);  // the lesson's pictures, faster
        options.lesson = std::make_shared<const Lesson>(lesson);
        Debugger debugger(options);
        std::string error;
        ASSERT_TRUE(debugger.init(*scene.scene, error)) << error;
        frames(debugger, 1);
        expectShows(debugger, lesson.steps[0], 0);
        for (size_t k = 1; k < lesson.steps.size(); ++k) {
            tap(k % 2 ? GLFW_KEY_PAGE_DOWN : GLFW_KEY_N);
            frames(debugger, 2);
            expectShows(debugger, lesson.steps[k], int(k));
        }
        // Past the last step nothing moves; PageUp goes back one.
        const int last = int(lesson.steps.size()) - 1;
        tap(GLFW_KEY_PAGE_DOWN);
        frames(debugger, 2);
        EXPECT_EQ(debugger.snapshot().lesson->stepIndex(), last);
        tap(GLFW_KEY_PAGE_UP);
        frames(debugger, 2);
        expectShows(debugger, lesson.steps[size_t(last - 1)], last - 1);
        ++played;
    }
    EXPECT_GE(played, 4);
}

}  // namespace
}  // namespace gridcull
