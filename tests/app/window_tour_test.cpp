// The real window driven headless through what a user does, on a 2D scene and
// two 3D ones: every culler the registry offers for the scene selected as the
// algorithm panel selects it, key taps stepping forward and back, the frame
// slider's seek in the background, every overlay preset the family offers, every view mode (3D),
// a compared culler beside it, and at the end another scene opened as the scene
// panel opens it. Each step checks what the panels are shown. Its main purpose
// is the sanitized build (scripts/test.sh): there the same frames run under
// AddressSanitizer and UndefinedBehaviorSanitizer over the ui and app code and
// the GL drawing of every family's overlay, and any report fails the test.
// Needs an X display (xvfb-run).
#include <GLFW/glfw3.h>

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/debugger.h"
#include "app/gl_context.h"
#include "app/imgui_runtime.h"
#include "app/input_queue.h"
#include "app/window_frame.h"
#include "culling/io/scene_loader.h"
#include "run_command.h"
#include "ui/overlay_preset.h"
#include "ui/registry/family_views.h"

namespace gridcull {
namespace {

constexpr int kWidth = 1280, kHeight = 720;
// The frame the slider seeks to (plus the culler's index, so each seek starts
// from somewhere else): far enough for temporal bounding volumes to expire and
// queries to be answered late, near enough to keep the sanitized run short.
constexpr int kSeekFrame = 24;
// A seek that has not finished after this many window frames is stuck.
constexpr int kMaxSeekFrames = 100000;

struct TourCase {
    const char* scene;       // the scene the window starts on
    const char* then_opens;  // the scene opened from the scene panel at the end
};

class WindowTourTest : public ::testing::TestWithParam<TourCase> {
protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(window_.create(kWidth, kHeight, "gridcull test", false, error)) << error;
        ASSERT_TRUE(imgui_.init(window_.get(), error)) << error;
        InputQueue::install(window_.get(), &input_);
        // The oracle at a modest resolution: the tour is about the window's
        // code paths, not about the oracle's precision.
        options_.knobs.set("oracle-res", 96);
    }
    void frames(Debugger& debugger, int count) {
        for (int i = 0; i < count; ++i)
            drawWindowFrame(debugger, window_.get(), input_, kWidth, kHeight, kWidth, kHeight);
    }
    // Frames until every queued key event was delivered (one per key a frame).
    void drain(Debugger& debugger) {
        do frames(debugger, 1);
        while (!input_.empty());
    }
    void tap(int key) {
        input_.push(key, true);
        input_.push(key, false);
    }
    void finishSeek(Debugger& debugger) {
        for (int i = 0; i < kMaxSeekFrames && debugger.session().seeking(); ++i)
            frames(debugger, 1);
        ASSERT_FALSE(debugger.session().seeking());
    }
    static std::vector<OverlayPreset> noPresets() { return {}; }
    static std::string shownAlgorithm(const FrameSnapshot& shown) {
        if (shown.algo_index < 0) return "";
        return (*shown.algo_names)[size_t(shown.algo_index)];
    }
    static void expectNoSceneErrors(const FrameSnapshot& shown) {
        ASSERT_NE(shown.scene_errors, nullptr);
        EXPECT_TRUE(shown.scene_errors->empty())
            << (shown.scene_errors->empty() ? "" : shown.scene_errors->front());
    }

