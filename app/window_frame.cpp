#include "app/window_frame.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/debugger.h"
#include "app/gl_api.h"
#include "app/input_queue.h"
#include "app/window_input.h"
#include "ui/layout.h"

namespace gridcull {

void drawWindowFrame(Debugger& debugger, GLFWwindow* window, InputQueue& input, int width,
                     int height, int fb_width, int fb_height) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    input.apply(ImGui::GetIO());
    ImGui::NewFrame();
    const WindowLayout layout = computeLayout(width, height, true, debugger.uiScale());
    handleWindowInput(debugger, window, layout);
    debugger.advancePlayback(ImGui::GetIO().DeltaTime);
    const UiActions actions = debugger.drawUi(layout);
    ImGui::Render();

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fb_width, fb_height);
    glClearColor(kWindowClear[0], kWindowClear[1], kWindowClear[2], kWindowClear[3]);
    glClear(GL_COLOR_BUFFER_BIT);
    debugger.drawScene(layout, fb_height, double(fb_width) / width);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    debugger.apply(actions);
}

}  // namespace gridcull
