// scenes/figure1-2d.json (made by scripts/make_figure1_scene.py), the scene of
// Batagelo & Wu's Figure 1: it loads as the paper describes it, and over all its
// 250 frames rgvc never culls what the exact oracle sees and culls far more than
// view-frustum culling. Prints cull ms (median), PVS, exact, PVS / exact and
// voxels visited per frame next to vfc's, the numbers of docs' results table.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/baseline/vfc_culler.h"
#include "culling/io/scene_loader.h"
#include "culling/oracle/exact_oracle.h"
#include "culling/rgvc/rgvc_culler.h"

namespace gridcull {
namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

TEST(RgvcFigure1, SceneMatchesThePaperAndCullsConservatively) {
    const SceneLoadResult loaded =
        loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/figure1-2d.json");
    ASSERT_TRUE(loaded.scene.has_value()) << (loaded.errors.empty() ? "" : loaded.errors.front());
    const Scene& scene = *loaded.scene;
    EXPECT_EQ(scene.dimensions, 2);
    EXPECT_EQ(scene.grid.resolution, glm::ivec3(256, 256, 1));
    int dynamic = 0;
    for (const SceneObject& o : scene.objects) dynamic += o.isDynamic() ? 1 : 0;
    EXPECT_EQ(dynamic, 300);
    EXPECT_GT(int(scene.objects.size()), dynamic);  // and some static walls

    RgvcCuller rgvc;
    VfcCuller vfc;
    ExactOracle exact;
    rgvc.reset(scene);
    vfc.reset(scene);
    exact.reset(scene);
    FrameResult r, v, e;
    std::vector<double> rgvc_ms, vfc_ms;
    int64_t false_culls = 0, pvs = 0, vfc_pvs = 0, exact_pvs = 0, visited = 0, updates = 0;
    int64_t created = 0, expired = 0, revealed = 0;
    for (int f = 0; f < scene.frames; ++f) {
        const double t = scene.timeOfFrame(f);
        const Camera camera = cameraAt(scene, t);
        timedCull(rgvc, scene, camera, t, r);
        timedCull(vfc, scene, camera, t, v);
        exact.cull(scene, camera, t, e);
        for (const int id : e.pvs)
            if (!std::binary_search(r.pvs.begin(), r.pvs.end(), id)) {
                ++false_culls;
                ADD_FAILURE() << "frame " << f << ": id " << id << " culled but visible";
            }
        rgvc_ms.push_back(r.stats.cull_ms);
        vfc_ms.push_back(v.stats.cull_ms);
        pvs += int64_t(r.pvs.size());
        vfc_pvs += int64_t(v.pvs.size());
        exact_pvs += int64_t(e.pvs.size());
        visited += r.stats.get(Counter::VoxelsVisited);
        updates += r.stats.get(Counter::ObjectUpdates);
        created += r.stats.get(Counter::TbvCreated);
        expired += r.stats.get(Counter::TbvExpired);
        revealed += r.stats.get(Counter::TbvRevealed);
    }
    const double n = double(scene.frames);
    std::printf("[ rgvc ] figure1-2d, %d frames, %zu objects: false culls %lld\n", scene.frames,
                scene.objects.size(), (long long)false_culls);
    std::printf(
        "[ rgvc ]   rgvc: cull %.3f ms (median), PVS %.1f, exact %.1f, PVS/exact %.2f, "
        "voxels visited %.0f, object updates %.1f, TBVs created %.2f expired %.2f revealed %.2f "
        "per frame\n",
        median(rgvc_ms), pvs / n, exact_pvs / n, double(pvs) / double(exact_pvs), visited / n,
        updates / n, created / n, expired / n, revealed / n);
    std::printf("[ rgvc ]   vfc:  cull %.3f ms (median), PVS %.1f, PVS/exact %.2f\n",
                median(vfc_ms), vfc_pvs / n, double(vfc_pvs) / double(exact_pvs));
    const RgvcMatrixMemory m = rgvc.memory();
    std::printf(
        "[ rgvc ]   memory: O %zu, Os %zu, H %zu, I static %zu, I dynamic %zu, T %zu, scratch %zu "
        "bytes\n",
        m.occluder, m.static_occluder, m.occlusion, m.identifiers_static, m.identifiers_dynamic,
        m.tbv, m.traversal);
    EXPECT_EQ(false_culls, 0);
    EXPECT_LT(pvs, vfc_pvs / 2);  // occlusion must pay off in this scene
}

}  // namespace
}  // namespace gridcull
