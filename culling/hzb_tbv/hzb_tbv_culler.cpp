// `hzb-tbv`, `hzb-tbvi`, `hzb`: Sudarsky & Gotsman, sections 3.3, 3.6 and 4;
// hzb_tbv_culler.h gives the frame's steps and the departures from the paper.
#include "culling/hzb_tbv/hzb_tbv_culler.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "culling/baseline/frustum_tests.h"
#include "culling/scene/motion_bounds.h"

namespace gridcull {

namespace {

Aabb toAabb(const TbvBox& b) {
    return {b.min, b.max};
}

TbvBox toTbvBox(const Aabb& b) {
    return {b.min, b.max};
}

}  // namespace

HzbTbvCuller::HzbTbvCuller(std::string name, bool use_tbvs, TbvUpdateMode mode,
                           const HzbTbvOptions& options, int reference_resolution)
    : name_(std::move(name)),
      use_tbvs_(use_tbvs),
      mode_(mode),
      options_(options),
      resolution_(options.resolution > 0 ? options.resolution : reference_resolution) {
    if (resolution_ <= 0) resolution_ = kDefaultImageResolution;
    if (!(options_.validity_s > 0.0) || !std::isfinite(options_.validity_s))
        options_.validity_s = HzbTbvOptions{}.validity_s;
}

std::unique_ptr<Culler> HzbTbvCuller::clone() const {
    auto copy = std::make_unique<HzbTbvCuller>(*this);
    copy->snapshot_ = HzbTbvSnapshot{};  // the copy fills its own at its next cull
    return copy;
}

void HzbTbvCuller::reset(const Scene& scene) {
    frame_ = 0;
    snapshot_.valid = false;
    ready_ = scene.dimensions == 3;
    if (!ready_) return;
    const size_t n = scene.objects.size();
    max_speed_.assign(n, 0.0);
    bound_radius_.assign(n, 0.0);
    reach_.assign(n, Aabb{});
    tested_stamp_.assign(n, 0);
    dynamic_.clear();
    reveals_.clear();
    reveals_.reserve(n);
    retests_.clear();
    retests_.reserve(n);
    size_t mesh_vertices = 0, keys = 0;
    for (size_t i = 0; i < n; ++i) {
        const SceneObject& object = scene.objects[i];
        if (object.isDynamic()) {
            dynamic_.push_back(int(i));
            max_speed_[i] = maxSpeedOf(object);
            bound_radius_[i] = boundingRadiusOf(object, 3);
            reach_[i] = reachOf(object, scene.grid.world, 3);
        }
        if (object.mesh) mesh_vertices = std::max(mesh_vertices, object.mesh->vertices.size());
        keys = std::max(keys, object.motion.keys.size());
    }
    key_times_.reserve(keys);
    buffer_.reserveMeshVertices(mesh_vertices);

    // The root is the cube on the world's longest side, as the paper's octree
    // subdivides a cube: the world's own box, flat in a building, would halve
    // its height at every level, and every object taller than half the world
    // (a wall) would stay at the root.
    OctreeParams params;
    const glm::dvec3 extent = scene.grid.world.extent();
    const double side = std::max({extent.x, extent.y, extent.z});
    params.bounds = {scene.grid.world.min, scene.grid.world.min + glm::dvec3(side)};
    params.max_depth = std::clamp(options_.octree_depth, 0, kMaxHzbOctreeDepth);
    octree_.reset(params);
    // Every object and its TBV share one entry, so n entries; nodes: a path of
    // at most max_depth + 1 per entry.
    octree_.reserve(int(std::min<size_t>(n * size_t(params.max_depth + 1) + 1, 1u << 22)), int(n));
    for (size_t i = 0; i < n; ++i)
        if (!scene.objects[i].isDynamic()) octree_.insert(int(i), scene.objects[i].bounds);

    TbvManagerOptions tbv;
    tbv.mode = mode_;
    tbv.validity_mode =
        options_.adaptive_validity ? TbvValidityMode::Adaptive : TbvValidityMode::Fixed;
    tbv.initial_validity = options_.validity_s;
    tbv.validity_floor = scene.dt;
    // TBVs made in one frame (all hidden objects at the start) would otherwise
    // all end in one later frame: a stalled frame.
    tbv.spread_validity = true;
    tbv.invalidate_fraction = std::clamp(options_.invalidate_fraction, 0.0, 1.0);
    tbv.seed = scene.seed;
    tbv_.reset(n, tbv);
    for (const int index : dynamic_) tbv_.addDynamic(index);
}

Aabb HzbTbvCuller::currentBox(int index) const {
    const SceneObject& object = scene_->objects[size_t(index)];
    if (!object.isDynamic()) return object.bounds;
    return object.bounds.translated(scene_->displacementAt(object, t_));
}

bool HzbTbvCuller::boxMayBeVisible(const Aabb& box) {
    if (!boxMayIntersectFrustum(box, *camera_)) return false;
    out_->stats.add(Counter::OcclusionTests, 1);
    const BoxOnScreen s = mapping_.project(box);
    return pyramid_.queryRefined(s.rect, s.znear, kHzbQueryReads).may_be_visible;
}

void HzbTbvCuller::writeInOctree(int index, const Aabb& box) {
    OctreeOpCost cost;
    if (!octree_.contains(index))
        cost = octree_.insert(index, box);
    else if (options_.octree_update_from_root)
        cost = octree_.updateFromRoot(index, box);
    else
        cost = octree_.update(index, box);
    out_->stats.add(Counter::OctreeUpdateNodes,
                    int64_t(cost.nodes_visited) + cost.nodes_created + cost.nodes_freed);
}

void HzbTbvCuller::writeObject(int index) {
    writeInOctree(index, currentBox(index));
    out_->stats.add(Counter::ObjectUpdates, 1);
}

void HzbTbvCuller::visitEntry(int index) {
    if (use_tbvs_ && tbv_.hasTbv(index)) {
        // A hidden object's TBV: while it stays hidden, so does its object. One
        // that may be visible is tested again after the traversal (header).
        if (boxMayBeVisible(toAabb(tbvBounds(tbv_.tbv(index).shape)))) retests_.push_back(index);
        return;
    }
    testAndDraw(index);
}

void HzbTbvCuller::retestTbvs() {
    for (const int index : retests_) {
        if (!boxMayBeVisible(toAabb(tbvBounds(tbv_.tbv(index).shape)))) continue;
        tbv_.reveal(index);
        reveals_.push_back(index);
        testAndDraw(index);
    }
}

void HzbTbvCuller::testAndDraw(int index) {
    if (tested_stamp_[size_t(index)] == frame_) return;
    tested_stamp_[size_t(index)] = frame_;
    const Aabb box = currentBox(index);
    if (!boxMayBeVisible(box)) return;
    const SceneObject& object = scene_->objects[size_t(index)];
    const glm::dvec3 shift =
        object.isDynamic() ? scene_->displacementAt(object, t_) : glm::dvec3(0.0);
    const bool drawn = buffer_.drawObject(index, object, shift);
    if (drawn) pyramid_.refresh(buffer_, buffer_.lastDrawCols(), buffer_.lastDrawRows());
    out_->pvs.push_back(object.id);
    if (use_tbvs_ && object.isDynamic()) tbv_.observe(index);
}

TbvShape HzbTbvCuller::makeTbv(int index, double validity) {
    const TbvShape shape = motionTbv(index, validity);
    // Cut to where the object can ever be: a person's sphere would reach
    // through the floor and out of the octree's root (kept at the root, tested
    // first against an empty pyramid, so revealed every time), and past the
    // walls of a chair's loop.
    const TbvBox bounds = tbvBounds(shape);
    const Aabb& reach = reach_[size_t(index)];
    const TbvBox cut{glm::max(bounds.min, reach.min), glm::min(bounds.max, reach.max)};
    if (cut.min == bounds.min && cut.max == bounds.max) return shape;
    if (!(cut.min.x <= cut.max.x && cut.min.y <= cut.max.y && cut.min.z <= cut.max.z))
        return shape;  // a reach that misses the TBV: keep it whole (never seen in a scene)
    TbvShape box;
    box.kind = TbvShapeKind::Box;
    box.dimensions = 3;
    box.box = cut;
    box.centre = 0.5 * (cut.min + cut.max);
    return box;
}

TbvShape HzbTbvCuller::motionTbv(int index, double validity) {
    const SceneObject& object = scene_->objects[size_t(index)];
    const glm::dvec3 shift = scene_->displacementAt(object, t_);
    const double speed = max_speed_[size_t(index)];
    const auto choice = HzbTbvShapeChoice(options_.tbv_shape);
    if (choice == HzbTbvShapeChoice::Box)
        return boxTbv(3, toTbvBox(object.bounds.translated(shift)), speed, validity);
    if (choice == HzbTbvShapeChoice::Swept && object.motion.kind == MotionKind::Keyframes &&
        !object.motion.keys.empty()) {
        const std::vector<PositionKey>& keys = object.motion.keys;
        auto box_at = [&](double s) {
            return toTbvBox(object.bounds.translated(scene_->displacementAt(object, s)));
        };
        key_times_.clear();
        for (const PositionKey& key : keys) key_times_.push_back(key.t);
        return sweptTbv(3, box_at, key_times_.data(), key_times_.size(), t_, validity);
    }
    return sphereTbv(3, object.anchor + shift, bound_radius_[size_t(index)], speed, validity);
}

void HzbTbvCuller::cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) {
    out.pvs.clear();
    out.stats = CullStats{};
    snapshot_.valid = false;
    if (!ready_) return;
    ++frame_;
    scene_ = &scene;
    camera_ = &camera;
    out_ = &out;
    t_ = t;
    int width = 0, height = 0;
    imageSizeForAspect(resolution_, camera.aspect, width, height);
    buffer_.resize(width, height);
    buffer_.begin(camera);
    mapping_.set(camera, width, height);
    // The buffer starts empty (+infinity), and so does the pyramid.
    pyramid_.resize(width, height);
    pyramid_.clear();

    // Steps 1 and 2.
    if (use_tbvs_) {
        tbv_.beginFrame(t, [&](int index, TbvDropReason) {
            // TBVe: step 2 writes the object in its TBV's place with the rest of
            // V. TBVi writes it now (see the header: its one-frame bound needs it).
            if (mode_ == TbvUpdateMode::Implicit) {
                tbv_.updVis(index);
                writeObject(index);
            }
        });
        for (const int index : tbv_.objectsToUpdate()) {
            tbv_.updVis(index);
            writeObject(index);
        }
    } else {
        for (const int index : dynamic_) writeObject(index);
    }

    // Step 3. Objects outside the world sit at the root, whose box does not
    // bound them: the root is then never skipped on its box.
    reveals_.clear();
    retests_.clear();
    const bool root_holds_outside = octree_.outsideCount() > 0;
    int64_t nodes = 0;
    if (capture_) {
        snapshot_.nodes.clear();
        snapshot_.nodes.reserve(size_t(octree_.poolSize()));
        snapshot_.node_count = {};
    }
    octree_.traverseFrontToBack(camera.position, [&](const OctreeNodeView& node) {
        ++nodes;
        const bool unbounded = node.id == DynamicOctree::kRoot && root_holds_outside;
        const bool enter = unbounded || boxMayBeVisible(node.box);
        if (capture_) captureNode(node, enter);
        if (!enter) return false;
        for (const int index : node.objects) visitEntry(index);
        return true;
    });
    out.stats.set(Counter::NodesVisited, nodes);
    retestTbvs();
    // The revealed objects replace their TBVs in T.
    for (const int index : reveals_) writeObject(index);

    // Step 4.
    if (use_tbvs_) {
        tbv_.endFrame([&](int index, double& validity) {
            const TbvShape shape = makeTbv(index, validity);
            writeInOctree(index, toAabb(tbvBounds(shape)));
            return shape;
        });
        const TbvFrameCounters& c = tbv_.frameCounters();
        out.stats.set(Counter::TbvCreated, c.tbv_created);
        out.stats.set(Counter::TbvExpired, c.tbv_expired);
        out.stats.set(Counter::TbvRevealed, c.tbv_revealed);
        out.stats.set(Counter::StateFetches, c.state_fetches);
        out.stats.set(Counter::TbvMessages, c.tbv_messages);
    } else {
        // Every dynamic object's configuration, every frame.
        out.stats.set(Counter::StateFetches, int64_t(dynamic_.size()));
        out.stats.set(Counter::TbvMessages, 0);
    }
    out.stats.add(Counter::ObjectUpdates, 0);      // reported, 0 or more
    out.stats.add(Counter::OctreeUpdateNodes, 0);  // likewise
    std::sort(out.pvs.begin(), out.pvs.end());
    if (capture_) fillSnapshot(out);
}

