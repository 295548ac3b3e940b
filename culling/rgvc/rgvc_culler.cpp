// `rgvc`: regular-grid culling after Batagelo & Wu (SIBGRAPI 2002), sections 3
// to 5; the frame loop, the PVS and the snapshot, for both dimensions. rgvc_culler.h lists the
// steps, where they live and where this departs from the paper.
#include "culling/rgvc/rgvc_culler.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "culling/baseline/frustum_tests.h"
#include "culling/scene/mesh_interior.h"
#include "culling/scene/motion_bounds.h"
#include "grid/chess_ring.h"

namespace gridcull {

const DebugSnapshotKind RgvcSnapshot::kKind{"rgvc"};

RgvcCuller::RgvcCuller(const RgvcOptions& options) : options_(options) {
    if (!(options_.validity_s > 0.0) || !std::isfinite(options_.validity_s))
        options_.validity_s = RgvcOptions{}.validity_s;
}

std::unique_ptr<Culler> RgvcCuller::clone() const {
    auto copy = std::make_unique<RgvcCuller>(*this);
    // inner_boxes_ point into mesh_interiors_: the copy's into its own.
    for (size_t i = 0; i < inner_boxes_.size(); ++i) {
        if (!inner_boxes_[i]) continue;
        for (size_t k = 0; k < mesh_interiors_.size(); ++k)
            if (inner_boxes_[i] == &mesh_interiors_[k].second)
                copy->inner_boxes_[i] = &copy->mesh_interiors_[k].second;
    }
    // The snapshot points into this culler's matrices; the copy fills its own.
    copy->snapshot_ = RgvcSnapshot{};
    return copy;
}

void RgvcCuller::reset(const Scene& scene) {
    ready_ = true;
    dimensions_ = scene.dimensions;
    object_count_ = scene.objects.size();
    frame_ = 0;
    last_t_ = 0.0;
    grid_ = scene.grid;
    snapshot_ = RgvcSnapshot{};
    if (dimensions_ != 2 && dimensions_ != 3) return;
    const int axes = dimensions_;
    if (options_.grid_resolution > 0) {
        const glm::dvec3 extent = grid_.world.extent();
        double longest = 0.0;
        for (int a = 0; a < axes; ++a) longest = std::max(longest, extent[a]);
        glm::ivec3 res{1, 1, 1};
        for (int a = 0; a < axes; ++a)
            res[a] = std::max(1, int(std::lround(options_.grid_resolution * extent[a] / longest)));
        if (checkResolution(dimensions_, res).empty()) grid_.resolution = res;
    }
    voxel_size_ = grid_.voxelSize();
    const int w = grid_.resolution.x, h = grid_.resolution.y;
    const int d = dimensions_ == 3 ? grid_.resolution.z : 1;

    const size_t n = scene.objects.size();
    dynamic_.clear();
    static_outside_.clear();
    max_speed_.assign(n, 0.0);
    bound_radius_.assign(n, 0.0);
    reach_.assign(n, Aabb{});
    reach_in_grid_.assign(n, 0);
    inner_boxes_.assign(n, nullptr);
    pvs_stamp_.assign(n, 0);
    rejected_stamp_.assign(n, 0);
    tbv_.assign(n, Tbv{});
    // Each TBV's node list keeps the capacity it grew (reused by a reset on the
    // same scene).
    tbv_nodes_.resize(n);
    for (std::vector<uint64_t>& nodes : tbv_nodes_) nodes.clear();
    tbv_seen_.assign(n, 0);
    tbv_test_ = 0;
    // Spread periods (spreadValidity) so that TBVs made together do not
    // expire together, never below the floor: one frame (and a hair, so that
    // t + dt rounds past the next frame's time), or --rgvc-validity if shorter.
    TbvManagerOptions tbv;
    tbv.mode = TbvUpdateMode::Explicit;
    tbv.validity_mode =
        options_.adaptive_validity ? TbvValidityMode::Adaptive : TbvValidityMode::Fixed;
    tbv.initial_validity = options_.validity_s;
    tbv.validity_floor = scene.dt * (1.0 + 1e-9);
    tbv.spread_validity = true;
    tbvs_.reset(n, tbv);
    renewals_.clear();
    renewals_.reserve(n);
    unwritten_.clear();
    unwritten_.reserve(n);
    edge_tbvs_.clear();
    has_static_ = has_dynamic_ = false;
    mesh_interiors_.clear();
    for (size_t i = 0; i < n; ++i) {
        const SceneObject& object = scene.objects[i];
        max_speed_[i] = maxSpeedOf(object);
        if (dimensions_ == 2) bound_radius_[i] = boundingRadiusOf(object, 2);
        reach_[i] = reachOf(object, grid_.world, dimensions_);
        bool in = true;
        for (int a = 0; a < axes; ++a)
            in = in && reach_[i].min[a] >= grid_.world.min[a] &&
                 reach_[i].max[a] <= grid_.world.max[a];
        reach_in_grid_[i] = in;
        if (object.isDynamic()) {
            dynamic_.push_back(int(i));
            tbvs_.addDynamic(int(i));
            has_dynamic_ = true;
        } else {
            has_static_ = true;
        }
    }
    if (dimensions_ == 3) {
        // One interior per distinct mesh (copies share theirs), made here once.
        for (size_t i = 0; i < n; ++i) {
            const SceneObject& object = scene.objects[i];
            if (object.shape != ShapeKind::Mesh || !object.mesh) continue;
            const TriangleMesh* mesh = object.mesh.get();
            auto it = std::find_if(mesh_interiors_.begin(), mesh_interiors_.end(),
                                   [&](const auto& e) { return e.first == mesh; });
            if (it == mesh_interiors_.end()) {
                mesh_interiors_.emplace_back(mesh, meshInteriorBoxes(*mesh));
                it = mesh_interiors_.end() - 1;
            }
        }
        for (size_t i = 0; i < n; ++i) {
            const SceneObject& object = scene.objects[i];
            if (object.shape != ShapeKind::Mesh || !object.mesh) continue;
            for (const auto& entry : mesh_interiors_)
                if (entry.first == object.mesh.get()) inner_boxes_[i] = &entry.second;
        }
    }
    occluder_.resize(w, h, d);
    occlusion_.resize(w, h, d);
    open_.resize(w, h, d);
    // Os only with static objects. The id-list matrices take memory on their first
    // add, so I's two parts and T cost nothing where the scene writes nothing.
    if (has_static_)
        static_occluder_.resize(w, h, d);
    else
        static_occluder_.release();
    // resize() keeps a matrix's storage for the same grid, so a reset on the
    // same scene reuses what the last run grew; a matrix this scene does not
    // write is released first, so it holds nothing (it keeps its shape for reads).
    if (!has_static_) identifiers_static_.release();
    identifiers_static_.resize(w, h, false, d);
    if (!has_dynamic_) identifiers_dynamic_.release();
    identifiers_dynamic_.resize(w, h, true, d);
    if (dimensions_ == 3) {
        holds_static_.resize(w, h, d);
        holds_dynamic_.resize(w, h, d);
    } else {
        holds_static_.release();
        holds_dynamic_.release();
    }
    if (!has_dynamic_) {
        tbv_matrix_.release();
        tbv_xz_.release();
        tbv_yz_.release();
    }
    tbv_matrix_.resize(w, h, false, 1, true);
    if (dimensions_ == 3) {
        tbv_xz_.resize(w, d, false, 1, true);
        tbv_yz_.resize(h, d, false, 1, true);
        direction_map_.resize(RgvcDirectionMap::resolutionFor(std::max({w, h, d})));
        direction_pass_ = direction_map_.restartPasses();
        layer_occluders_.reserve(size_t(w) * size_t(h) + size_t(h) * size_t(d) +
                                 size_t(w) * size_t(d));
    } else {
        tbv_xz_.release();
        tbv_yz_.release();
        direction_map_ = RgvcDirectionMap{};
    }
    discretizeStatic(scene);
}

void RgvcCuller::addToPvs(int index) {
    if (pvs_stamp_[size_t(index)] == frame_ || rejected_stamp_[size_t(index)] == frame_) return;
    // A voxel in the frustum may hold an object that is not: the object's own
    // frustum test (as vfc's) keeps it out.
    if (!objectTouchesFrustum(*scene_, index)) {
        rejected_stamp_[size_t(index)] = frame_;
        return;
    }
    pvs_stamp_[size_t(index)] = frame_;
    out_->pvs.push_back(index);
    // Seen: stays in V. (An object under a TBV joins the PVS only when the
    // traversal is replaced by the frustum alone; its TBV stays.)
    if (tbvs_.isDynamic(index) && tbvs_.inV(index)) tbvs_.observe(index);
}

void RgvcCuller::setUpFrame2d(const Camera& camera, bool& unreachable, bool& teleported) {
    wedge_.set(camera, voxel_size_);
    const glm::ivec3 v = grid_.voxelOf(camera.position);
    viewer_ = {v.x, v.y};
    // voxelOf clamps beyond 1e9 voxels: the viewer's voxel then no longer holds
    // the viewpoint and the chess layers mean nothing.
    unreachable = std::abs(v.x) >= 900000000 || std::abs(v.y) >= 900000000;
    teleported = frame_ > 1 && chessDistance(viewer_ - last_viewer_) > 1;
    const glm::dvec3 fwd = camera.forward();
    line_of_sight_ = BresenhamLine::towards(fwd.x / voxel_size_.x, fwd.y / voxel_size_.y);
    double x0, y0, x1, y1;
    wedge_.bounds(x0, y0, x1, y1);
    const glm::dvec3& o = grid_.world.min;
    auto cell = [](double u, int hi) { return int(std::clamp(std::floor(u), -1.0, double(hi))); };
    clip_x0_ = std::max(0, cell((x0 - o.x) / voxel_size_.x, grid_.resolution.x));
    clip_x1_ =
        std::min(grid_.resolution.x - 1, cell((x1 - o.x) / voxel_size_.x, grid_.resolution.x));
    clip_y0_ = std::max(0, cell((y0 - o.y) / voxel_size_.y, grid_.resolution.y));
    clip_y1_ =
        std::min(grid_.resolution.y - 1, cell((y1 - o.y) / voxel_size_.y, grid_.resolution.y));
}

void RgvcCuller::setUpFrame3d(const Camera& camera, bool& unreachable, bool& teleported) {
    frustum3_.set(camera, grid_);
    const glm::ivec3 v = grid_.voxelOf(camera.position);
    viewer3_ = glm::i64vec3(v);
    unreachable = false;
    for (int a = 0; a < 3; ++a) unreachable = unreachable || std::abs(v[a]) >= 900000000;
    const glm::i64vec3 step = viewer3_ - last_viewer3_;
    teleported =
        frame_ > 1 && std::max({std::llabs(step.x), std::llabs(step.y), std::llabs(step.z)}) > 1;
    const glm::dvec3 fwd = camera.forward();
    line_of_sight3_ = BresenhamLine3::towards(fwd.x / voxel_size_.x, fwd.y / voxel_size_.y,
                                              fwd.z / voxel_size_.z);
    eye_in_grid_ = grid_.world.contains(camera.position);
    direction_map_.begin(camera.position);
    direction_map_.setFrustum(frustum3_.edgeDirections());
    direction_covered_ = false;
}

void RgvcCuller::cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) {
    out.pvs.clear();
    out.stats = CullStats{};
    if (scene.dimensions != 2 && scene.dimensions != 3) {
        // No grid for such a scene: view-frustum culling of the bounds, which is
        // conservative.
        for (const SceneObject& object : scene.objects)
            if (boxMayIntersectFrustum(scene.boundsAt(object, t), camera))
                out.pvs.push_back(object.id);
        std::sort(out.pvs.begin(), out.pvs.end());
        return;
    }
    if (!ready_ || scene.dimensions != dimensions_ || scene.objects.size() != object_count_ ||
        (frame_ > 0 && t < last_t_))
        reset(scene);
    ++frame_;
    t_ = t;
    out_ = &out;
    camera_ = &camera;
    scene_ = &scene;
    voxels_visited_ = object_updates_ = 0;
    bool unreachable = false, teleported = false;
    if (dimensions_ == 2)
        setUpFrame2d(camera, unreachable, teleported);
    else
        setUpFrame3d(camera, unreachable, teleported);

    // Step 1: scene discretization (s4.1, s4.5, s5.1).
    if (has_static_)
        occluder_.copyFrom(static_occluder_);
    else
        occluder_.clearAll();
    occlusion_.clearAll();
    open_.clearAll();
    identifiers_dynamic_.clear();
    if (dimensions_ == 3) holds_dynamic_.clearAll();
    current_layer_ = -1;
    fillSnapshotFrame(camera);
    for (const int index : static_outside_)
        if (objectTouchesFrustum(scene, index)) addToPvs(index);
    handleDynamicObjects(scene, teleported);

    // Steps 2 to 4: traversal with occluder extension and occlusion.
    if (unreachable) {
        for (size_t i = 0; i < scene.objects.size(); ++i)
            if (objectTouchesFrustum(scene, int(i))) addToPvs(int(i));
    } else if (dimensions_ == 2) {
        traverse(scene);
    } else {
        traverse3d(scene);
    }

    // The snapshot's TBVs are T as the traversal saw it.
    if (snapshot_enabled_) {
        snapshot_.tbv_list.clear();
        for (const int index : dynamic_)
            if (hasTbv(index)) snapshot_.tbv_list.push_back(tbvView(scene, index));
    }
    // Criterion 1 (the manager's step 4): the objects of V that left the PVS
    // get a TBV, against this frame's viewer voxel; T gets them at the next
    // frame's start.
    tbvs_.endFrame([&](int index, double& validity) {
        const TbvShape shape = makeTbv(scene, index, validity, false);
        unwritten_.push_back(index);
        return shape;
    });

    for (int& entry : out.pvs) entry = scene.objects[size_t(entry)].id;
    std::sort(out.pvs.begin(), out.pvs.end());
    const TbvFrameCounters& c = tbvs_.frameCounters();
    out.stats.set(Counter::VoxelsVisited, voxels_visited_);
    out.stats.set(Counter::TbvCreated, c.tbv_created);
    out.stats.set(Counter::TbvExpired, c.tbv_expired);
    out.stats.set(Counter::TbvRevealed, c.tbv_revealed);
    out.stats.set(Counter::ObjectUpdates, object_updates_);

    last_viewer_ = viewer_;
    last_viewer3_ = viewer3_;
    last_t_ = t;
    snapshot_.memory = memory();
    out_ = nullptr;
    camera_ = nullptr;
    scene_ = nullptr;
}

