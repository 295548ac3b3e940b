#include "app/imgui_runtime.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "ui/ui_units.h"

namespace gridcull {

ImGuiRuntime::~ImGuiRuntime() {
    if (renderer_) ImGui_ImplOpenGL3_Shutdown();
    if (platform_) ImGui_ImplGlfw_Shutdown();
    if (context_) ImGui::DestroyContext();
}

void ImGuiRuntime::buildFontAndStyle(double ui_scale) {
    scale_ = ui_scale;
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    ImFontConfig font;
    font.SizePixels = float(kDesignFontPixels * ui_scale);
    io.Fonts->AddFontDefault(&font);
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.WindowRounding = 0.0f;
    style.FrameRounding = 2.0f;
    style.WindowBorderSize = 1.0f;
    style.ItemSpacing = ImVec2(6.0f, 4.0f);
    // Popups and tooltips opaque: the scene behind them must not show through
    // their text.
    style.Colors[ImGuiCol_PopupBg].w = 1.0f;
    style.ScaleAllSizes(float(ui_scale));
    ImGui::GetStyle() = style;
}

void ImGuiRuntime::setScale(double ui_scale) {
    buildFontAndStyle(ui_scale);
    if (renderer_) {
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
    }
}

bool ImGuiRuntime::init(GLFWwindow* window, std::string& error, double ui_scale) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    context_ = true;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    buildFontAndStyle(ui_scale);
    if (window) {
        if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) {
            error = "cannot start ImGui's GLFW backend";
            return false;
        }
        platform_ = true;
    }
    if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
        error = "cannot start ImGui's OpenGL 3 backend";
        return false;
    }
    renderer_ = true;
    return true;
}

}  // namespace gridcull
