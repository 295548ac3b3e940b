// One meaning per colour (ui/palette.h): vermillion is the false culls' alone,
// so no family's overlay may draw it. Every family in the ui registry draws its
// overlay with its "all" preset on a small scene, a thing picked (an occluder,
// an object), an object focused and the pointer over the view through the
// culling camera, so that every layer it has is drawn; no primitive of the
// batch may be vermillion. A family added to the registry without a scene here
// fails until it gets one.
#include <map>
#include <memory>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"
#include "tests/ui/overlay_swatches.h"
#include "ui/debugger_session.h"
#include "ui/registry/family_views.h"

namespace gridcull {
namespace {

struct AuditCase {
    const char* algorithm;
    const char* scene;  // under scenes/
    int frame;
    std::map<std::string, double> flags;  // view flags: something picked
};

// Per family id, its scenes (both dimensions where it runs on both).
const std::multimap<std::string, AuditCase>& auditCases() {
    static const std::multimap<std::string, AuditCase> cases{
        {"rgvc", {"rgvc", "figure1-2d.json", 30, {{"rgvc-occluder", 0}}}},
        {"rgvc", {"rgvc", "hidden-movers-3d.json", 60, {{"rgvc-occluder", 0}}}},
        {"lazy-grid", {"lazy-grid", "hidden-movers-3d.json", 30, {}}},
        {"hzb", {"hzb-tbv", "hidden-movers-3d.json", 60, {}}},
        {"bsp", {"bsp-oq", "hidden-movers-3d.json", 30, {}}},
    };
    return cases;
}

// The overlay of `c` with the "all" preset, each object in turn focused.
// Returns the swatches drawn.
std::set<Swatch> auditOverlay(const FamilyViewEntry& entry, const AuditCase& c) {
    KnobValues knobs;
    knobs.set("oracle-res", 160);
    DebuggerSession session(knobs);
    SceneLoadResult loaded = loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/" + c.scene);
    EXPECT_TRUE(loaded.scene) << c.scene;
    if (!loaded.scene) return {};
    std::string error;
    EXPECT_TRUE(session.open(std::move(*loaded.scene), "", c.algorithm, error)) << error;
    session.seek(c.frame);
    EXPECT_NE(session.debugSnapshot(), nullptr) << c.algorithm;

    std::unique_ptr<FamilyView> view = entry.make();
    KnobValues flags;
    for (const auto& [flag, value] : c.flags) flags.set(flag, value);
    EXPECT_TRUE(view->applyFlags(flags, session.scene(), error)) << error;
    EXPECT_FALSE(view->overlayPresets().empty()) << entry.family << ": no presets";
    view->applyOverlayPreset(OverlayPreset::All);

    const Scene& scene = session.scene();
    const Camera& camera = session.cullingCamera();
    FamilyViewContext context;
    context.scene = &scene;
    context.algo = c.algorithm;
    context.snapshot = session.debugSnapshot();
    context.knobs = &session.knobs();
    context.states = &session.states();
    OverlayView overlay;
    ViewPointer pointer;
    pointer.over_view = true;
    if (scene.dimensions == 3) {
        overlay.width = 960;
        overlay.height = int(960 / camera.aspect);
        overlay.view_projection = camera.projectionMatrix() * camera.viewMatrix();
        overlay.through_culling_camera = true;
        overlay.culling_aspect = camera.aspect;
        pointer.origin = camera.position;  // along the line of sight
        pointer.direction = camera.forward();
    } else {
        pointer.origin = scene.grid.world.center();
    }
    view->pointer(context, pointer);

    std::set<Swatch> drawn;
    DebugDrawBatch batch;
    const int objects = int(scene.objects.size());
    for (int focus = -1; focus < objects; focus += std::max(1, objects / 12)) {
        context.hovered_object = focus;
        batch.clear();
        view->drawOverlay(context, overlay, batch);
        for (Swatch s : test::swatchesIn(batch)) drawn.insert(s);
    }
    return drawn;
}

TEST(PaletteAudit, NoOverlayDrawsTheFalseCullColour) {
    ASSERT_FALSE(familyViews().empty());
    for (const FamilyViewEntry& entry : familyViews()) {
        const auto range = auditCases().equal_range(entry.family);
        ASSERT_NE(range.first, range.second) << "family " << entry.family << ": add a scene here";
        for (auto it = range.first; it != range.second; ++it) {
            SCOPED_TRACE(entry.family + " on " + it->second.scene);
            const std::set<Swatch> drawn = auditOverlay(entry, it->second);
            EXPECT_GE(drawn.size(), 3u) << "the overlay drew next to nothing: a weak audit";
            EXPECT_EQ(drawn.count(Swatch::Vermillion), 0u) << "vermillion means a false cull";
        }
    }
}

}  // namespace
}  // namespace gridcull
