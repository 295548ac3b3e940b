// The life cycle of regular-grid culling's temporal bounding volumes (Batagelo &
// Wu, sections 4.1 and 5.2, after Sudarsky & Gotsman): made when an object
// leaves the PVS, renewed when its validity runs out, dropped when the
// traversal reveals it. The bookkeeping (each object's state, validity period
// and expiry, the expiration queue, V) is the shared TBV manager's
// (culling/tbv/tbv_manager.h); this file writes TBVs into T and takes them
// out. One implementation for both dimensions; only the TBV's shape differs: a
// digital circle in T (2D, rgvc_tbv.h), a box's projections in Txy, Txz and
// Tyz (3D, rgvc_tbv3d.h). rgvc_culler.h says where this departs from the paper.
#include <algorithm>
#include <cmath>
#include <limits>

#include "culling/baseline/frustum_tests.h"
#include "culling/rgvc/rgvc_culler.h"
#include "culling/rgvc/rgvc_tbv3d.h"

namespace gridcull {

namespace {

// Shrinks `box` to its intersection with `limit` (an empty result keeps
// min > max on some axis).
Aabb intersect(const Aabb& box, const Aabb& limit) {
    return {glm::max(box.min, limit.min), glm::min(box.max, limit.max)};
}

bool insideBox(const Aabb& inner, const Aabb& outer, int axes) {
    for (int a = 0; a < axes; ++a)
        if (inner.min[a] < outer.min[a] || inner.max[a] > outer.max[a]) return false;
    return true;
}

}  // namespace

void RgvcCuller::shapeTbv(Tbv& b, double radius) {
    b.radius = radius;
    if (dimensions_ == 2) b.curve = tbvCurveFor(grid_, b.centre, radius);
}

bool RgvcCuller::tbvMayEncloseViewer(const Tbv& b) const {
    if (dimensions_ == 2)
        return b.cells.contains({viewer_.x, viewer_.y, 0}) && tbvCurveMayEnclose(b.curve, viewer_);
    return b.cells.contains(viewer3_);
}

TbvShape RgvcCuller::makeTbv(const Scene& scene, int index, double& validity, bool write) {
    const SceneObject& object = scene.objects[size_t(index)];
    Tbv& b = tbv_[size_t(index)];
    const double speed = max_speed_[size_t(index)];
    const glm::dvec3 shift = scene.displacementAt(object, t_);
    const double base = dimensions_ == 2 ? bound_radius_[size_t(index)] : 0.0;
    // A hair of extra size so that rounding never leaves the object outside.
    const double scale = std::max({voxel_size_.x, voxel_size_.y, voxel_size_.z, base});
    const double pad = 1e-9 * scale;
    // The manager's period (spread, adapted); an object that cannot move keeps
    // its TBV for ever. A TBV made at a frame's end (not written now) first
    // serves the next frame: its period counts from there, as the paper's,
    // made in the next frame's step 1, would (one frame longer from now).
    const double lead = write ? 0.0 : scene.dt;
    if (!(speed > 0.0))
        validity = std::numeric_limits<double>::infinity();
    else
        validity += lead;
    b.centre = object.anchor + shift;
    // 2D: a disc around the anchor, cut to where the object can ever be. 3D:
    // the object's bounds now grown on every side (a cube of motion), cut so.
    const Aabb& reach = reach_[size_t(index)];
    const Aabb now = object.bounds.translated(shift);
    auto grown = [&](double v) { return base + (speed > 0.0 ? speed * v : 0.0) + pad; };
    auto reshape = [&](double v) {
        shapeTbv(b, grown(v));
        if (dimensions_ == 2) {
            b.cells = voxelBoxTouching(grid_, reach);
        } else {
            const glm::dvec3 g(b.radius);
            b.cells = voxelBoxTouching(grid_, intersect({now.min - g, now.max + g}, reach));
        }
    };
    reshape(validity);
    b.filled = false;
    if (tbvMayEncloseViewer(b)) {
        // The paper's condition: choose the validity so that the TBV leaves the
        // viewer's voxel outside; if not even one frame is left, write it filled.
        double largest;
        if (dimensions_ == 2) {
            largest = tbvLargestRadiusExcluding(grid_, b.centre, viewer_) - base;
        } else {
            // The box excludes the viewer's voxel while, on some axis, the growth
            // stays short of the gap between the object and that voxel.
            largest = -1.0;
            for (int a = 0; a < 3; ++a) {
                const double v0 = grid_.world.min[a] + double(viewer3_[a]) * voxel_size_[a];
                const double gap = std::max(v0 - now.max[a], now.min[a] - (v0 + voxel_size_[a]));
                largest = std::max(largest, gap - 3e-6 * voxel_size_[a]);
            }
        }
        const double shorter = speed > 0.0 ? (largest - pad) / speed : -1.0;
        if (shorter >= scene.dt + lead && shorter < validity) {
            validity = shorter;
            reshape(validity);
        }
        b.filled = tbvMayEncloseViewer(b);
    }
    if (dimensions_ == 2) {
        b.edge = !reach_in_grid_[size_t(index)] && !tbvCurveInsideGrid(grid_, b.curve);
        if (write) writeTbv(index, true);
        // What the manager keeps: the disc itself.
        return sphereTbv(2, b.centre, b.radius, 0.0, 0.0);
    }
    const glm::dvec3 g(b.radius);
    const Aabb cube = intersect({now.min - g, now.max + g}, reach);
    b.edge = !reach_in_grid_[size_t(index)] && !insideBox(cube, grid_.world, 3);
    b.box = cube;
    if (write) writeTbv(index, true);
    // What the manager keeps: the cut cube itself.
    TbvShape shape;
    shape.kind = TbvShapeKind::Box;
    shape.dimensions = 3;
    shape.box = {cube.min, cube.max};
    shape.centre = 0.5 * (cube.min + cube.max);
    return shape;
}

void RgvcCuller::writeTbv(int index, bool add) {
    Tbv& b = tbv_[size_t(index)];
    if (b.edge) {
        if (add) {
            b.edge_slot = int(edge_tbvs_.size());
            edge_tbvs_.push_back(index);
        } else {
            const int last = edge_tbvs_.back();
            edge_tbvs_[size_t(b.edge_slot)] = last;
            tbv_[size_t(last)].edge_slot = b.edge_slot;
            edge_tbvs_.pop_back();
            b.edge_slot = -1;
        }
        return;
    }
    // Adding records each node written; removing takes those nodes out in O(1)
    // each (a cell of T may hold many TBVs' ids).
    std::vector<uint64_t>& nodes = tbv_nodes_[size_t(index)];
    IdListMatrix* planes[3] = {&tbv_matrix_, &tbv_xz_, &tbv_yz_};
    if (!add) {
        for (const uint64_t node : nodes)
            planes[node >> 32]->removeNode(int32_t(node & 0xffffffffu));
        nodes.clear();
        return;
    }
    const int32_t id = int32_t(index);
    auto put = [&](int plane, int x, int y) {
        nodes.push_back((uint64_t(plane) << 32) |
                        uint64_t(uint32_t(planes[plane]->addNode(x, y, id))));
    };
    if (dimensions_ == 3) {
        forEachTbvProjectionCell(b.cells, b.filled,
                                 [&](TbvPlane plane, int a, int c) { put(int(plane), a, c); });
    } else if (b.filled) {
        forEachTbvFilledSpanClipped(b.curve, b.cells, [&](int y, int x0, int x1) {
            for (int x = x0; x <= x1; ++x) put(0, x, y);
        });
    } else {
        forEachTbvBoundaryVoxelClipped(b.curve, b.cells, [&](int x, int y) { put(0, x, y); });
    }
}

void RgvcCuller::revealTbv(const Scene& scene, int index, bool during_traversal) {
    if (!tbvs_.hasTbv(index)) return;
    if (snapshot_enabled_)
        snapshot_.reveals.push_back(
            RgvcRevealView{during_traversal ? int32_t(current_layer_) : -1, tbvView(scene, index)});
    // del_TBV and upd_vis: the period halves, the object joins V and is
    // written into O and I at once.
    tbvs_.reveal(index);
    writeTbv(index, false);
    discretizeObject(scene, index, during_traversal);
}

void RgvcCuller::handleDynamicObjects(const Scene& scene, bool teleported) {
    // Every dynamic object is, each frame, either in V (written into O and I)
    // or under a TBV. The last frame ended with V = the objects of V in its PVS
    // (the others got TBVs then, criterion 1); the others are touched only
    // when their TBV expires or is revealed.
    // The TBVs the last frame made go into T first: this frame may drop them.
    for (const int index : unwritten_) writeTbv(index, true);
    unwritten_.clear();
    renewals_.clear();
    tbvs_.beginFrame(t_, [&](int index, TbvDropReason) {
        writeTbv(index, false);
        renewals_.push_back(index);
    });
    // Criterion 2: still hidden, TBV expired: a new validity period from where
    // the object is now, without looking at it (the paper's renewal; Sudarsky
    // & Gotsman would write it into O and I and test it).
    for (const int index : renewals_)
        tbvs_.renew(index,
                    [&](int i, double& validity) { return makeTbv(scene, i, validity, true); });
    for (const int index : tbvs_.objectsToUpdate()) {
        tbvs_.updVis(index);
        discretizeObject(scene, index, false);
    }
    if (teleported) {
        // The viewer's voxel jumped: it may have landed inside a boundary TBV
        // without stepping on its boundary. Rare, so a pass over all of them.
        for (const int index : dynamic_) {
            if (!tbvs_.hasTbv(index)) continue;
            const Tbv& b = tbv_[size_t(index)];
            if (!b.edge && !b.filled && tbvMayEncloseViewer(b)) revealTbv(scene, index, false);
        }
    }
    // TBVs of objects that can leave the grid: revealed when they touch the
    // frustum. Backwards, because revealing moves the last entry into the freed
    // slot.
    for (size_t i = edge_tbvs_.size(); i-- > 0;) {
        const int index = edge_tbvs_[i];
        const Tbv& b = tbv_[size_t(index)];
        const bool touches = dimensions_ == 2
                                 ? circleMayIntersectWedge(b.centre, b.radius, *camera_)
                                 : boxMayIntersectFrustum(b.box, *camera_);
        if (touches) revealTbv(scene, index, false);
    }
}

}  // namespace gridcull
