#include "app/debugger.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/hover_pick.h"
#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"
#include "culling/scene/ray_pick.h"
#include "ui/registry/family_views.h"

namespace gridcull {

namespace {

// Frames played per call at most; beyond that playback runs slower than real time.
constexpr int kMaxFramesPerAdvance = 4;

int indexOfName(const std::vector<std::string>& names, const std::string& name) {
    const auto found = std::find(names.begin(), names.end(), name);
    return found == names.end() ? -1 : int(found - names.begin());
}

}  // namespace

bool Debugger::init(const Scene& scene, std::string& error) {
    if (!renderer_.init(error)) return false;
    session_.setComputeAhead(options_.compute_ahead);
    if (!session_.open(scene, scene.source_path, options_.algo, error)) return false;
    if (!checkViewFlags(options_.view_flags, session_.scene(), error)) return false;
    flags_scene_generation_ = session_.sceneGeneration();
    algo_names_ = gridcull::algorithmNames(session_.scene().dimensions);
    syncFamilyView();
    renderer_.setScene(session_.scene());
    view_camera_.frameScene(session_.scene());
    session_.seek(options_.frame);
    if (!options_.compare.empty() && !setCompare(options_.compare, error)) return false;
    if (options_.play) togglePlay();
    refreshSceneChoices();
    if (options_.lesson) {
        startLesson(*options_.lesson);
        goToLessonStep(options_.lesson_step, options_.lesson_step_finished);
    }
    return true;
}

void Debugger::syncFamilyView() { family_view_ = familyViewOf(session_.algo()); }

FamilyView* Debugger::familyViewOf(const std::string& algo) {
    const FamilyEntry* family = familyOfAlgorithm(algo);
    const FamilyViewEntry* entry = family ? findFamilyView(family->id) : nullptr;
    if (!entry) return nullptr;
    std::unique_ptr<FamilyView>& view = family_views_[entry->family];
    if (!view) {
        view = entry->make();
        // The preset asked for on the command line, when the family offers it.
        const std::vector<OverlayPreset> presets = view->overlayPresets();
        const bool offered = options_.overlays &&
                             std::find(presets.begin(), presets.end(), *options_.overlays) !=
                                 presets.end();
        if (!presets.empty()) view->applyOverlayPreset(offered ? *options_.overlays : presets.front());
        // The flags name things of the scene they were checked against (init).
        std::string error;
        if (session_.sceneGeneration() == flags_scene_generation_ &&
            !view->applyFlags(options_.view_flags, session_.scene(), error))
            scene_errors_ = {error};
    }
    return view.get();
}

int Debugger::outlinedObject() const {
    return family_view_ ? family_view_->focusedObject(familyContext()) : hovered_index_;
}

FamilyViewContext Debugger::familyContext() const {
    FamilyViewContext context;
    context.scene = &session_.scene();
    context.frame = session_.frame();
    context.t = session_.t();
    context.algo = session_.algo().c_str();
    context.snapshot = session_.debugSnapshot();
    context.knobs = &session_.knobs();
    context.view_mode = view_mode_;
    context.hovered_object = hovered_index_;
    context.states = &session_.states();
    return context;
}

void Debugger::updatePointer(double x, double y, bool inside, bool clicked,
                             const WindowLayout& layout) {
    hovered_index_ = -1;
    hovered_distance_ = 0.0;
    hovered_in_compare_ = false;
    ViewPointer pointer;
    const ScenePanes split = panes(layout);
    const ScenePane* over = nullptr;
    for (int k = 0; k < split.count; ++k)
        if (inside && split.pane[k].rect.contains(x, y)) over = &split.pane[k];
    FamilyView* view = family_view_;
    if (over) {
        const WindowRect& r = over->rect;
        const Scene& scene = session_.scene();
        const DebuggerSession& session = sessionOf(*over);
        hovered_in_compare_ = over->compared;
        const ViewMatrices m = view_camera_.matrices(over->mode, session.cullingCamera(),
                                                     double(r.width) / std::max(r.height, 1));
        viewRay(m, x - r.x, y - r.y, r.width, r.height, pointer.origin, pointer.direction);
        pointer.over_view = true;
        pointer.clicked = clicked;
        if (scene.dimensions == 2) {
            hovered_index_ = pickObject2d(scene, session.t(), pointer.origin, session.states());
        } else {
            double distance = 0.0;
            const int id =
                pickObject(scene, session.t(), pointer.origin, pointer.direction, &distance);
            if (id >= 0) {
                hovered_index_ = scene.indexOf(id);
                hovered_distance_ = distance;
            }
        }
        view = viewOf(*over);
        if (view) view->pointer(paneContext(*over), pointer);
        if (view == family_view_) return;
    }
    // The selected family's view hears that the pointer is not over it.
    if (family_view_) family_view_->pointer(familyContext(), ViewPointer{});
}

void Debugger::advancePlayback(double seconds) {
    sampleFlight(seconds);
    if (lesson_.active()) {
        const LessonPlayer::Tick tick = lesson_.advance(seconds);
        if (tick.step_changed) showLessonStep();
        else if (tick.animation_changed) applyLessonFlags();
    }
    session_.pollSeek();
    if (session_.seeking()) return;  // the frame shown waits for the seek
    if (!playing_) return;
    const double dt = session_.scene().dt;
    play_clock_ += seconds;
    int steps = 0;
    while (play_clock_ >= dt && steps < kMaxFramesPerAdvance) {
        play_clock_ -= dt;
        ++steps;
        if (!session_.step()) {
            playing_ = false;
            break;
        }
    }
    if (steps == kMaxFramesPerAdvance) play_clock_ = 0.0;
}

void Debugger::togglePlay() {
    playing_ = !playing_;
    play_clock_ = 0.0;
    // Play at the last frame means play again from the start.
    if (playing_ && session_.frame() + 1 >= session_.scene().frames) session_.seek(0);
}

void Debugger::stepForward() {
    playing_ = false;
    session_.step();
}

void Debugger::stepBack() {
    playing_ = false;
    session_.seek(session_.frame() - 1);
}

void Debugger::refreshSceneChoices() {
    namespace fs = std::filesystem;
    constexpr size_t kRecentScenes = 8;
    const std::string& current = session_.sceneFile();
    if (!current.empty()) {
        recent_scenes_.erase(std::remove(recent_scenes_.begin(), recent_scenes_.end(), current),
                             recent_scenes_.end());
        recent_scenes_.insert(recent_scenes_.begin(), current);
        if (recent_scenes_.size() > kRecentScenes) recent_scenes_.resize(kRecentScenes);
    }
    std::vector<std::string> found;
    std::vector<fs::path> folders = {fs::path("scenes")};
    if (!current.empty()) folders.insert(folders.begin(), fs::path(current).parent_path());
    std::error_code error;
    for (const fs::path& folder : folders) {
        if (!fs::is_directory(folder, error)) continue;
        for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
            if (entry.path().extension() == ".json" && entry.is_regular_file(error))
                found.push_back(entry.path().string());
        }
    }
    std::sort(found.begin(), found.end());
    // The same file reached twice (beside the current one and in ./scenes) is listed once.
    auto same = [&](const std::string& a, const std::string& b) {
        return fs::weakly_canonical(a, error) == fs::weakly_canonical(b, error);
    };
    scene_choices_ = recent_scenes_;
    for (const std::string& file : found) {
        const bool listed = std::any_of(scene_choices_.begin(), scene_choices_.end(),
                                        [&](const std::string& f) { return same(f, file); });
        if (!listed) scene_choices_.push_back(file);
    }
}

