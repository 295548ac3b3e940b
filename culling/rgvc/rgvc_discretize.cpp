// Scene discretization of regular-grid culling (Batagelo & Wu, section 4.1, and
// section 4.5 for static objects) and the TBVs (after Sudarsky & Gotsman).
// rgvc_culler.h says where this departs from the paper.
#include <algorithm>
#include <cmath>
#include <limits>

#include "culling/baseline/frustum_tests.h"
#include "culling/rgvc/rgvc_culler.h"
#include "grid/conservative_raster.h"

namespace gridcull {

namespace {

bool insideWorld(const Aabb& bounds, const Aabb& world) {
    return bounds.min.x >= world.min.x && bounds.min.y >= world.min.y &&
           bounds.max.x <= world.max.x && bounds.max.y <= world.max.y;
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
    if (object.shape == ShapeKind::Sphere)
        return circleMayIntersectWedge(object.center + scene.displacementAt(object, t_),
                                       object.radius, *camera_);
    return boxMayIntersectWedge(scene.boundsAt(object, t_), *camera_);
}

void RgvcCuller::discretizeStatic(const Scene& scene) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (object.isDynamic()) continue;
        const int32_t index = int32_t(i);
        rasterizeObject(
            grid_, object, glm::dvec3(0.0),
            [&](int y, int x0, int x1) {
                for (int x = x0; x <= x1; ++x) identifiers_static_.add(x, y, index);
            },
            [&](int y, int x0, int x1) { static_occluder_.setRun(y, x0, x1); });
        if (!insideWorld(object.bounds, grid_.world)) static_outside_.push_back(int(i));
    }
}

void RgvcCuller::discretizeObject(const Scene& scene, int index, bool during_traversal) {
    const SceneObject& object = scene.objects[size_t(index)];
    const glm::dvec3 shift = scene.displacementAt(object, t_);
    ++object_updates_;
    rasterizeObject(
        grid_, object, shift,
        [&](int y, int x0, int x1) {
            for (int x = x0; x <= x1; ++x) {
                identifiers_dynamic_.add(x, y, index);
                // The traversal has passed this voxel non-occluded and will not
                // come back: it would have found the object there.
                if (during_traversal && open_.get(x, y)) addToPvs(index);
            }
        },
        [&](int y, int x0, int x1) { occluder_.setRun(y, x0, x1); });
    if (!insideWorld(object.bounds.translated(shift), grid_.world) &&
        objectTouchesFrustum(scene, index))
        addToPvs(index);
}

void RgvcCuller::createTbv(const Scene& scene, int index) {
    const SceneObject& object = scene.objects[size_t(index)];
    Tbv& b = tbv_[size_t(index)];
    const double speed = max_speed_[size_t(index)];
    const double base = bound_radius_[size_t(index)];
    // A hair of extra radius so that rounding never leaves the object outside.
    const double pad = 1e-9 * std::max({voxel_size_.x, voxel_size_.y, base});
    double validity = speed > 0.0 ? options_.validity_s : std::numeric_limits<double>::infinity();
    b.centre = object.anchor + scene.displacementAt(object, t_);
    b.radius = base + (speed > 0.0 ? speed * validity : 0.0) + pad;
    b.curve = tbvCurveFor(grid_, b.centre, b.radius);
    b.filled = false;
    if (tbvCurveMayEnclose(b.curve, viewer_)) {
        // The paper's condition: choose the validity so that the circle leaves the
        // viewpoint outside; if not even one frame is left, write it filled.
        const double largest = tbvLargestRadiusExcluding(grid_, b.centre, viewer_);
        const double shorter = speed > 0.0 ? (largest - base - pad) / speed : -1.0;
        if (shorter >= scene.dt && shorter < validity) {
            validity = shorter;
            b.radius = base + speed * validity + pad;
            b.curve = tbvCurveFor(grid_, b.centre, b.radius);
        }
        b.filled = tbvCurveMayEnclose(b.curve, viewer_);
    }
    b.active = true;
    b.created = t_;
    b.expiry = t_ + validity;
    b.edge = !tbvCurveInsideGrid(grid_, b.curve);
    ++tbv_created_;
    if (b.edge) {
        b.edge_slot = int(edge_tbvs_.size());
        edge_tbvs_.push_back(index);
        return;
    }
    const int32_t id = int32_t(index);
    if (b.filled) {
        forEachTbvFilledSpan(b.curve, [&](int y, int x0, int x1) {
            for (int x = x0; x <= x1; ++x) tbv_matrix_.add(x, y, id);
        });
    } else {
        forEachTbvBoundaryVoxel(b.curve, [&](int x, int y) { tbv_matrix_.add(x, y, id); });
    }
}

void RgvcCuller::removeTbv(int index) {
    Tbv& b = tbv_[size_t(index)];
    if (!b.active) return;
    b.active = false;
    if (b.edge) {
        const int last = edge_tbvs_.back();
        edge_tbvs_[size_t(b.edge_slot)] = last;
        tbv_[size_t(last)].edge_slot = b.edge_slot;
        edge_tbvs_.pop_back();
        b.edge_slot = -1;
        return;
    }
    const int32_t id = int32_t(index);
    if (b.filled) {
        forEachTbvFilledSpan(b.curve, [&](int y, int x0, int x1) {
            for (int x = x0; x <= x1; ++x) tbv_matrix_.remove(x, y, id);
        });
    } else {
        forEachTbvBoundaryVoxel(b.curve, [&](int x, int y) { tbv_matrix_.remove(x, y, id); });
    }
}

void RgvcCuller::revealTbv(const Scene& scene, int index, bool during_traversal) {
    removeTbv(index);
    ++tbv_revealed_;
    discretizeObject(scene, index, during_traversal);
}

void RgvcCuller::handleDynamicObjects(const Scene& scene, bool teleported) {
    for (const int index : dynamic_) {
        Tbv& b = tbv_[size_t(index)];
        if (frame_ == 1 || in_last_pvs_[size_t(index)]) {
            // Potentially visible last frame: into O and I at its position now.
            // (It has no TBV unless the last frame culled without the grid.)
            removeTbv(index);
            discretizeObject(scene, index, false);
        } else if (!b.active) {
            // Hidden since the last frame: it gets a TBV.
            createTbv(scene, index);
        } else if (t_ > b.expiry) {
            // Still hidden, TBV expired: a new validity period from where it is now.
            removeTbv(index);
            ++tbv_expired_;
            createTbv(scene, index);
        }
    }
    if (teleported) {
        // The viewer's voxel jumped: it may have landed inside a boundary TBV
        // without stepping on its curve.
        for (const int index : dynamic_) {
            const Tbv& b = tbv_[size_t(index)];
            if (b.active && !b.edge && !b.filled && tbvCurveMayEnclose(b.curve, viewer_))
                revealTbv(scene, index, false);
        }
    }
    // TBVs reaching outside the grid: revealed by their disc touching the frustum.
    // Backwards, because revealing moves the last entry into the freed slot.
    for (size_t i = edge_tbvs_.size(); i-- > 0;) {
        const int index = edge_tbvs_[i];
        const Tbv& b = tbv_[size_t(index)];
        if (circleMayIntersectWedge(b.centre, b.radius, *camera_)) revealTbv(scene, index, false);
    }
}

}  // namespace gridcull
