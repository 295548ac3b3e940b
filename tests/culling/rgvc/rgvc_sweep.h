// The differential run both rgvc sweeps share (rgvc_differential_test.cpp in
// 2D, rgvc_differential3d_test.cpp in 3D): one seeded random scene's frames
// through rgvc, the exact oracle and vfc side by side; every id the oracle sees
// must be in rgvc's PVS (a false cull is reported with the seed, frame and
// camera that replay it), and the totals feed the printed PVS / exact ratios.
#pragma once
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "culling/baseline/vfc_culler.h"
#include "culling/oracle/exact_oracle.h"
#include "culling/rgvc/rgvc_culler.h"

namespace gridcull::test {

struct RgvcSweepTotals {
    int64_t frames = 0;
    int64_t false_culls = 0;
    int64_t pvs = 0;
    int64_t exact = 0;
    int64_t vfc = 0;
    int64_t objects = 0;
    int64_t voxels_visited = 0;
    int64_t occluded_frames = 0;  // frames where rgvc kept fewer than vfc
};

inline void rgvcSweepScene(const Scene& scene, int frames, uint64_t seed,
                           const RgvcOptions& options, RgvcSweepTotals& totals) {
    RgvcCuller rgvc(options);
    ExactOracle exact;
    VfcCuller vfc;
    rgvc.reset(scene);
    exact.reset(scene);
    vfc.reset(scene);
    FrameResult got, want, frustum;
    for (int frame = 0; frame < frames; ++frame) {
        const double t = scene.timeOfFrame(frame);
        const Camera camera = cameraAt(scene, t);
        rgvc.cull(scene, camera, t, got);
        exact.cull(scene, camera, t, want);
        vfc.cull(scene, camera, t, frustum);
        std::string missing;
        int64_t missed = 0;
        for (const int id : want.pvs)
            if (!std::binary_search(got.pvs.begin(), got.pvs.end(), id)) {
                missing += (missing.empty() ? "" : ",") + std::to_string(id);
                ++missed;
            }
        if (missed > 0)
            ADD_FAILURE() << "false cull: seed " << seed << " frame " << frame << " t " << t
                          << " camera (" << camera.position.x << ", " << camera.position.y << ", "
                          << camera.position.z << ") fov " << camera.fov_deg << " near "
                          << camera.near << " far " << camera.far << " missing ids " << missing;
        EXPECT_TRUE(std::is_sorted(got.pvs.begin(), got.pvs.end()));
        totals.frames += 1;
        totals.false_culls += missed;
        totals.pvs += int64_t(got.pvs.size());
        totals.exact += int64_t(want.pvs.size());
        totals.vfc += int64_t(frustum.pvs.size());
        totals.objects += int64_t(scene.objects.size());
        totals.voxels_visited += got.stats.get(Counter::VoxelsVisited);
        totals.occluded_frames += got.pvs.size() < frustum.pvs.size() ? 1 : 0;
    }
}

inline void rgvcSweepReport(const char* dims, const char* name, size_t scenes, int frames,
                            const RgvcSweepTotals& t) {
    const double n = double(std::max<int64_t>(1, t.frames));
    std::printf(
        "[ rgvc %s ] %s: %zu scenes x %d frames: false culls %lld, mean PVS %.2f, mean exact "
        "%.2f, PVS/exact %.3f (vfc %.3f), frames culling more than vfc %.1f%%, mean objects "
        "%.1f, mean voxels visited %.0f\n",
        dims, name, scenes, frames, (long long)t.false_culls, double(t.pvs) / n,
        double(t.exact) / n, t.exact > 0 ? double(t.pvs) / double(t.exact) : 0.0,
        t.exact > 0 ? double(t.vfc) / double(t.exact) : 0.0, 100.0 * double(t.occluded_frames) / n,
        double(t.objects) / n, double(t.voxels_visited) / n);
}


}  // namespace gridcull::test
