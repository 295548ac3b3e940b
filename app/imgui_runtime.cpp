#include "app/imgui_runtime.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

namespace gridcull {

ImGuiRuntime::~ImGuiRuntime() {
    if (renderer_) ImGui_ImplOpenGL3_Shutdown();
    if (platform_) ImGui_ImplGlfw_Shutdown();
    if (context_) ImGui::DestroyContext();
}

bool ImGuiRuntime::init(GLFWwindow* window, std::string& error) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    context_ = true;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 0.0f;
    style.FrameRounding = 2.0f;
    style.WindowBorderSize = 1.0f;
    style.ItemSpacing = ImVec2(6.0f, 4.0f);
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
