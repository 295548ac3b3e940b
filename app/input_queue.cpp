#include "app/input_queue.h"

#include <algorithm>

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace gridcull {

void InputQueue::push(int key, bool down) {
    events_.push_back({key, down});
}

void InputQueue::apply(ImGuiIO& io) {
    applied_.clear();
    // In order, up to the first event of a key changed already this frame: it
    // and every later event wait, so that no event overtakes an earlier one
    // (a Ctrl release never comes before the key pressed with it).
    size_t next = 0;
    for (; next < events_.size(); ++next) {
        const Event& event = events_[next];
        if (event.key < 0 || event.key >= int(IM_ARRAYSIZE(io.KeysDown)))
            continue;  // a key ImGui has no slot for
        if (std::find(applied_.begin(), applied_.end(), event.key) != applied_.end()) break;
        io.KeysDown[event.key] = event.down;
        applied_.push_back(event.key);
    }
    events_.erase(events_.begin(), events_.begin() + std::ptrdiff_t(next));
    const bool* down = io.KeysDown;
    io.KeyCtrl = down[GLFW_KEY_LEFT_CONTROL] || down[GLFW_KEY_RIGHT_CONTROL];
    io.KeyShift = down[GLFW_KEY_LEFT_SHIFT] || down[GLFW_KEY_RIGHT_SHIFT];
    io.KeyAlt = down[GLFW_KEY_LEFT_ALT] || down[GLFW_KEY_RIGHT_ALT];
    io.KeySuper = down[GLFW_KEY_LEFT_SUPER] || down[GLFW_KEY_RIGHT_SUPER];
}

void InputQueue::install(GLFWwindow* window, InputQueue* queue) {
    glfwSetWindowUserPointer(window, queue);
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
        if (action == GLFW_REPEAT) return;  // ImGui repeats held keys itself
        static_cast<InputQueue*>(glfwGetWindowUserPointer(w))->push(key, action == GLFW_PRESS);
    });
}

}  // namespace gridcull
