// The Debugger's split scene view: a second culler compared on the same frame
// (its own DebuggerSession, kept on the shown frame, camera and knobs), the
// panes the view is split into, and how each is drawn.
#include <algorithm>
#include <cstdio>

#include "app/debugger.h"
#include "culling/registry/registry.h"

namespace gridcull {

namespace {

bool inPvs(ObjectState state) {
    return state == ObjectState::Visible || state == ObjectState::Hidden;
}

}  // namespace

bool Debugger::setCompare(const std::string& algo, std::string& error) {
    if (algo.empty()) {
        compare_.reset();
        differing_.clear();
        return true;
    }
    std::string why;
    if (!algorithmFits(algo, session_.scene(), why)) {
        error = "cannot compare with " + why;
        return false;
    }
    auto compare = std::make_unique<DebuggerSession>(session_.knobs());
    if (!compare->open(session_.scene(), session_.sceneFile(), algo, error)) return false;
    compare_ = std::move(compare);
    familyViewOf(algo);  // made now, so its overlay draws on the first frame
    syncCompare(true);
    return true;
}

void Debugger::syncCompare(bool wait) {
    differing_.clear();
    if (!compare_) return;
    compare_->pollSeek();
    if (compare_->cullingCameraFrozen() != session_.cullingCameraFrozen()) {
        // Frozen at the frame the shown culler was frozen at, so both cull
        // from the same camera.
        compare_->cancelSeek();
        if (session_.cullingCameraFrozen()) compare_->seek(session_.frozenAt());
        compare_->setCullingCameraFrozen(session_.cullingCameraFrozen());
    }
    if (compare_->frame() != session_.frame()) {
        if (wait) {
            compare_->cancelSeek();
            compare_->seek(session_.frame());
        } else if (!compare_->seeking() || compare_->seekTarget() != session_.frame()) {
            compare_->seekInBackground(session_.frame());
        }
    }
    if (compare_->frame() != session_.frame()) return;
    const std::vector<ObjectState>& a = session_.states();
    const std::vector<ObjectState>& b = compare_->states();
    for (size_t i = 0; i < a.size() && i < b.size(); ++i)
        if (inPvs(a[i]) != inPvs(b[i])) differing_.push_back(int(i));
}

ScenePanes Debugger::panes(const WindowLayout& layout) const {
    const ViewMode mode = session_.scene().dimensions == 3 ? view_mode_ : ViewMode::Overview;
    return splitSceneView(layout.scene_view, mode, compare_ != nullptr);
}

FamilyView* Debugger::viewOf(const ScenePane& pane) {
    return pane.compared && compare_ ? familyViewOf(compare_->algo()) : family_view_;
}

FamilyViewContext Debugger::paneContext(const ScenePane& pane) const {
    const DebuggerSession& session = sessionOf(pane);
    FamilyViewContext context = familyContext();
    context.frame = session.frame();
    context.t = session.t();
    context.algo = session.algo().c_str();
    context.snapshot = session.debugSnapshot();
    context.states = &session.states();
    context.view_mode = pane.mode;
    return context;
}

void Debugger::applyOverlayPreset(OverlayPreset preset) {
    if (family_view_) family_view_->applyOverlayPreset(preset);
    // The compared culler's family follows, when it offers the preset.
    FamilyView* compared = compare_ ? familyViewOf(compare_->algo()) : nullptr;
    if (compared && compared != family_view_) {
        const std::vector<OverlayPreset> offered = compared->overlayPresets();
        if (std::find(offered.begin(), offered.end(), preset) != offered.end())
            compared->applyOverlayPreset(preset);
    }
}

void Debugger::captionPanes(const WindowLayout& layout) {
    const ScenePanes split = panes(layout);
    // Resized and assigned in place: the strings keep their capacity from
    // frame to frame.
    pane_captions_.resize(split.count < 2 ? 0 : size_t(split.count));
    char line[160];
    for (size_t k = 0; k < pane_captions_.size(); ++k) {
        const ScenePane& pane = split.pane[k];
        PaneCaption& caption = pane_captions_[k];
        caption.rect = pane.rect;
        if (!compare_) {
            caption.title.assign(pane.mode == ViewMode::CullingCamera
                                     ? "culling camera"
                                     : "observer: right-drag rotates, wheel zooms");
            caption.detail.clear();
            continue;
        }
        const DebuggerSession& session = sessionOf(pane);
        std::snprintf(line, sizeof line, "%s: %s", pane.compared ? "B" : "A",
                      session.algo().c_str());
        caption.title.assign(line);
        if (session.frame() != session_.frame()) {
            std::snprintf(line, sizeof line, "catching up: frame %d of %d", session.frame(),
                          session_.frame());
        } else {
            std::snprintf(line, sizeof line,
                          "PVS %zu (exact %zu), %zu false culls; %zu in one PVS only",
                          session.result().pvs.size(), session.exactResult().pvs.size(),
                          session.falseCulled().size(), differing_.size());
        }
        caption.detail.assign(line);
    }
}

void Debugger::drawScene(const WindowLayout& layout, int framebuffer_height, double scale) {
    const ScenePanes split = panes(layout);
    last_draw_ms_ = 0.0;
    for (int k = 0; k < split.count; ++k) drawPane(split.pane[k], framebuffer_height, scale);
    session_.recordDrawMs(last_draw_ms_);
}

void Debugger::drawPane(const ScenePane& pane, int framebuffer_height, double scale) {
    const DebuggerSession& session = sessionOf(pane);
    SceneDrawInput input;
    input.scene = &session.scene();
    input.t = session.t();
    input.states = &session.states();
    input.culling_camera = session.cullingCamera();
    const bool through_camera =
        session.scene().dimensions == 3 && pane.mode == ViewMode::CullingCamera;
    input.show_culling_camera = !through_camera;
    input.through_culling_camera = through_camera;
    const WindowRect& v = pane.rect;
    input.viewport = {int(v.x * scale), int(v.y * scale), int(v.width * scale),
                      int(v.height * scale)};
    input.framebuffer_height = framebuffer_height;
    input.view = view_camera_.matrices(pane.mode, session.cullingCamera(),
                                       double(v.width) / std::max(v.height, 1));
    const FamilyViewContext context = paneContext(pane);
    input.hovered_index = outlinedObject();
    input.differing = compare_ ? &differing_ : nullptr;
    input.family = viewOf(pane);
    input.family_context = &context;
    last_draw_ms_ += renderer_.draw(input);
}

}  // namespace gridcull
