#include "app/window.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <iostream>
#include <vector>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "app/debugger.h"
#include "app/gl_api.h"
#include "app/gl_context.h"
#include "app/imgui_runtime.h"
#include "app/input_queue.h"
#include "app/offscreen_target.h"
#include "app/png_file.h"
#include "app/window_frame.h"
#include "ui/layout.h"

namespace gridcull {

namespace {

// ImGui frames a shot builds before the one it draws: auto-sized windows and
// tables take a frame or two to reach their final layout.
constexpr int kShotSettleFrames = 3;
constexpr float kShotDeltaTime = 1.0f / 60.0f;

// What a `--view` name draws: panels or not, and from which camera.
bool parseView(const std::string& view, bool& panels, ViewMode& mode) {
    mode = ViewMode::Overview;
    panels = view == "main" || view == "main-camera";
    if (view == "main" || view == "scene") return true;
    if (view == "camera" || view == "main-camera") {
        mode = ViewMode::CullingCamera;
        return true;
    }
    return false;
}

void printDrawSummary(std::vector<double>& draw_ms) {
    if (draw_ms.empty()) return;
    std::sort(draw_ms.begin(), draw_ms.end());
    const double median = draw_ms[draw_ms.size() / 2];
    std::fprintf(stderr, "gridcull: %zu frames drawn, draw ms median %.3f, min %.3f, max %.3f\n",
                 draw_ms.size(), median, draw_ms.front(), draw_ms.back());
}

}  // namespace

const char* viewNamesHelp() {
    return "main (the window: view and panels), scene (the view alone), camera (3D: "
           "through the culling camera, no panels) or main-camera (the window, its view "
           "through the culling camera); default main";
}

int runWindow(const Scene& scene, const ViewOptions& options) {
    std::string error;
    GlWindow window;
    const std::string title = "gridcull: " + scene.name;
    if (!window.create(options.width, options.height, title.c_str(), true, error)) {
        std::cerr << "gridcull: " << error << "\n";
        return 1;
    }
    glfwSwapInterval(1);
    ImGuiRuntime imgui;
    Debugger debugger(options);
    if (!imgui.init(window.get(), error, options.ui_scale) || !debugger.init(scene, error)) {
        std::cerr << "gridcull: " << error << "\n";
        return 1;
    }
    InputQueue input;
    InputQueue::install(window.get(), &input);
    std::vector<double> draw_ms;
    draw_ms.reserve(size_t(std::max(options.exit_after_frames, 0)));
    int frames = 0;
    while (!glfwWindowShouldClose(window.get())) {
        glfwPollEvents();
        int width = 0, height = 0, fb_width = 0, fb_height = 0;
        glfwGetWindowSize(window.get(), &width, &height);
        glfwGetFramebufferSize(window.get(), &fb_width, &fb_height);
        if (width <= 0 || height <= 0 || fb_width <= 0 || fb_height <= 0) {
            glfwWaitEvents();  // minimised
            continue;
        }
        if (debugger.uiScale() != imgui.scale()) imgui.setScale(debugger.uiScale());
        drawWindowFrame(debugger, window.get(), input, width, height, fb_width, fb_height);
        glfwSwapBuffers(window.get());

        if (options.exit_after_frames > 0) {
            draw_ms.push_back(debugger.lastDrawMs());
            if (++frames >= options.exit_after_frames) glfwSetWindowShouldClose(window.get(), 1);
        }
    }
    // Scripted runs (--exit-after) report how long drawing took.
    printDrawSummary(draw_ms);
    return 0;
}

bool renderShot(const Scene& scene, const ViewOptions& options, const std::string& out_png,
                std::string& error) {
    bool panels = true;
    ViewMode mode = ViewMode::Overview;
    if (!parseView(options.view, panels, mode)) {
        error = "unknown view '" + options.view + "': use " + viewNamesHelp();
        return false;
    }
    if (options.frame < 0 || options.frame >= scene.frames) {
        error = "frame " + std::to_string(options.frame) + " is outside the scene's frames 0.." +
                std::to_string(scene.frames - 1);
        return false;
    }
    const int width = options.width, height = options.height;
    GlWindow window;
    // The hidden window only provides the context: the image is the framebuffer
    // object, so its size is free of the X screen's.
    if (!window.create(64, 64, "gridcull shot", false, error)) return false;
    OffscreenTarget target;
    if (!target.create(width, height, error)) return false;
    ImGuiRuntime imgui;
    if (panels && !imgui.init(nullptr, error, options.ui_scale)) return false;
    ViewOptions still = options;
    still.play = false;  // a shot is one frame: the panels show it paused
    Debugger debugger(still);
    debugger.setShowTimings(false);
    if (!debugger.init(scene, error)) return false;
    debugger.setViewMode(mode);

    const WindowLayout layout = computeLayout(width, height, panels, options.ui_scale);
    if (panels) {
        // No clock, no pointer: the same frame always lays out the same.
        ImGuiIO& io = ImGui::GetIO();
        for (int i = 0; i < kShotSettleFrames; ++i) {
            io.DisplaySize = ImVec2(float(width), float(height));
            io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
            io.DeltaTime = kShotDeltaTime;
            io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
            ImGui_ImplOpenGL3_NewFrame();
            ImGui::NewFrame();
            debugger.drawUi(layout);
            ImGui::Render();
        }
    }
    target.bind();
    glViewport(0, 0, width, height);
    glClearColor(kWindowClear[0], kWindowClear[1], kWindowClear[2], kWindowClear[3]);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    debugger.drawScene(layout, height);
    if (panels) ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glFinish();
    const GLenum gl_error = glGetError();
    if (gl_error != GL_NO_ERROR) {
        error = "OpenGL error " + std::to_string(gl_error) + " while drawing the shot";
        return false;
    }
    std::vector<uint8_t> rgba;
    target.readPixelsTopDown(rgba);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;  // an opaque picture
    return writePngFile(out_png, width, height, rgba, error);
}

}  // namespace gridcull