void Debugger::setUiScale(double scale) {
    options_.ui_scale = std::clamp(scale, kMinUiScale, kMaxUiScale);
}

void Debugger::toggleFreeze() {
    session_.setCullingCameraFrozen(!session_.cullingCameraFrozen());
}

FrameSnapshot Debugger::snapshot() const {
    FrameSnapshot s;
    s.scene = &session_.scene();
    s.trade = &trade_.view();
    s.frame = session_.frame();
    s.t = session_.t();
    s.playing = playing_;
    s.seek_target = session_.seeking() ? session_.seekTarget() : -1;
    s.seek_progress = session_.seeking() ? session_.seekProgress() : 0.0;
    s.checkpointing = checkpointing_;
    s.knobs = &session_.knobs();
    s.knob_cost = knob_cost_;
    s.algo_names = &algo_names_;
    s.algo_index = indexOfName(algo_names_, session_.algo());
    s.compare_index = compare_ ? indexOfName(algo_names_, compare_->algo()) : -1;
    s.result = &session_.result();
    s.exact = &session_.exactResult();
    s.false_culled = &session_.falseCulled();
    s.history = &session_.history();
    s.timeline = ahead_frames_ > 0 ? &ahead_ : nullptr;
    s.timeline_frames = ahead_frames_;
    // The object under the pointer as the pane it is in shows it (B's state in B's).
    const DebuggerSession& hovered = hovered_in_compare_ && compare_ ? *compare_ : session_;
    s.hover = describeObject(hovered.scene(), hovered_index_, hovered.t(), hovered.states(),
                             hovered_distance_);
    s.draw_ms = last_draw_ms_;
    s.show_timings = show_timings_;
    s.view_mode = view_mode_;
    s.culling_camera_frozen = session_.cullingCameraFrozen();
    s.flight = {flight_.recording(), int(flight_.keys().size()), flight_.seconds()};
    s.scene_file = &session_.sceneFile();
    s.scene_errors = &scene_errors_;
    s.scene_choices = &scene_choices_;
    s.recent_scene_count = int(recent_scenes_.size());
    s.note = &note_;
    s.panes = &pane_captions_;
    s.lesson = lesson_.active() ? &lesson_ : nullptr;
    return s;
}

