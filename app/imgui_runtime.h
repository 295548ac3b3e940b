// Dear ImGui's context and backends for one GL context: the OpenGL 3 renderer
// always, the GLFW platform backend only for a real window (a shot sets the
// display size, time step and mouse itself, so its panels never depend on the
// machine's clock or pointer). The style is fixed here so shots and window match;
// --ui-scale scales the font (rasterized at that size, not stretched) and the style.
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
    // `ui_scale`: the font's size and the style's sizes over ImGui's defaults.
    bool init(GLFWwindow* window, std::string& error, double ui_scale = 1.0);
    // Rebuilds the font and the style at another scale (between frames).
    void setScale(double ui_scale);
    double scale() const { return scale_; }

private:
    void buildFontAndStyle(double ui_scale);

    double scale_ = 1.0;
    bool context_ = false;
    bool platform_ = false;
    bool renderer_ = false;
};

}  // namespace gridcull