void RgvcCuller::fillSnapshotFrame(const Camera& camera) {
    snapshot_.valid = snapshot_enabled_;
    if (!snapshot_enabled_) return;
    snapshot_.dimensions = dimensions_;
    snapshot_.frame = frame_;
    snapshot_.t = t_;
    snapshot_.grid = grid_;
    snapshot_.viewpoint = camera.position;
    snapshot_.forward = camera.forward();
    snapshot_.fov_deg = camera.fov_deg;
    snapshot_.far = camera.far;
    if (dimensions_ == 2) {
        snapshot_.viewer_voxel = viewer_;
        snapshot_.viewer_voxel_z = 0;
    } else {
        snapshot_.viewer_voxel = {viewer3_.x, viewer3_.y};
        snapshot_.viewer_voxel_z = viewer3_.z;
    }
    snapshot_.occluder = &occluder_;
    snapshot_.static_occluder = has_static_ ? &static_occluder_ : nullptr;
    snapshot_.occlusion = &occlusion_;
    snapshot_.identifiers_static = &identifiers_static_;
    snapshot_.identifiers_dynamic = &identifiers_dynamic_;
    snapshot_.tbvs = has_dynamic_ ? &tbv_matrix_ : nullptr;
    snapshot_.tbvs_xz = has_dynamic_ && dimensions_ == 3 ? &tbv_xz_ : nullptr;
    snapshot_.tbvs_yz = has_dynamic_ && dimensions_ == 3 ? &tbv_yz_ : nullptr;
    snapshot_.direction_map = dimensions_ == 3 ? &direction_map_ : nullptr;
    snapshot_.visits.clear();
    snapshot_.seeds.clear();
    snapshot_.occluders.clear();
    snapshot_.occluders3d.clear();
    snapshot_.tbv_list.clear();
    snapshot_.reveals.clear();
    const size_t voxels = size_t(grid_.voxelCount());
    snapshot_.h_layer.assign(voxels, kRgvcNoLayer);
    snapshot_.o_layer.assign(voxels, kRgvcNoLayer);
    snapshot_.h_cause.assign(voxels, -1);
    if (dimensions_ == 3) {
        const size_t r = size_t(direction_map_.resolution());
        snapshot_.direction_cause.assign(6 * r * r, -1);
    } else {
        snapshot_.direction_cause.clear();
    }
    snapshot_.first_layer = 0;
    snapshot_.last_layer = -1;
    snapshot_.terminated_early = false;
}

