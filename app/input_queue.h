// Key presses and releases applied to ImGui one transition per key per frame,
// so that a tap shorter than a frame is never lost: a press and a release that
// arrive within one (slow) frame reach ImGui over two frames, as ImGui 1.87's
// input queue delivers them. Debian 12 ships ImGui 1.86, whose GLFW backend
// writes io.KeysDown straight from its callback, so there the release
// overwrites the press before ImGui sees it. (Mouse buttons need no queue: the
// 1.86 backend already keeps a press that was released within the frame.)
//
// The window feeds the queue from GLFW's key callback; tests drive the window
// by pushing synthetic events into it.
#pragma once
#include <vector>

struct GLFWwindow;
struct ImGuiIO;

namespace gridcull {

class InputQueue {
public:
    // A press (down) or release of GLFW key code `key`.
    void push(int key, bool down);
    // Before ImGui::NewFrame(): applies the waiting events in order to
    // io.KeysDown and the modifier flags, up to the first one whose key already
    // changed in this call; that one and all after it wait for the next frame,
    // so events never overtake each other.
    void apply(ImGuiIO& io);
    bool empty() const { return events_.empty(); }

    // Routes `window`'s key events into `queue` (call after ImGui's GLFW backend
    // is set up, whose key callback this replaces and whose other callbacks,
    // text input among them, stay). The queue must outlive the window's use.
    static void install(GLFWwindow* window, InputQueue* queue);

private:
    struct Event {
        int key;
        bool down;
    };
    std::vector<Event> events_;  // oldest first
    std::vector<int> applied_;   // keys changed in the current apply()
};

}  // namespace gridcull
