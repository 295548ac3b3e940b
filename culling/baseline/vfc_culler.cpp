#include "culling/baseline/vfc_culler.h"

#include <algorithm>

#include "culling/baseline/frustum_tests.h"

namespace gridcull {

void VfcCuller::reset(const Scene& /*scene*/) {}

void VfcCuller::cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) {
    out.stats = CullStats{};
    out.pvs.clear();
    const std::array<glm::dvec4, 6> planes = camera.frustumPlanes();  // once, not per object
    for (const SceneObject& object : scene.objects) {
        bool keep;
        if (scene.dimensions == 2 && object.shape == ShapeKind::Sphere) {
            keep = circleMayIntersectWedge(object.center + scene.displacementAt(object, t),
                                           object.radius, camera);
        } else if (scene.dimensions == 2) {
            keep = boxMayIntersectWedge(scene.boundsAt(object, t), camera);
        } else {
            keep = boxMayIntersectFrustum(scene.boundsAt(object, t), camera, planes);
        }
        if (keep) out.pvs.push_back(object.id);
    }
    std::sort(out.pvs.begin(), out.pvs.end());
    out.stats.set(Counter::ObjectsTested, int64_t(scene.objects.size()));
}

}  // namespace gridcull
