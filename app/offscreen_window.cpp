#include "app/offscreen_window.h"

#include <cfloat>

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "app/gl_api.h"
#include "app/window_frame.h"

namespace gridcull {

namespace {

// ImGui frames a shot builds before the one it draws: auto-sized windows and
// tables take a frame or two to reach their final layout.
constexpr int kShotSettleFrames = 3;
constexpr float kShotDeltaTime = 1.0f / 60.0f;

// What a `--view` name draws: panels or not, and from which camera.
bool parseView(const std::string& view, bool& panels, ViewMode& mode) {
    mode = ViewMode::Overview;
    panels = view == "main" || view == "main-camera" || view == "main-cameras";
    if (view == "main" || view == "scene") return true;
    if (view == "camera" || view == "main-camera") {
        mode = ViewMode::CullingCamera;
        return true;
    }
    if (view == "cameras" || view == "main-cameras") {
        mode = ViewMode::Cameras;
        return true;
    }
    return false;
}

}  // namespace

bool OffscreenWindow::open(const Scene& scene, const ViewOptions& options, std::string& error) {
    ViewMode mode = ViewMode::Overview;
    if (!parseView(options.view, panels_, mode)) {
        error = "unknown view '" + options.view + "': use " + viewNamesHelp();
        return false;
    }
    if (options.frame < 0 || options.frame >= scene.frames) {
        error = "frame " + std::to_string(options.frame) + " is outside the scene's frames 0.." +
                std::to_string(scene.frames - 1);
        return false;
    }
    width_ = options.width;
    height_ = options.height;
    // The hidden window only provides the context: the image is the framebuffer
    // object, so its size is free of the X screen's.
    if (!window_.create(64, 64, "gridcull shot", false, error)) return false;
    if (!target_.create(width_, height_, error)) return false;
    if (panels_ && !imgui_.init(nullptr, error, options.ui_scale)) return false;
    ViewOptions still = options;
    still.play = false;  // the panels show each frame paused
    debugger_ = std::make_unique<Debugger>(still);
    debugger_->setShowTimings(false);
    if (!debugger_->init(scene, error)) return false;
    // A lesson's step chooses its own view.
    if (!options.lesson) debugger_->setViewMode(mode);
    layout_ = computeLayout(width_, height_, panels_, options.ui_scale);
    return true;
}

bool OffscreenWindow::draw(std::vector<uint8_t>& rgba, std::string& error) {
    debugger_->syncCompare(true);  // a picture of both cullers on the same frame
    if (panels_) {
        // No clock, no pointer: the same frame always lays out the same.
        ImGuiIO& io = ImGui::GetIO();
        for (int i = 0; i < kShotSettleFrames; ++i) {
            io.DisplaySize = ImVec2(float(width_), float(height_));
            io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
            io.DeltaTime = kShotDeltaTime;
            io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
            ImGui_ImplOpenGL3_NewFrame();
            ImGui::NewFrame();
            debugger_->drawUi(layout_);
            ImGui::Render();
        }
    }
    target_.bind();
    glViewport(0, 0, width_, height_);
    glClearColor(kWindowClear[0], kWindowClear[1], kWindowClear[2], kWindowClear[3]);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    debugger_->drawScene(layout_, height_);
    if (panels_) ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glFinish();
    const GLenum gl_error = glGetError();
    if (gl_error != GL_NO_ERROR) {
        error = "OpenGL error " + std::to_string(gl_error) + " while drawing the window";
        return false;
    }
    target_.readPixelsTopDown(rgba);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;  // an opaque picture
    return true;
}

}  // namespace gridcull
