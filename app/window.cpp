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
#include "app/offscreen_window.h"
#include "app/png_file.h"
#include "app/window_frame.h"
#include "ui/layout.h"

namespace gridcull {

namespace {

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
           "through the culling camera, no panels), main-camera (the window, its view "
           "through the culling camera), cameras (3D: the orbit view and the culling "
           "camera's side by side, no panels) or main-cameras (the window with them); "
           "default main";
}

int runWindow(const Scene& scene, const ViewOptions& window_options) {
    ViewOptions options = window_options;
    options.compute_ahead = true;  // the window's timeline shows the whole run
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
    OffscreenWindow window;
    std::vector<uint8_t> rgba;
    return window.open(scene, options, error) && window.draw(rgba, error) &&
           writePngFile(out_png, window.width(), window.height(), rgba, error);
}

}  // namespace gridcull