    GlWindow window_;
    ImGuiRuntime imgui_;
    InputQueue input_;
    ViewOptions options_;
};

TEST_P(WindowTourTest, EveryCullerSteppedSeekedWithEveryOverlayAndView) {
    const TourCase tour = GetParam();
    SceneLoadResult loaded = loadSceneFile(test::sourcePath(tour.scene));
    ASSERT_TRUE(loaded.scene);
    const int last_frame = loaded.scene->frames - 1;
    const bool dimensions3 = loaded.scene->dimensions == 3;
    Debugger debugger(options_);
    std::string error;
    ASSERT_TRUE(debugger.init(*loaded.scene, error)) << error;
    frames(debugger, 2);

    // The window's list is the registry's for this dimension, nothing left out.
    const std::vector<std::string> offered = debugger.offeredAlgorithms();
    EXPECT_EQ(offered, algorithmNames(loaded.scene->dimensions));
    ASSERT_GE(offered.size(), 2u);
    for (size_t k = 0; k < offered.size(); ++k) {
        SCOPED_TRACE(offered[k]);
        UiActions select;
        select.algorithm.select_algo = int(k);
        debugger.apply(select);
        frames(debugger, 1);
        FrameSnapshot shown = debugger.snapshot();
        expectNoSceneErrors(shown);
        EXPECT_EQ(shownAlgorithm(shown), offered[k]);
        const int start = shown.frame;

        // Three taps forward, one back: the frame moves by two.
        for (int i = 0; i < 3; ++i) tap(GLFW_KEY_RIGHT);
        tap(GLFW_KEY_LEFT);
        drain(debugger);
        EXPECT_EQ(debugger.snapshot().frame, std::min(start + 2, last_frame));

        // The frame slider: culled in the background, the window live meanwhile.
        UiActions seek;
        seek.playback.seek_frame = std::min(kSeekFrame + int(k), last_frame);
        debugger.apply(seek);
        finishSeek(debugger);
        frames(debugger, 1);
        EXPECT_EQ(debugger.snapshot().frame, seek.playback.seek_frame);

        // The presets the family's panel offers (none for a family without a view).
        const FamilyViewEntry* view = familyViewOfAlgorithm(offered[k]);
        for (OverlayPreset preset : view ? view->make()->overlayPresets() : noPresets()) {
            UiActions overlays;
            overlays.overlay_preset = preset;
            debugger.apply(overlays);
            frames(debugger, 1);
        }
        if (dimensions3) {
            for (ViewMode mode :
                 {ViewMode::Fly, ViewMode::CullingCamera, ViewMode::Cameras, ViewMode::Overview}) {
                UiActions view;
                view.algorithm.view_mode = mode;
                debugger.apply(view);
                frames(debugger, 1);
                EXPECT_EQ(debugger.snapshot().view_mode, mode);
            }
        }

        // The next culler of the list beside this one, brought to the same frame.
        UiActions compare;
        compare.algorithm.compare_algo = int((k + 1) % offered.size());
        debugger.apply(compare);
        debugger.syncCompare(true);
        frames(debugger, 2);
        shown = debugger.snapshot();
        expectNoSceneErrors(shown);
        EXPECT_EQ(shown.compare_index, *compare.algorithm.compare_algo);
        ASSERT_NE(shown.panes, nullptr);
        EXPECT_EQ(shown.panes->size(), 2u);
        compare.algorithm.compare_algo = -1;
        debugger.apply(compare);
        frames(debugger, 1);
        EXPECT_EQ(debugger.snapshot().compare_index, -1);
    }

    // Space plays a few frames, Space pauses, Home goes back to the start.
    tap(GLFW_KEY_SPACE);
    drain(debugger);
    frames(debugger, 5);
    tap(GLFW_KEY_SPACE);
    tap(GLFW_KEY_HOME);
    drain(debugger);
    finishSeek(debugger);
    frames(debugger, 1);
    EXPECT_FALSE(debugger.playing());
    EXPECT_EQ(debugger.snapshot().frame, 0);

    // Another scene, opened as the scene panel opens it.
    UiActions open;
    open.scene.open = true;
    open.scene.path = test::sourcePath(tour.then_opens);
    debugger.apply(open);
    frames(debugger, 3);
    const FrameSnapshot shown = debugger.snapshot();
    expectNoSceneErrors(shown);
    EXPECT_EQ(*shown.scene_file, open.scene.path);
    EXPECT_EQ(shown.frame, 0);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, WindowTourTest,
    ::testing::Values(TourCase{"scenes/figure1-2d.json", "scenes/city-walk-3d.json"},
                      TourCase{"scenes/city-walk-3d.json", "scenes/figure1-2d.json"},
                      TourCase{"scenes/mesh-3d.json", "scenes/hidden-movers-2d.json"}),
    [](const ::testing::TestParamInfo<TourCase>& info) {
        std::string name = info.param.scene;
        name = name.substr(name.find('/') + 1);
        name = name.substr(0, name.find('.'));
        std::replace(name.begin(), name.end(), '-', '_');
        return name;
    });

}  // namespace
}  // namespace gridcull
