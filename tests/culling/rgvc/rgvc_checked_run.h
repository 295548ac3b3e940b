// What rgvc's hand-made scene tests share: running a scene frame by frame
// against the exact oracle (any false cull fails the test), giving the last
// object a straight-line motion, and looking up an id in a PVS.
#pragma once
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "culling/oracle/exact_oracle.h"
#include "culling/rgvc/rgvc_culler.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull::test {

inline bool has(const std::vector<int>& ids, int id) {
    return std::binary_search(ids.begin(), ids.end(), id);
}

inline void moving(Scene& scene, const glm::dvec3& velocity) {
    SceneObject& o = scene.objects.back();
    o.motion.kind = MotionKind::Linear;
    o.motion.velocity = velocity;
    o.motion.max_speed = glm::length(velocity);
}

// Culls frames 0..frames-1 with rgvc and exact; fails on a false cull.
inline std::vector<FrameResult> runChecked(const Scene& scene, int frames, RgvcCuller& rgvc) {
    ExactOracle exact;
    rgvc.reset(scene);
    exact.reset(scene);
    std::vector<FrameResult> results;
    for (int f = 0; f < frames; ++f) {
        const double t = scene.timeOfFrame(f);
        const Camera camera = cameraAt(scene, t);
        FrameResult got, want;
        rgvc.cull(scene, camera, t, got);
        exact.cull(scene, camera, t, want);
        EXPECT_TRUE(isSubset(want.pvs, got.pvs)) << "frame " << f;
        results.push_back(got);
    }
    return results;
}

}  // namespace gridcull::test
