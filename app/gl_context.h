// A GLFW window with an OpenGL 3.3 core context, for the debugger window and for
// shots (hidden). GLFW needs an X display; without one, creation fails with a
// message that says so instead of crashing.
#pragma once
#include <string>

struct GLFWwindow;

namespace gridcull {

// Owns glfwInit / glfwTerminate and one window; the context is made current.
class GlWindow {
public:
    GlWindow() = default;
    GlWindow(const GlWindow&) = delete;
    GlWindow& operator=(const GlWindow&) = delete;
    ~GlWindow();

    // visible == false: a hidden window, used only for its context.
    bool create(int width, int height, const char* title, bool visible, std::string& error);
    GLFWwindow* get() const { return window_; }

private:
    GLFWwindow* window_ = nullptr;
    bool initialized_ = false;
};

// One hidden window's context for the whole process (the -gl cullers and
// bench --draw share it), made current; created on the first call, kept until
// exit, since GL objects made in it must outlive their owners. False with
// `error` when no context can be made (no X display: run under xvfb-run).
bool ensureHiddenGlContext(std::string& error);

}  // namespace gridcull
