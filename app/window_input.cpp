#include "app/window_input.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/debugger.h"

namespace gridcull {

namespace {

constexpr double kUiScaleStep = 1.2;

}  // namespace

void handleWindowInput(Debugger& debugger, GLFWwindow* window, const WindowLayout& layout) {
    const ImGuiIO& io = ImGui::GetIO();
    const WindowRect& view = layout.scene_view;
    const bool mouse_free = !io.WantCaptureMouse;
    const bool over_view = mouse_free && view.contains(io.MousePos.x, io.MousePos.y);
    const bool dimensions3 = debugger.session().scene().dimensions == 3;

    const bool clicked = over_view && ImGui::IsMouseClicked(ImGuiMouseButton_Left);
    debugger.updatePointer(io.MousePos.x, io.MousePos.y, over_view, clicked, layout);

    ViewCamera& camera = debugger.viewCamera();
    if (mouse_free && io.MouseDown[ImGuiMouseButton_Right]) {
        const double dx = io.MouseDelta.x, dy = io.MouseDelta.y;
        if (!dimensions3)
            camera.pan2d(dx, dy, view.height);
        else if (debugger.viewMode() == ViewMode::Fly)
            camera.look(dx, dy);
        else if (debugger.viewMode() == ViewMode::Overview)
            camera.orbit(dx, dy);
    }
    if (over_view && io.MouseWheel != 0.0f) camera.zoom(io.MouseWheel);

    if (io.WantCaptureKeyboard) return;
    if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) debugger.togglePlay();
    if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT)) debugger.stepForward();
    if (ImGui::IsKeyPressed(GLFW_KEY_LEFT)) debugger.stepBack();
    if (ImGui::IsKeyPressed(GLFW_KEY_HOME, false)) {
        UiActions actions;
        actions.playback.seek_frame = 0;
        debugger.apply(actions);
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) debugger.toggleFreeze();
    if (dimensions3 && ImGui::IsKeyPressed(GLFW_KEY_R, false)) debugger.toggleFlightRecording();
    // A lesson's steps: a presentation clicker sends PageDown / PageUp.
    if (debugger.lesson().active()) {
        const int step = debugger.lesson().stepIndex();
        if (ImGui::IsKeyPressed(GLFW_KEY_PAGE_DOWN) || ImGui::IsKeyPressed(GLFW_KEY_N))
            debugger.goToLessonStep(step + 1);
        if (ImGui::IsKeyPressed(GLFW_KEY_PAGE_UP) || ImGui::IsKeyPressed(GLFW_KEY_P))
            debugger.goToLessonStep(step - 1);
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) debugger.cancelSeek();
    // Ctrl+plus / Ctrl+minus (main keyboard or keypad): a fifth larger or smaller.
    if (io.KeyCtrl) {
        if (ImGui::IsKeyPressed(GLFW_KEY_EQUAL) || ImGui::IsKeyPressed(GLFW_KEY_KP_ADD))
            debugger.setUiScale(debugger.uiScale() * kUiScaleStep);
        if (ImGui::IsKeyPressed(GLFW_KEY_MINUS) || ImGui::IsKeyPressed(GLFW_KEY_KP_SUBTRACT))
            debugger.setUiScale(debugger.uiScale() / kUiScaleStep);
    }
    if (dimensions3 && debugger.viewMode() == ViewMode::Fly) {
        auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0 : 0.0; };
        const glm::dvec3 move(down(GLFW_KEY_D) - down(GLFW_KEY_A),
                              down(GLFW_KEY_E) - down(GLFW_KEY_Q),
                              down(GLFW_KEY_W) - down(GLFW_KEY_S));
        const bool fast = down(GLFW_KEY_LEFT_SHIFT) > 0.0 || down(GLFW_KEY_RIGHT_SHIFT) > 0.0;
        if (move != glm::dvec3(0.0)) camera.fly(move, io.DeltaTime, fast);
    }
}

}  // namespace gridcull
