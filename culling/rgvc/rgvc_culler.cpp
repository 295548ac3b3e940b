// `rgvc`: regular-grid culling after Batagelo & Wu (SIBGRAPI 2002), sections 3
// and 4; the frame loop, the PVS and the snapshot. rgvc_culler.h lists the
// steps, where they live and where this departs from the paper.
#include "culling/rgvc/rgvc_culler.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "culling/baseline/frustum_tests.h"
#include "grid/chess_ring.h"

namespace gridcull {

namespace {

// An upper bound of the object's speed: the declared or computed max_speed, and
// whatever its motion data imply (hand-built scenes may leave max_speed at 0).
double maxSpeedOf(const SceneObject& object) {
    const Motion& m = object.motion;
    double speed = m.max_speed;
    switch (m.kind) {
        case MotionKind::Static:
            return 0.0;
        case MotionKind::Linear:
            speed = std::max(speed, glm::length(m.velocity));
            break;
        case MotionKind::Random:
            for (const glm::dvec3& v : m.segment_velocities)
                speed = std::max(speed, glm::length(v));
            break;
        case MotionKind::Keyframes:
            for (size_t i = 1; i < m.keys.size(); ++i) {
                const double span = m.keys[i].t - m.keys[i - 1].t;
                const double dist = glm::length(m.keys[i].position - m.keys[i - 1].position);
                if (span > 0.0) speed = std::max(speed, dist / span);
            }
            break;
    }
    return speed;
}

// The radius around the object's anchor that holds the whole shape.
double boundingRadiusOf(const SceneObject& object) {
    const glm::dvec3 a = object.anchor;
    switch (object.shape) {
        case ShapeKind::Sphere:
            return object.radius + glm::length(object.center - a);
        case ShapeKind::Polygon: {
            double r = 0.0;
            for (const glm::dvec3& p : object.points) r = std::max(r, glm::length(p - a));
            return r;
        }
        case ShapeKind::Box:
        case ShapeKind::Mesh:
            break;
    }
    const Aabb& b = object.bounds;
    double r = 0.0;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 corner{(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, 0.0};
        r = std::max(r, glm::length(corner - glm::dvec3(a.x, a.y, 0.0)));
    }
    return r;
}

}  // namespace

const DebugSnapshotKind RgvcSnapshot::kKind{"rgvc"};

RgvcCuller::RgvcCuller(const RgvcOptions& options) : options_(options) {
    if (!(options_.validity_s > 0.0) || !std::isfinite(options_.validity_s))
        options_.validity_s = RgvcOptions{}.validity_s;
}

void RgvcCuller::reset(const Scene& scene) {
    ready_ = true;
    object_count_ = scene.objects.size();
    frame_ = 0;
    last_t_ = 0.0;
    grid_ = scene.grid;
    snapshot_ = RgvcSnapshot{};
    if (scene.dimensions != 2) return;
    if (options_.grid_resolution > 0) {
        const glm::dvec3 extent = grid_.world.extent();
        const double longest = std::max(extent.x, extent.y);
        glm::ivec3 res{1, 1, 1};
        for (int axis = 0; axis < 2; ++axis)
            res[axis] =
                std::max(1, int(std::lround(options_.grid_resolution * extent[axis] / longest)));
        if (checkResolution(2, res).empty()) grid_.resolution = res;
    }
    voxel_size_ = grid_.voxelSize();
    const int w = grid_.resolution.x, h = grid_.resolution.y;

    const size_t n = scene.objects.size();
    dynamic_.clear();
    static_outside_.clear();
    max_speed_.assign(n, 0.0);
    bound_radius_.assign(n, 0.0);
    in_last_pvs_.assign(n, 0);
    pvs_stamp_.assign(n, 0);
    tbv_.assign(n, Tbv{});
    edge_tbvs_.clear();
    has_static_ = has_dynamic_ = false;
    for (size_t i = 0; i < n; ++i) {
        const SceneObject& object = scene.objects[i];
        max_speed_[i] = maxSpeedOf(object);
        bound_radius_[i] = boundingRadiusOf(object);
        if (object.isDynamic()) {
            dynamic_.push_back(int(i));
            has_dynamic_ = true;
        } else {
            has_static_ = true;
        }
    }
    occluder_.resize(w, h);
    occlusion_.resize(w, h);
    open_.resize(w, h);
    // Os only with static objects. The id-list matrices take memory on their first
    // add, so I's two parts and T cost nothing where the scene writes nothing.
    if (has_static_)
        static_occluder_.resize(w, h);
    else
        static_occluder_.release();
    identifiers_static_.resize(w, h, false);
    identifiers_dynamic_.resize(w, h, true);
    tbv_matrix_.resize(w, h, false);
    discretizeStatic(scene);
}

void RgvcCuller::addToPvs(int index) {
    if (pvs_stamp_[size_t(index)] == frame_) return;
    pvs_stamp_[size_t(index)] = frame_;
    out_->pvs.push_back(index);
}

void RgvcCuller::cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) {
    out.pvs.clear();
    out.stats = CullStats{};
    if (scene.dimensions != 2) {
        // The registry offers rgvc for 2D scenes only; a caller that culls a 3D
        // scene anyway gets view-frustum culling of the bounds, which is
        // conservative.
        for (const SceneObject& object : scene.objects)
            if (boxMayIntersectFrustum(scene.boundsAt(object, t), camera))
                out.pvs.push_back(object.id);
        std::sort(out.pvs.begin(), out.pvs.end());
        return;
    }
    if (!ready_ || scene.objects.size() != object_count_ || (frame_ > 0 && t < last_t_))
        reset(scene);
    ++frame_;
    t_ = t;
    out_ = &out;
    camera_ = &camera;
    voxels_visited_ = tbv_created_ = tbv_expired_ = tbv_revealed_ = object_updates_ = 0;

    wedge_.set(camera, voxel_size_);
    const glm::ivec3 v = grid_.voxelOf(camera.position);
    viewer_ = {v.x, v.y};
    // voxelOf clamps beyond 1e9 voxels: the viewer's voxel then no longer holds
    // the viewpoint and the chess layers mean nothing.
    const bool unreachable = std::abs(v.x) >= 900000000 || std::abs(v.y) >= 900000000;
    const bool teleported = frame_ > 1 && chessDistance(viewer_ - last_viewer_) > 1;
    const glm::dvec3 fwd = camera.forward();
    line_of_sight_ = BresenhamLine::towards(fwd.x / voxel_size_.x, fwd.y / voxel_size_.y);
    {
        double x0, y0, x1, y1;
        wedge_.bounds(x0, y0, x1, y1);
        const glm::dvec3& o = grid_.world.min;
        auto cell = [](double u, int hi) {
            return int(std::clamp(std::floor(u), -1.0, double(hi)));
        };
        clip_x0_ = std::max(0, cell((x0 - o.x) / voxel_size_.x, grid_.resolution.x));
        clip_x1_ =
            std::min(grid_.resolution.x - 1, cell((x1 - o.x) / voxel_size_.x, grid_.resolution.x));
        clip_y0_ = std::max(0, cell((y0 - o.y) / voxel_size_.y, grid_.resolution.y));
        clip_y1_ =
            std::min(grid_.resolution.y - 1, cell((y1 - o.y) / voxel_size_.y, grid_.resolution.y));
    }

    // Step 1: scene discretization (s4.1, s4.5).
    if (has_static_)
        occluder_.copyFrom(static_occluder_);
    else
        occluder_.clearAll();
    occlusion_.clearAll();
    open_.clearAll();
    identifiers_dynamic_.clear();
    fillSnapshotFrame(camera);
    for (const int index : static_outside_)
        if (objectTouchesFrustum(scene, index)) addToPvs(index);
    handleDynamicObjects(scene, teleported);

    // Steps 2 to 4: traversal with occluder extension and occlusion (s4.2 - s4.4).
    if (unreachable) {
        for (size_t i = 0; i < scene.objects.size(); ++i)
            if (objectTouchesFrustum(scene, int(i))) addToPvs(int(i));
    } else {
        traverse(scene);
    }

    for (const int index : dynamic_)
        in_last_pvs_[size_t(index)] = pvs_stamp_[size_t(index)] == frame_;
    for (int& entry : out.pvs) entry = scene.objects[size_t(entry)].id;
    std::sort(out.pvs.begin(), out.pvs.end());
    out.stats.set(Counter::VoxelsVisited, voxels_visited_);
    out.stats.set(Counter::TbvCreated, tbv_created_);
    out.stats.set(Counter::TbvExpired, tbv_expired_);
    out.stats.set(Counter::TbvRevealed, tbv_revealed_);
    out.stats.set(Counter::ObjectUpdates, object_updates_);

    last_viewer_ = viewer_;
    last_t_ = t;
    snapshot_.memory = memory();
    if (snapshot_enabled_) {
        snapshot_.tbv_list.clear();
        for (const int index : dynamic_) {
            const Tbv& b = tbv_[size_t(index)];
            if (!b.active) continue;
            RgvcTbvView view;
            view.object_index = index;
            view.object_id = scene.objects[size_t(index)].id;
            view.centre = b.centre;
            view.radius = b.radius;
            view.created = b.created;
            view.expiry = b.expiry;
            view.curve_centre = b.curve.centre;
            view.curve_radius = b.curve.radius;
            view.filled = b.filled;
            view.edge = b.edge;
            snapshot_.tbv_list.push_back(view);
        }
    }
    out_ = nullptr;
    camera_ = nullptr;
}

