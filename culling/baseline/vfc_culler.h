// `vfc`: view-frustum culling only, the baseline every occlusion culler is
// compared with ("VFC" in the papers' tables). No occlusion, no state between
// frames.
//
// 3D: each object's world bounds at t (Scene::boundsAt) against the six planes of
// Camera::frustumPlanes, near and far included, with the conservative box-plane
// test (the box is culled only when its most inward corner is outside one plane;
// a box that straddles two planes outside the frustum's corner is kept).
// 2D: the wedge of fov_deg around the view direction, cut at `far`. A sphere
// (circle) is tested as its circle, every other shape as its bounding box: culled
// when its nearest point is beyond `far`, or when its angular interval seen from
// the camera misses the wedge's (fov 360: only the far test).
// Both: a camera inside the bounds (or circle) keeps the object.
// Counter: objects_tested (every object, every frame). Cost O(objects).
#pragma once
#include "culling/api/culler.h"

namespace gridcull {

class VfcCuller final : public Culler {
public:
    const char* name() const override { return "vfc"; }
    void reset(const Scene& scene) override;
    void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) override;
    std::unique_ptr<Culler> clone() const override { return std::make_unique<VfcCuller>(*this); }
};

}  // namespace gridcull
