#include "app/trade_plot_png.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <cfloat>
#include <vector>

#include "app/gl_api.h"
#include "app/gl_context.h"
#include "app/png_file.h"
#include "app/window_frame.h"

namespace gridcull {

namespace {

// ImGui sizes a new window over its first frames; the second already lays out
// as every later one.
constexpr int kSettleFrames = 3;

}  // namespace

bool TradePlotPng::init(int width, int height, std::string& error) {
    if (!ensureHiddenGlContext(error)) {
        error = "the plots need an OpenGL context: " + error;
        return false;
    }
    width_ = width;
    height_ = height;
    imgui_ = std::make_unique<ImGuiRuntime>();
    return target_.create(width, height, error) && imgui_->init(nullptr, error);
}

bool TradePlotPng::write(const TradePlotInput& input, const std::string& path,
                         std::string& error) {
    ImGuiIO& io = ImGui::GetIO();
    for (int i = 0; i < kSettleFrames; ++i) {
        io.DisplaySize = ImVec2(float(width_), float(height_));
        io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(io.DisplaySize);
        ImGui::Begin("trade", nullptr,
                     ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
        const ImVec2 room = ImGui::GetContentRegionAvail();
        drawTradePlot(input, room.x, room.y - ImGui::GetTextLineHeightWithSpacing());
        ImGui::End();
        ImGui::Render();
    }
    target_.bind();
    glViewport(0, 0, width_, height_);
    glClearColor(kWindowClear[0], kWindowClear[1], kWindowClear[2], kWindowClear[3]);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glFinish();
    std::vector<uint8_t> rgba;
    target_.readPixelsTopDown(rgba);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    return writePngFile(path, width_, height_, rgba, error);
}

}  // namespace gridcull