// --- Debug capture (hzb_tbv_snapshot.h): reads the structures, changes nothing
// the culling depends on.

void HzbTbvCuller::captureNode(const OctreeNodeView& node, bool entered) {
    HzbNodeVisit visit;
    visit.box = node.box;
    visit.node = node.id;
    visit.depth = node.depth;
    visit.entries = node.objects.size();
    // boxMayBeVisible tests the frustum first; asking it again apart (a pure
    // test, no counter) tells which of the two skipped the node.
    visit.outcome = entered                                      ? HzbNodeOutcome::Entered
                    : boxMayIntersectFrustum(node.box, *camera_) ? HzbNodeOutcome::ZCulled
                                                                 : HzbNodeOutcome::FrustumCulled;
    ++snapshot_.node_count[size_t(visit.outcome)];
    snapshot_.nodes.push_back(visit);  // reserved for the pool's size
}

void HzbTbvCuller::fillSnapshot(const FrameResult& out) {
    HzbTbvSnapshot& s = snapshot_;
    s.valid = true;
    s.uses_tbvs = use_tbvs_;
    s.mode = mode_;
    s.frame = frame_;
    s.t = t_;

    // D.
    s.slot_of_object.assign(scene_->objects.size(), -1);
    s.objects.clear();
    s.objects.reserve(dynamic_.size());
    s.status_count = {};
    for (const int index : dynamic_) {
        HzbTbvObject o;
        o.object_index = index;
        o.object_id = scene_->objects[size_t(index)].id;
        o.in_pvs = std::binary_search(out.pvs.begin(), out.pvs.end(), o.object_id);
        const TbvObjectView v = tbv_.view(index);
        o.state = v.state;
        o.period = v.period;
        if (!use_tbvs_) {
            o.status = o.in_pvs ? HzbObjectStatus::Visible : HzbObjectStatus::Culled;
        } else {
            if (v.has_tbv) {
                o.has_tbv = true;
                o.tbv = toAabb(tbv_.bounds(index));
                o.created = v.created;
                o.expiry = v.expiry;
                o.remaining = v.remaining;
                o.new_tbv = v.created == t_;
            }
            o.status = v.has_tbv ? HzbObjectStatus::Hidden : HzbObjectStatus::Visible;
            // A TBV ends at most once a frame: an object whose TBV ended has none
            // until step 4, and step 4 comes last.
            if (v.dropped && v.last_drop_frame == tbv_.frame()) {
                switch (v.last_drop) {
                    case TbvDropReason::Expired:
                        o.status = HzbObjectStatus::Expired;
                        break;
                    case TbvDropReason::Revealed:
                        o.status = HzbObjectStatus::Revealed;
                        break;
                    case TbvDropReason::Violated:
                    case TbvDropReason::Invalidated:
                        o.status = HzbObjectStatus::Violated;
                        break;
                }
            }
        }
        ++s.status_count[size_t(o.status)];
        s.slot_of_object[size_t(index)] = int32_t(s.objects.size());
        s.objects.push_back(o);
    }

    // Q. Its live entries are at most one per object.
    s.queue_size = use_tbvs_ ? tbv_.queue().size() : 0;
    s.next_expiries.clear();
    s.next_expiries.reserve(kHzbNextExpiries);
    if (use_tbvs_) {
        expiry_scratch_.reserve(tbv_.objects());
        tbv_.queue().nextExpiries(kHzbNextExpiries, expiry_scratch_);
        for (const std::pair<int, double>& e : expiry_scratch_)
            s.next_expiries.push_back(
                {e.first, scene_->objects[size_t(e.first)].id, e.second, e.second - t_});
    }

    // T.
    s.octree_nodes = octree_.nodeCount();
    s.octree_max_depth = octree_.params().max_depth;

    // The Z-pyramid's coarse levels.
    s.pyramid_width = pyramid_.width();
    s.pyramid_height = pyramid_.height();
    s.pyramid_level_count = pyramid_.levelCount();
    s.pyramid_levels.clear();
    size_t texels = 0;
    for (int l = 0; l < pyramid_.levelCount(); ++l) {
        const ZPyramidLevel level = pyramid_.level(l);
        if (level.width > kHzbMaxCapturedSide || level.height > kHzbMaxCapturedSide) continue;
        s.pyramid_levels.push_back({l, level.width, level.height, texels});
        texels += size_t(level.width) * size_t(level.height);
    }
    s.pyramid_texels.resize(texels);
    for (const HzbPyramidLevel& l : s.pyramid_levels) {
        const ZPyramidLevel level = pyramid_.level(l.level);
        const size_t count = size_t(l.width) * size_t(l.height);
        for (size_t k = 0; k < count; ++k) s.pyramid_texels[l.offset + k] = float(level.data[k]);
    }

    s.stats = out.stats;
    s.tbv_counters = use_tbvs_ ? tbv_.frameCounters() : TbvFrameCounters{};
}

}  // namespace gridcull