void RgvcCuller::fillSnapshotFrame(const Camera& camera) {
    snapshot_.valid = snapshot_enabled_;
    if (!snapshot_enabled_) return;
    snapshot_.frame = frame_;
    snapshot_.t = t_;
    snapshot_.grid = grid_;
    snapshot_.viewpoint = camera.position;
    snapshot_.forward = camera.forward();
    snapshot_.fov_deg = camera.fov_deg;
    snapshot_.far = camera.far;
    snapshot_.viewer_voxel = viewer_;
    snapshot_.occluder = &occluder_;
    snapshot_.static_occluder = has_static_ ? &static_occluder_ : nullptr;
    snapshot_.occlusion = &occlusion_;
    snapshot_.identifiers_static = &identifiers_static_;
    snapshot_.identifiers_dynamic = &identifiers_dynamic_;
    snapshot_.tbvs = has_dynamic_ ? &tbv_matrix_ : nullptr;
    snapshot_.visits.clear();
    snapshot_.seeds.clear();
    snapshot_.occluders.clear();
    snapshot_.tbv_list.clear();
    snapshot_.first_layer = 0;
    snapshot_.last_layer = -1;
    snapshot_.terminated_early = false;
}

RgvcMatrixMemory RgvcCuller::memory() const {
    RgvcMatrixMemory m;
    m.occluder = occluder_.memoryBytes();
    m.static_occluder = static_occluder_.memoryBytes();
    m.occlusion = occlusion_.memoryBytes();
    m.identifiers_static = identifiers_static_.memoryBytes();
    m.identifiers_dynamic = identifiers_dynamic_.memoryBytes();
    m.tbv = tbv_matrix_.memoryBytes();
    m.traversal = open_.memoryBytes();
    return m;
}

}  // namespace gridcull
