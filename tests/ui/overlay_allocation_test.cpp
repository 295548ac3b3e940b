// "Hot per-frame paths do not allocate": once a family's overlay has been drawn
// into the debug-draw batch, drawing it again (the window does every frame)
// allocates nothing, for the rgvc and lazy grid overlays, with their optional
// layers and a focused object on. Counted by tests/common/counting_new.h, which
// replaces the global operator new of this test binary; the counter runs only
// inside the measured draws.
#include <string>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"
#include "tests/common/counting_new.h"
#include "ui/debug_draw.h"
#include "ui/debugger_session.h"
#include "ui/registry/family_views.h"

namespace gridcull {
namespace {

// Allocations made by drawing `view`'s overlay a second and third time.
long allocationsOfRedraws(const char* scene_file, const char* algo, int frame,
                          const KnobValues& flags, bool through_camera) {
    SceneLoadResult loaded =
        loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/" + scene_file);
    EXPECT_TRUE(loaded.scene);
    KnobValues knobs;
    knobs.set("oracle-res", 160);
    DebuggerSession session(knobs);
    std::string error;
    EXPECT_TRUE(session.open(std::move(*loaded.scene), "", algo, error)) << error;
    session.seek(frame);
    std::unique_ptr<FamilyView> view = familyViewOfAlgorithm(algo)->make();
    EXPECT_TRUE(view->applyFlags(flags, session.scene(), error)) << error;
    FamilyViewContext context;
    context.scene = &session.scene();
    context.algo = algo;
    context.snapshot = session.debugSnapshot();
    context.knobs = &session.knobs();
    OverlayView overlay;
    overlay.width = 900;
    overlay.height = 720;
    overlay.through_culling_camera = through_camera;
    overlay.culling_aspect = session.cullingCamera().aspect;
    DebugDrawBatch batch;
    view->drawOverlay(context, overlay, batch);
    EXPECT_FALSE(batch.empty()) << algo << ": the overlay draws something";
    test::startCounting();
    for (int k = 0; k < 2; ++k) {
        batch.clear();
        view->drawOverlay(context, overlay, batch);
    }
    test::stopCounting();
    return test::allocationCount();
}

TEST(OverlayAllocation, TheCounterSeesAnAllocation) {
    test::startCounting();
    std::string* s = new std::string(100, 'x');
    test::stopCounting();
    delete s;
    EXPECT_GE(test::allocationCount(), 1);
}

TEST(OverlayAllocation, RedrawingTheRgvcOverlayAllocatesNothing) {
    KnobValues flags;
    flags.set("rgvc-layer", 20);
    flags.set("rgvc-occluder", 0);
    EXPECT_EQ(allocationsOfRedraws("figure1-2d.json", "rgvc", 60, flags, false), 0);
}

// 3D: the voxel boxes with a layer stepped to and a picked occluder's cap, and
// a slice.
TEST(OverlayAllocation, RedrawingTheRgvcOverlayIn3dAllocatesNothing) {
    KnobValues flags;
    flags.set("rgvc-layer", 12);
    flags.set("rgvc-occluder", 0);
    EXPECT_EQ(allocationsOfRedraws("hidden-movers-3d.json", "rgvc", 60, flags, false), 0);
    flags.set("rgvc-slice", 10);
    flags.set("rgvc-slice-axis", 2);
    EXPECT_EQ(allocationsOfRedraws("hidden-movers-3d.json", "rgvc", 60, flags, false), 0);
}

TEST(OverlayAllocation, RedrawingTheLazyGridOverlayAllocatesNothing) {
    KnobValues flags;
    flags.set("lazy-object", 2300);  // a crown culled after pixel queries
    EXPECT_EQ(allocationsOfRedraws("forest-3d.json", "lazy-grid", 60, flags, true), 0);
}

}  // namespace
}  // namespace gridcull
