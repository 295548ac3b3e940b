// Dear ImGui's context and backends for one GL context: the OpenGL 3 renderer
// always, the GLFW platform backend only for a real window (a shot sets the
// display size, time step and mouse itself, so its panels never depend on the
// machine's clock or pointer). The style is fixed here so shots and window match.
#pragma once
#include <string>

struct GLFWwindow;

namespace gridcull {

class ImGuiRuntime {
public:
    ImGuiRuntime() = default;
    ImGuiRuntime(const ImGuiRuntime&) = delete;
    ImGuiRuntime& operator=(const ImGuiRuntime&) = delete;
    ~ImGuiRuntime();

    // window == nullptr: no platform backend (shots). Never reads or writes an
    // imgui.ini: a saved layout would make shots depend on earlier runs.
    bool init(GLFWwindow* window, std::string& error);

private:
    bool context_ = false;
    bool platform_ = false;
    bool renderer_ = false;
};

}  // namespace gridcull
