// A family's side of the window: its panel, its overlay over the scene view, how
// it answers the pointer, and the view flags that reach its state from the
// command line (`shot`, `view`). The window knows families only through this
// interface and the ui registry (ui/registry/family_views.h), which maps a
// family's registry id to its FamilyViewEntry; a family's view lives in its own
// folder (ui/<family>/).
//
// The view reads the culler's state as the const DebugSnapshot the culler
// captured (culling/api/debug_snapshot.h), cast back with as<T>() in the
// family's own code. What the view keeps (toggles, a picked object, a chess
// layer) is UI state, changed only by its own panel, the pointer and flags.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "culling/api/debug_snapshot.h"
#include "culling/api/knobs.h"
#include "culling/scene/camera.h"
#include "culling/scene/scene.h"
#include "ui/debug_draw.h"
#include "ui/image_frame.h"
#include "ui/object_state.h"
#include "ui/overlay_preset.h"
#include "ui/view_mode.h"

namespace gridcull {

// The frame as the family's view sees it. Pointers borrow from the window and
// are valid for the call only.
struct FamilyViewContext {
    const Scene* scene = nullptr;
    int frame = 0;
    double t = 0.0;
    const char* algo = "";                    // the selected algorithm's name
    const DebugSnapshot* snapshot = nullptr;  // the culler's last frame; null when none
    const KnobValues* knobs = nullptr;        // the culler's knob values
    ViewMode view_mode = ViewMode::Overview;
    int hovered_object = -1;  // index into scene->objects, -1: none
    // Each object's state this frame (visible, hidden, culled, false-culled),
    // by object index; null when not known.
    const std::vector<ObjectState>* states = nullptr;
};

// The pointer over the scene view this frame.
struct ViewPointer {
    bool over_view = false;
    // 2D: the world point under the pointer (z = 0). 3D: the ray through it.
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0};
    bool clicked = false;  // the left button was clicked over the view
};

// Where the overlay draws: the scene view's size and camera.
struct OverlayView {
    glm::dmat4 view_projection{1.0};  // World space to clip space
    int width = 1, height = 1;        // view pixels
    // 3D and looking through the culling camera: the culling camera's image lies
    // on the view (cullingImage says where), so image-space state can be drawn
    // over the objects it describes.
    bool through_culling_camera = false;
    double culling_aspect = 1.0;
    // The camera the culler used this frame (3D): from outside it, an
    // image-space overlay can be held up on a plane across its frustum
    // (ui/image_plane_draw.h).
    Camera culling_camera;
    ImageFrame cullingImage(int image_width, int image_height) const {
        return cullingImageFrame(culling_aspect, width, height, image_width, image_height);
    }
};

// What a family's panel asks the window to do.
struct FamilyAction {
    // Knobs to set (flag, value): the window re-makes the culler with them and
    // re-runs up to the current frame.
    std::vector<std::pair<std::string, double>> knobs;
};

class FamilyView {
public:
    virtual ~FamilyView() = default;
    // The view flags of the command line (its entry's `flags`), checked against
    // the scene: false and `error` naming the flag when one names something the
    // scene lacks (an object id, say).
    virtual bool applyFlags(const KnobValues& flags, const Scene& scene, std::string& error) {
        (void)flags, (void)scene, (void)error;
        return true;
    }
    // The overlay presets the family offers, in the panel's order; the first is
    // the one a new view starts with (empty: the family has no toggles).
    virtual std::vector<OverlayPreset> overlayPresets() const { return {}; }
    // Sets the overlay's toggles to `preset`, one of overlayPresets(); the
    // family's own toggles stay free to change afterwards.
    virtual void applyOverlayPreset(OverlayPreset preset) { (void)preset; }
    // Another scene was opened: forget what pointed into the old one.
    virtual void sceneChanged() {}
    // The pointer over the view (hovering; a click picks).
    virtual void pointer(const FamilyViewContext& context, const ViewPointer& pointer) {
        (void)context, (void)pointer;
    }
    // The object the view outlines as focused (index, -1: none); by default the
    // one under the pointer.
    virtual int focusedObject(const FamilyViewContext& context) const {
        return context.hovered_object;
    }
    // The family's panel, right under the algorithm panel, in the current ImGui window.
    virtual void drawPanel(const FamilyViewContext& context, FamilyAction& action) = 0;
    // The family's overlay, over the objects and under the false-cull outlines.
    virtual void drawOverlay(const FamilyViewContext& context, const OverlayView& view,
                             DebugDraw& draw) = 0;
};

struct FamilyViewEntry {
    std::string family;       // the FamilyEntry::id it shows
    std::vector<Knob> flags;  // view flags (a picked object, a shown layer); unset: their default
    std::function<std::unique_ptr<FamilyView>()> make;
};

}  // namespace gridcull
