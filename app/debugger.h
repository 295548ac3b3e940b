// The debugger: a DebuggerSession (culling), the Renderer (scene view), the view
// camera, the panels' state and the selected family's view (its panel and
// overlay, from the ui registry), put together the same way for the window and
// for `shot`, so a shot is a picture of what the window shows.
//
// Per frame the caller: feeds input (window only), calls drawUi() between
// ImGui::NewFrame() and ImGui::Render(), drawScene(), renders ImGui, then
// apply()s the actions the panels returned. Needs a current GL context.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app/renderer.h"
#include "app/trade_explorer.h"
#include "app/view_camera.h"
#include "app/window.h"
#include "ui/debugger_session.h"
#include "ui/debugger_ui.h"
#include "ui/family_view.h"
#include "ui/flight_recorder.h"
#include "ui/layout.h"
#include "ui/lesson_player.h"
#include "ui/scene_panes.h"

namespace gridcull {

class Debugger {
public:
    explicit Debugger(const ViewOptions& options) : options_(options), session_(options.knobs) {}

    // Copies `scene`, sets up GL objects and runs culling up to options.frame.
    // Fails with `error` when the algorithm does not run on the scene's
    // dimension or a view flag names something the scene lacks.
    bool init(const Scene& scene, std::string& error);

    DebuggerSession& session() { return session_; }
    ViewCamera& viewCamera() { return view_camera_; }
    ViewMode viewMode() const { return view_mode_; }
    bool playing() const { return playing_; }
    // The algorithms offered for the current scene (those that run on its dimension).
    const std::vector<std::string>& offeredAlgorithms() const { return algo_names_; }
    // What the window last did on its own (say, switched the culler), or "".
    const std::string& note() const { return note_; }
    // The object the view outlines (index, -1: none): the selected family's
    // focus (a picked object, say), else the one under the mouse.
    int outlinedObject() const;

    // The panels' scale; the window rebuilds its font when it changes.
    double uiScale() const { return options_.ui_scale; }
    void setUiScale(double scale);

    // Shots hide wall-clock times: they differ from run to run.
    void setShowTimings(bool show) { show_timings_ = show; }

    // Looks up the object under (x, y) in window pixels, in the pane of the
    // scene view it is over, and tells that pane's family view where the
    // pointer is; `clicked` when the left button was clicked. Clears the hover
    // when the point is outside every pane or `inside` is false.
    void updatePointer(double x, double y, bool inside, bool clicked, const WindowLayout& layout);
    // Advances playback by `seconds` of wall time: one scene frame per scene dt,
    // at most a few frames per call so slow culling cannot snowball.
    void advancePlayback(double seconds);
    void setViewMode(ViewMode mode);
    void togglePlay();
    void stepForward();
    void stepBack();
    void toggleFreeze();
    // Stops a seek running in the background (the view stays where it was).
    void cancelSeek() { session_.cancelSeek(); }
    // Opens a scene file as the scene panel does; on failure the panel shows why.
    void openSceneFile(const std::string& path);
    // Selects the culler as the panel does; on failure the panel shows why.
    void selectAlgorithm(const std::string& name);

    // A second culler on the same frame, shown in the right half of the view
    // (app/debugger_panes.cpp); "" shows none. False and `error` when it does
    // not run on the scene.
    bool setCompare(const std::string& algo, std::string& error);
    // The compared culler's session (null: none).
    const DebuggerSession* compareSession() const { return compare_.get(); }
    // Objects (indices) in one culler's PVS and not the other's, this frame;
    // empty while the compared culler is not on the same frame yet.
    const std::vector<int>& differingObjects() const { return differing_; }
    // Brings the compared culler to the shown frame, camera and knobs; with
    // `wait`, in the foreground (shots, lessons, tests), else a long seek runs
    // in the background and this is polled each frame.
    void syncCompare(bool wait);
    // Where the scene view's panes are in `layout`.
    ScenePanes panes(const WindowLayout& layout) const;

    // A camera path flown in the window (app/debugger_flight.cpp): recording
    // starts or stops (recorded while flying, one key per scene time step);
    // saving writes it into the scene file as the culling camera's path and
    // reopens the scene, so the culling camera replays it.
    void toggleFlightRecording();
    bool saveFlight();
    void discardFlight() { flight_.discard(); }
    const FlightRecorder& flight() const { return flight_; }

    // Sets the selected family's overlay toggles to one of its presets.
    void applyOverlayPreset(OverlayPreset preset);

