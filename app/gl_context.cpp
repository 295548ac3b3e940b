#include "app/gl_context.h"

#include <GLFW/glfw3.h>

namespace gridcull {

namespace {

// GLFW reports errors through a callback; the last one becomes our message.
std::string& lastGlfwError() {
    static std::string message;
    return message;
}

void onGlfwError(int code, const char* description) {
    lastGlfwError() = std::string(description ? description : "unknown error") + " (GLFW error " +
                      std::to_string(code) + ")";
}

}  // namespace

GlWindow::~GlWindow() {
    if (window_) glfwDestroyWindow(window_);
    if (initialized_) glfwTerminate();
}

bool GlWindow::create(int width, int height, const char* title, bool visible,
                      std::string& error) {
    glfwSetErrorCallback(onGlfwError);
    lastGlfwError().clear();
    if (!glfwInit()) {
        error = "cannot start GLFW: " + lastGlfwError() +
                "; a window needs an X display (on a headless machine use xvfb-run)";
        return false;
    }
    initialized_ = true;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    // Not forward-compatible: keeps wide lines, which outline false culls.
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SAMPLES, 0);
    window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
    if (!window_) {
        error = "cannot open an OpenGL 3.3 core window: " + lastGlfwError();
        return false;
    }
    glfwMakeContextCurrent(window_);
    return true;
}

bool ensureHiddenGlContext(std::string& error) {
    static GlWindow* window = nullptr;
    if (window) {
        glfwMakeContextCurrent(window->get());
        return true;
    }
    auto* made = new GlWindow;  // lives until exit: GL objects made in it need it
    if (!made->create(64, 64, "gridcull", false, error)) {
        delete made;
        return false;
    }
    window = made;
    return true;
}

}  // namespace gridcull
