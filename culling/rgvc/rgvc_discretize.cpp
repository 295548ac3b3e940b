// Scene discretization of regular-grid culling (Batagelo & Wu, section 4.1, and
// section 4.5 for static objects): the parts both dimensions share, and the 2D
// rasterization. The 3D one (section 5.1) is in rgvc_discretize3d.cpp, the TBVs
// in rgvc_tbv_life.cpp. rgvc_culler.h says where this departs from the paper.
#include <algorithm>
#include <cmath>

#include "culling/baseline/frustum_tests.h"
#include "culling/rgvc/rgvc_culler.h"
#include "grid/conservative_raster.h"

namespace gridcull {

namespace {

bool insideWorld(const Aabb& bounds, const Aabb& world, int dimensions) {
    for (int a = 0; a < dimensions; ++a)
        if (bounds.min[a] < world.min[a] || bounds.max[a] > world.max[a]) return false;
    return true;
}

// Writes one object, displaced by `shift`, through touched(y, x0, x1) (I) and
// inside(y, x0, x1) (O). Meshes do not exist in 2D scenes (the loader rejects
// them); one that slips through spans its bounding box and makes nothing opaque.
template <typename Touched, typename Inside>
void rasterizeObject(const RegularGrid& grid, const SceneObject& object, const glm::dvec3& shift,
                     Touched&& touched, Inside&& inside) {
    switch (object.shape) {
        case ShapeKind::Sphere:
            rasterizeCircle(grid, object.center + shift, object.radius, touched, inside);
            return;
        case ShapeKind::Box:
            rasterizeBox(grid, object.box.translated(shift), touched, inside);
            return;
        case ShapeKind::Polygon:
            rasterizePolygon(grid, object.points.data(), object.points.size(), shift, touched,
                             inside);
            return;
        case ShapeKind::Mesh:
            rasterizeBox(grid, object.bounds.translated(shift), touched, [](int, int, int) {});
            return;
    }
}

}  // namespace

bool RgvcCuller::objectTouchesFrustum(const Scene& scene, int index) const {
    const SceneObject& object = scene.objects[size_t(index)];
    if (dimensions_ == 3) return boxMayIntersectFrustum(scene.boundsAt(object, t_), *camera_);
    if (object.shape == ShapeKind::Sphere)
        return circleMayIntersectWedge(object.center + scene.displacementAt(object, t_),
                                       object.radius, *camera_);
    return boxMayIntersectWedge(scene.boundsAt(object, t_), *camera_);
}

void RgvcCuller::rasterize2d(const SceneObject& object, const glm::dvec3& shift, int index,
                             bool is_static, bool during_traversal) {
    IdListMatrix& ids = is_static ? identifiers_static_ : identifiers_dynamic_;
    BitMatrix& opaque = is_static ? static_occluder_ : occluder_;
    rasterizeObject(
        grid_, object, shift,
        [&](int y, int x0, int x1) {
            for (int x = x0; x <= x1; ++x) {
                ids.add(x, y, int32_t(index));
                // The traversal has passed this voxel non-occluded and will not
                // come back: it would have found the object there.
                if (during_traversal && open_.get(x, y)) addToPvs(index);
            }
        },
        [&](int y, int x0, int x1) {
            if (during_traversal && snapshot_enabled_)
                for (int x = x0; x <= x1; ++x) noteOpaque(x, y);
            opaque.setRun(y, x0, x1);
        });
}

void RgvcCuller::discretizeStatic(const Scene& scene) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (object.isDynamic()) continue;
        if (dimensions_ == 2)
            rasterize2d(object, glm::dvec3(0.0), int(i), true, false);
        else
            rasterize3d(object, glm::dvec3(0.0), int(i), true, false);
        if (!insideWorld(object.bounds, grid_.world, dimensions_))
            static_outside_.push_back(int(i));
    }
}

void RgvcCuller::discretizeObject(const Scene& scene, int index, bool during_traversal) {
    const SceneObject& object = scene.objects[size_t(index)];
    const glm::dvec3 shift = scene.displacementAt(object, t_);
    ++object_updates_;
    if (dimensions_ == 2)
        rasterize2d(object, shift, index, false, during_traversal);
    else
        rasterize3d(object, shift, index, false, during_traversal);
    if (!insideWorld(object.bounds.translated(shift), grid_.world, dimensions_) &&
        objectTouchesFrustum(scene, index))
        addToPvs(index);
}

}  // namespace gridcull