UiActions Debugger::drawUi(const WindowLayout& layout) {
    updateTrade();
    noteCheckpoints();
    ahead_frames_ = session_.computedAhead(ahead_);
    syncCompare(false);
    captionPanes(layout);
    return drawDebuggerUi(snapshot(), ui_state_, layout, family_view_, familyContext());
}

void Debugger::noteCheckpoints() {
    const CullerCheckpoints& saved = session_.checkpoints();
    checkpointing_.count = saved.count();
    checkpointing_.interval = saved.interval();
    checkpointing_.bytes = saved.bytes();
    checkpointing_.budget = saved.budget();
}

void Debugger::setViewMode(ViewMode mode) {
    if (mode == ViewMode::Fly && view_mode_ != ViewMode::Fly) view_camera_.startFlyingFromOrbit();
    view_mode_ = mode;
}

void Debugger::openSceneFile(const std::string& path) {
    SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.scene) {
        scene_errors_ = loaded.errors;
        if (scene_errors_.empty()) scene_errors_.push_back(path + ": scene rejected");
        return;
    }
    // A culler that does not run on the new scene's dimension gives way to one
    // that does, and the scene panel says so.
    std::string algo = session_.algo(), why, error;
    std::string note;
    if (!algorithmFits(algo, *loaded.scene, why)) {
        std::string unused;
        algo = algorithmFits(defaultAlgorithm(), *loaded.scene, unused) ? defaultAlgorithm()
                                                                        : lastResortAlgorithm();
        note = why + "; switched to " + algo;
    }
    if (!session_.open(std::move(*loaded.scene), path, algo, error)) {
        scene_errors_ = {error};
        return;
    }
    trade_.clear();  // the curve was another scene's
    scene_errors_.clear();
    refreshSceneChoices();
    note_ = note;
    playing_ = false;
    hovered_index_ = -1;
    algo_names_ = gridcull::algorithmNames(session_.scene().dimensions);
    for (auto& [id, view] : family_views_) view->sceneChanged();
    syncFamilyView();
    renderer_.setScene(session_.scene());
    view_camera_.frameScene(session_.scene());
    if (compare_) {
        // The compared culler follows to the new scene when it runs there.
        const std::string compared = compare_->algo();
        compare_.reset();
        if (!setCompare(compared, error)) note_ += (note_.empty() ? "" : "; ") + error;
    }
}

void Debugger::selectAlgorithm(const std::string& name) {
    std::string error;
    if (!session_.selectAlgorithm(name, error)) {
        scene_errors_ = {error};
        return;
    }
    note_.clear();
    syncFamilyView();
}