    // Plays `lesson` (checked by app/lesson_file.h) from its first step
    // (app/debugger_lesson.cpp).
    void startLesson(Lesson lesson);
    const LessonPlayer& lesson() const { return lesson_; }
    // Shows lesson step `index` (clamped); `finished`: its animation at its end.
    void goToLessonStep(int index, bool finished = false);
    void setLessonAutoPlay(bool on);

    // The panels; returns the user's actions (apply them after the frame).
    UiActions drawUi(const WindowLayout& layout);
    void apply(const UiActions& actions);

    // Draws the scene view into layout.scene_view of a framebuffer `framebuffer`
    // pixels high (`scale` framebuffer pixels per layout pixel); records the time.
    void drawScene(const WindowLayout& layout, int framebuffer_height, double scale = 1.0);
    double lastDrawMs() const { return last_draw_ms_; }

    // Takes in what the trade curve's background sweep measured (drawUi does, each frame).
    void updateTrade() { trade_.poll(session_.knobs()); }

    // What the panels are shown this frame.
    FrameSnapshot snapshot() const;

private:
    // Copies the session's checkpoint figures for the panels.
    void noteCheckpoints();
    // Re-makes the cullers with knobs set and unset (checked as the command
    // line checks them) and records what the re-run cost for the knobs panel.
    void applyKnobs(const std::vector<std::pair<std::string, double>>& set,
                    const std::vector<std::string>& unset);
    FamilyViewContext familyContext() const;
    // The context of one pane: its session's frame and states, its view mode.
    FamilyViewContext paneContext(const ScenePane& pane) const;
    const DebuggerSession& sessionOf(const ScenePane& pane) const {
        return pane.compared && compare_ ? *compare_ : session_;
    }
    // The family view that draws a pane's overlay (the compared culler's
    // family's on the B side), null for none.
    FamilyView* viewOf(const ScenePane& pane);
    void drawPane(const ScenePane& pane, int framebuffer_height, double scale);
    // The panes' captions for the snapshot.
    void captionPanes(const WindowLayout& layout);
    // Applies the lesson step shown and the value its animation reached.
    void showLessonStep();
    void applyLessonFlags();
    // Points family_view_ at the selected algorithm's family's view, made the
    // first time that family is selected and kept after, so its state (toggles,
    // picks) survives switching away and back.
    void syncFamilyView();
    // The family view of algorithm `algo`, made the first time (null: none).
    FamilyView* familyViewOf(const std::string& algo);

    ViewOptions options_;
    DebuggerSession session_;
    Renderer renderer_;
    ViewCamera view_camera_;
    UiState ui_state_;
    std::vector<std::string> algo_names_;
    std::vector<std::string> scene_errors_;
    std::string note_;
    ViewMode view_mode_ = ViewMode::Overview;
    bool playing_ = false;
    bool show_timings_ = true;
    double play_clock_ = 0.0;
    double last_draw_ms_ = 0.0;
    // The scene picker's list: the files opened in this window, most recent
    // first, then the scene files beside the current one and in ./scenes.
    void refreshSceneChoices();
    std::vector<std::string> recent_scenes_;
    std::vector<std::string> scene_choices_;
    Checkpointing checkpointing_;
    KnobApplyCost knob_cost_;
    TradeExplorer trade_;  // the trade curve's sweep, in the background
    // Applies point `index` of the trade curve: the family's knobs as its setting has them.
    void applyTradeSetting(int index);
    FrameHistory ahead_;  // the run computed ahead, copied each frame for the timeline
    int ahead_frames_ = 0;
    int hovered_index_ = -1;
    bool hovered_in_compare_ = false;  // the pointer is over the compared culler's pane
    double hovered_distance_ = 0.0;
    // One view per family shown so far, by family id, and the selected
    // algorithm's (null for a family without one).
    std::map<std::string, std::unique_ptr<FamilyView>> family_views_;
    FamilyView* family_view_ = nullptr;
    // The compared culler (null: none) and where the two PVS differ.
    std::unique_ptr<DebuggerSession> compare_;
    std::vector<int> differing_;
    std::vector<PaneCaption> pane_captions_;
    LessonPlayer lesson_;
    FlightRecorder flight_;
    // Keeps a key of the flight when recording and flying.
    void sampleFlight(double seconds);
    // The scene the command line's view flags were checked against: a view made
    // later applies them only while that scene is open.
    int flags_scene_generation_ = -1;
};

}  // namespace gridcull
