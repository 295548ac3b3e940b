// A flight recorded in the window and saved as the scene's camera path: R (a
// synthetic key tap) starts and stops recording in the fly view, the observer
// moves between frames, Save writes the keys into (a copy of) the scene file and
// reopens it, and the culling camera then stands, frame after frame, where the
// observer flew. Needs an X display (xvfb-run).
#include <filesystem>

#include <GLFW/glfw3.h>
#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "app/debugger.h"
#include "app/gl_context.h"
#include "app/imgui_runtime.h"
#include "app/input_queue.h"
#include "app/window_frame.h"
#include "culling/io/scene_loader.h"
#include "run_command.h"

namespace gridcull {
namespace {

namespace fs = std::filesystem;
constexpr int kWidth = 1280, kHeight = 720;

TEST(FlightWindow, AFlownPathIsSavedIntoTheSceneAndTheCullingCameraFliesIt) {
    GlWindow window;
    ImGuiRuntime imgui;
    InputQueue input;
    std::string error;
    ASSERT_TRUE(window.create(kWidth, kHeight, "gridcull test", false, error)) << error;
    ASSERT_TRUE(imgui.init(window.get(), error)) << error;
    InputQueue::install(window.get(), &input);

    const fs::path dir = fs::temp_directory_path() / "gridcull-flight-window-test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string file = (dir / "hidden-movers-3d.json").string();
    fs::copy_file(test::sourcePath("scenes/hidden-movers-3d.json"), file);
    SceneLoadResult loaded = loadSceneFile(file);
    ASSERT_TRUE(loaded.scene);

    ViewOptions options;
    options.algo = "vfc";
    Debugger debugger(options);
    ASSERT_TRUE(debugger.init(*loaded.scene, error)) << error;
    // Frames until every queued key event was delivered (one per key a frame).
    auto frame = [&] {
        do {
            drawWindowFrame(debugger, window.get(), input, kWidth, kHeight, kWidth, kHeight);
        } while (!input.empty());
    };
    frame();
    input.push(GLFW_KEY_R, true);
    input.push(GLFW_KEY_R, false);
    frame();
    EXPECT_EQ(debugger.viewMode(), ViewMode::Fly);
    ASSERT_TRUE(debugger.flight().recording());
    const double dt = debugger.session().scene().dt;
    for (int k = 0; k < 12; ++k) {
        debugger.viewCamera().fly({1.0, 0.0, 1.0}, 0.05, false);
        debugger.advancePlayback(dt);  // the clock the window's frames feed
    }
    input.push(GLFW_KEY_R, true);
    input.push(GLFW_KEY_R, false);
    frame();
    ASSERT_FALSE(debugger.flight().recording());
    const std::vector<CameraKey> keys = debugger.flight().keys();
    ASSERT_GE(keys.size(), 12u);

    UiActions save;
    save.algorithm.flight_save = true;
    debugger.apply(save);
    EXPECT_TRUE(debugger.snapshot().scene_errors->empty());
    EXPECT_TRUE(fs::exists(file + "~"));
    const DebuggerSession& session = debugger.session();
    EXPECT_EQ(session.scene().frames, int(keys.size()));
    for (int f : {0, 5, int(keys.size()) - 1}) {
        debugger.session().seek(f);
        const Camera& camera = session.cullingCamera();
        EXPECT_NEAR(glm::length(camera.position - keys[size_t(f)].position), 0.0, 1e-9) << f;
        EXPECT_NEAR(glm::length(camera.target - keys[size_t(f)].target), 0.0, 1e-9) << f;
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace gridcull