RgvcTbvView RgvcCuller::tbvView(const Scene& scene, int index) const {
    const Tbv& b = tbv_[size_t(index)];
    RgvcTbvView view;
    view.object_index = index;
    view.object_id = scene.objects[size_t(index)].id;
    view.centre = b.centre;
    view.radius = b.radius;
    const TbvRecord& record = tbvs_.tbv(index);
    view.created = record.created;
    view.expiry = record.expiry;
    view.curve_centre = b.curve.centre;
    view.curve_radius = b.curve.radius;
    view.filled = b.filled;
    view.edge = b.edge;
    view.cells = b.cells;
    return view;
}

void RgvcCuller::noteOccluded(int x, int row, int32_t cause) {
    // Rows are y + z * height, and linear indices x + width * (y + height * z).
    const size_t v = size_t(row) * size_t(grid_.resolution.x) + size_t(x);
    if (snapshot_.h_layer[v] != kRgvcNoLayer) return;
    snapshot_.h_layer[v] = int32_t(current_layer_);
    snapshot_.h_cause[v] = cause;
}

void RgvcCuller::noteOpaque(int x, int row) {
    const size_t v = size_t(row) * size_t(grid_.resolution.x) + size_t(x);
    if (snapshot_.o_layer[v] == kRgvcNoLayer && !occluder_.get(x, row))
        snapshot_.o_layer[v] = int32_t(current_layer_);
}

RgvcMatrixMemory RgvcCuller::memory() const {
    RgvcMatrixMemory m;
    m.occluder = occluder_.memoryBytes();
    m.static_occluder = static_occluder_.memoryBytes();
    m.occlusion = occlusion_.memoryBytes();
    m.identifiers_static = identifiers_static_.memoryBytes();
    m.identifiers_dynamic = identifiers_dynamic_.memoryBytes();
    m.tbv = tbv_matrix_.memoryBytes() + tbv_xz_.memoryBytes() + tbv_yz_.memoryBytes();
    m.traversal = open_.memoryBytes() + holds_static_.memoryBytes() + holds_dynamic_.memoryBytes();
    m.direction_map = direction_map_.memoryBytes();
    return m;
}

}  // namespace gridcull
