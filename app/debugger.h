// The debugger: a DebuggerSession (culling), the Renderer (scene view), the view
// camera and the panels' state, put together the same way for the window and
// for `shot`, so a shot is a picture of what the window shows.
//
// Per frame the caller: feeds input (window only), calls drawUi() between
// ImGui::NewFrame() and ImGui::Render(), drawScene(), renders ImGui, then
// apply()s the actions the panels returned. Needs a current GL context.
#pragma once
#include <string>
#include <vector>

#include "app/debugger_session.h"
#include "app/renderer.h"
#include "app/view_camera.h"
#include "app/window.h"
#include "ui/debugger_ui.h"
#include "ui/layout.h"

namespace gridcull {

class Debugger {
public:
    explicit Debugger(const ViewOptions& options) : options_(options), session_(options.culler) {
        rgvc_view_.layer = options.rgvc_layer;
        rgvc_view_.occluder = options.rgvc_occluder;
    }

    // Copies `scene`, sets up GL objects and runs culling up to options.frame.
    bool init(const Scene& scene, std::string& error);

    DebuggerSession& session() { return session_; }
    ViewCamera& viewCamera() { return view_camera_; }
    ViewMode viewMode() const { return view_mode_; }
    bool playing() const { return playing_; }

    // Shots hide wall-clock times: they differ from run to run.
    void setShowTimings(bool show) { show_timings_ = show; }

    // Looks up the object under (x, y) in window pixels, or clears the hover when
    // the point is outside `view` or `inside` is false.
    void updateHover(double x, double y, bool inside, const WindowRect& view);
    // Advances playback by `seconds` of wall time: one scene frame per scene dt,
    // at most a few frames per call so slow culling cannot snowball.
    void advancePlayback(double seconds);
    void setViewMode(ViewMode mode);
    void togglePlay();
    void stepForward();
    void stepBack();
    void toggleFreeze();
    // rgvc, 2D: picks the extended occluder at the voxel under the mouse (none
    // when no occluder starts at or covers it).
    void pickRgvcOccluder();
    // Lazy grid, 3D: keeps the object under the mouse (none: clears) as the one
    // the lazy overlay and panel detail while the mouse is elsewhere.
    void pickLazyObject();

    // The panels; returns the user's actions (apply them after the frame).
    UiActions drawUi(const WindowLayout& layout);
    void apply(const UiActions& actions);

    // Draws the scene view into layout.scene_view of a framebuffer `framebuffer`
    // pixels high (`scale` framebuffer pixels per layout pixel); records the time.
    void drawScene(const WindowLayout& layout, int framebuffer_height, double scale = 1.0);
    double lastDrawMs() const { return last_draw_ms_; }

private:
    FrameSnapshot snapshot() const;
    void openSceneFile(const std::string& path);
    // The object (index) the lazy grid's overlay and panel detail: the one under
    // the mouse, else the picked one (a click, or options.lazy_object).
    int lazyObject() const { return hovered_index_ >= 0 ? hovered_index_ : lazy_pinned_index_; }
    bool throughCullingCamera() const;

    ViewOptions options_;
    DebuggerSession session_;
    Renderer renderer_;
    ViewCamera view_camera_;
    UiState ui_state_;
    std::vector<std::string> algo_names_;
    std::vector<std::string> scene_errors_;
    ViewMode view_mode_ = ViewMode::Overview;
    bool playing_ = false;
    bool show_timings_ = true;
    double play_clock_ = 0.0;
    double last_draw_ms_ = 0.0;
    int hovered_index_ = -1;
    double hovered_distance_ = 0.0;
    // rgvc (2D): what the overlay shows, the voxel under the mouse and its
    // description (refreshed before the panels are drawn; its lists are reused).
    RgvcViewState rgvc_view_;
    bool voxel_hovered_ = false;
    glm::ivec2 hovered_voxel_{0};
    RgvcVoxelInfo rgvc_voxel_;
    // Lazy grid (3D): what the overlay shows, and the picked object's index.
    LazyGridViewState lazy_view_;
    int lazy_pinned_index_ = -1;
};

}  // namespace gridcull