void Debugger::apply(const UiActions& actions) {
    const PlaybackAction& playback = actions.playback;
    if (playback.toggle_play) togglePlay();
    if (playback.step) stepForward();
    if (playback.cancel_seek) session_.cancelSeek();
    if (actions.timeline.seek_frame >= 0) {
        playing_ = false;
        session_.seekInBackground(actions.timeline.seek_frame);
    }
    if (playback.seek_frame >= 0) {
        playing_ = false;
        session_.seekInBackground(playback.seek_frame);
    }
    const AlgorithmAction& algorithm = actions.algorithm;
    if (algorithm.select_algo && *algorithm.select_algo >= 0 &&
        *algorithm.select_algo < int(algo_names_.size()))
        selectAlgorithm(algo_names_[size_t(*algorithm.select_algo)]);
    if (algorithm.compare_algo) {
        std::string error;
        const int k = *algorithm.compare_algo;
        if (!setCompare(k >= 0 && k < int(algo_names_.size()) ? algo_names_[size_t(k)] : "",
                        error))
            scene_errors_ = {error};
    }
    if (algorithm.freeze_culling) session_.setCullingCameraFrozen(*algorithm.freeze_culling);
    if (algorithm.view_mode) setViewMode(*algorithm.view_mode);
    if (algorithm.flight_record) toggleFlightRecording();
    if (algorithm.flight_save) saveFlight();
    if (algorithm.flight_discard) discardFlight();
    if (actions.scene.open) openSceneFile(actions.scene.path);
    if (!actions.family.knobs.empty()) applyKnobs(actions.family.knobs, {});
    if (actions.knobs.apply) applyKnobs(actions.knobs.set, actions.knobs.unset);
    if (actions.knobs.trade.stop) trade_.stop();
    if (actions.knobs.trade.start)
        trade_.start(session_.scene(), session_.algo(), session_.knobs());
    if (actions.knobs.trade.apply >= 0) applyTradeSetting(actions.knobs.trade.apply);
    if (actions.overlay_preset) applyOverlayPreset(*actions.overlay_preset);
    if (actions.lesson.go_to >= 0) goToLessonStep(actions.lesson.go_to);
    if (actions.lesson.auto_play >= 0) setLessonAutoPlay(actions.lesson.auto_play == 1);
}

namespace {

// Median cull time and summed PVS over summed exact visible, frames 0..last.
void runFigures(const FrameHistory& history, int last, double& median_ms, double& ratio) {
    std::vector<float> ms(history.cull_ms.begin(), history.cull_ms.begin() + last + 1);
    std::nth_element(ms.begin(), ms.begin() + std::ptrdiff_t(ms.size() / 2), ms.end());
    median_ms = ms[ms.size() / 2];
    double pvs = 0.0, exact = 0.0;
    for (int f = 0; f <= last; ++f) {
        pvs += history.pvs_size[size_t(f)];
        exact += history.exact_visible[size_t(f)];
    }
    ratio = exact > 0.0 ? pvs / exact : 0.0;
}

}  // namespace

void Debugger::applyTradeSetting(int index) {
    const TradeSetting* setting = trade_.setting(index);
    const FamilyEntry* family = setting ? familyOfAlgorithm(setting->algorithm) : nullptr;
    if (!family) return;
    std::vector<std::pair<std::string, double>> set;
    std::vector<std::string> unset;
    for (const Knob& k : family->knobs) {
        if (setting->knobs.has(k.flag))
            set.emplace_back(k.flag, setting->knobs.get(k));
        else
            unset.push_back(k.flag);
    }
    applyKnobs(set, unset);
}

void Debugger::applyKnobs(const std::vector<std::pair<std::string, double>>& set,
                          const std::vector<std::string>& unset) {
    // Checked like the command line's values: a panel asking for a knob that
    // is not there, or out of its range, is a bug to show, not to ignore.
    KnobValues knobs = session_.knobs();
    std::string error;
    for (const auto& [flag, value] : set) {
        const Knob* knob = findKnob(flag);
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", value);
        double checked = 0.0;
        if (!knob) {
            error = "the panel set --" + flag + ", which is no knob";
        } else if (parseKnobValue(*knob, text, checked, error)) {
            knobs.set(flag, checked);
            continue;
        }
        scene_errors_ = {error};
        return;
    }
    for (const std::string& flag : unset) knobs.unset(flag);
    KnobApplyCost cost;
    const int last = session_.frame();
    runFigures(session_.history(), last, cost.cull_ms_before, cost.pvs_ratio_before);
    const auto start = std::chrono::steady_clock::now();
    if (!session_.setKnobs(knobs, error)) {
        scene_errors_ = {error};
        return;
    }
    cost.rerun_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    cost.frames = last + 1;
    if (compare_ && !compare_->setKnobs(knobs, error)) note_ = "the compared culler: " + error;
    runFigures(session_.history(), last, cost.cull_ms_after, cost.pvs_ratio_after);
    cost.valid = true;
    knob_cost_ = cost;
}

}  // namespace gridcull
