// Kovalčík & Sochor, "Fast rendering of complex dynamic scenes", sections 3.1
// to 3.4 and Algorithms 2 to 4: the frame of bsp_oq_culler.h, whose header says
// what each step does and where it departs from the paper.
#include "culling/bsp_oq/bsp_oq_culler.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <unordered_map>
#include <utility>

#include "culling/baseline/frustum_tests.h"
#include "culling/raster/id_depth_buffer.h"
#include "culling/raster/software_image_target.h"
#include "culling/scene/object_triangles.h"

namespace gridcull {

namespace {

uint32_t historyMask(int history) {
    return history >= 32 ? ~0u : (1u << history) - 1u;
}

bool overlaps(const PixelRect& a, const PixelRect& b) {
    return !a.intersect(b).empty();
}

// A test box's growth, relative to the largest coordinate its depths are
// computed from (its own and the eye's): some 10^7 times the rounding of a
// depth (a few units in 10^16 of them), so that the grown box's faces are
// strictly nearer than any surface drawn on the box's own faces, and far below
// anything a scene resolves (10^-7 units in a world of 100).
constexpr double kTestBoxMargin = 1e-9;

Aabb grownForQuery(const Aabb& box, const glm::dvec3& eye) {
    double scale = 1.0;
    for (int a = 0; a < 3; ++a)
        scale = std::max({scale, std::abs(box.min[a]), std::abs(box.max[a]), std::abs(eye[a])});
    if (!std::isfinite(scale)) return box;  // an unbounded box needs no margin
    const glm::dvec3 margin(kTestBoxMargin * scale);
    return {box.min - margin, box.max + margin};
}

}  // namespace

int bspSkipFrames(uint32_t answers, int history) {
    assert(history >= 0 && history <= kMaxBspHistory);
    return __builtin_popcount(answers & historyMask(history));
}

int bspSpreadSkip(int skip, uint64_t key) {
    // SplitMix64's finalizer: every bit of the key moves every bit of the hash.
    key += 0x9E3779B97F4A7C15ull;
    key = (key ^ (key >> 30)) * 0xBF58476D1CE4E5B9ull;
    key = (key ^ (key >> 27)) * 0x94D049BB133111EBull;
    key ^= key >> 31;
    return skip + int(key % uint64_t(skip / 2 + 1));
}

BspOqCuller::BspOqCuller(std::string name, BspOqMode mode, const BspOqOptions& options,
                         int reference_resolution, std::unique_ptr<ImageTarget> target)
    : name_(std::move(name)),
      mode_(mode),
      options_(options),
      resolution_(options.resolution > 0 ? options.resolution : reference_resolution),
      target_(target ? std::move(target) : std::make_unique<SoftwareImageTarget>()) {
    assert(resolution_ >= 1);
    assert(options_.leaf_triangles >= 1 && options_.node_objects >= 1);
    assert(options_.history >= 0 && options_.history <= kMaxBspHistory);
    assert(options_.batch >= 1 && options_.batch <= kMaxBspBatch);
    snapshot_.mode = mode;
}

const ObjectBsp* BspOqCuller::objectTree(int object) const {
    if (object < 0 || size_t(object) >= tree_of_.size() || tree_of_[size_t(object)] < 0)
        return nullptr;
    return trees_[size_t(tree_of_[size_t(object)])].get();
}

std::unique_ptr<Culler> BspOqCuller::clone() const {
    auto copy = std::make_unique<BspOqCuller>(*this);
    if (!copy->target_) return nullptr;  // a target that cannot be copied (OpenGL)
    copy->snapshot_ = BspOqSnapshot{};   // the copy fills its own at its next cull
    copy->snapshot_.mode = mode_;
    return copy;
}

void BspOqCuller::reset(const Scene& scene) {
    scene_ = &scene;
    frame_ = 0;
    ready_ = true;
    target_->prepare(scene);
    const size_t n = scene.objects.size();

    // Section 3.1's preprocessing: a tree for every mesh too complex for one
    // leaf, shared by the mesh's copies, its triangles registered on the target.
    trees_.clear();
    tree_handle_.clear();
    tree_of_.assign(n, -1);
    object_state_first_.assign(n, -1);
    std::unordered_map<const TriangleMesh*, int> tree_of_mesh;
    ObjectBspParams params;
    params.max_leaf_triangles = options_.leaf_triangles;
    std::vector<glm::dvec3> corners;
    size_t object_nodes = 0;
    for (size_t i = 0; i < n; ++i) {
        const SceneObject& object = scene.objects[i];
        if (object.shape != ShapeKind::Mesh || !object.mesh ||
            int64_t(object.mesh->indices.size() / 3) <= options_.leaf_triangles)
            continue;
        auto [found, added] = tree_of_mesh.emplace(object.mesh.get(), int(trees_.size()));
        if (added) {
            trees_.push_back(std::make_shared<const ObjectBsp>(*object.mesh, params));
            corners.clear();
            for (const BspTrianglePiece& piece : trees_.back()->pieces())
                corners.insert(corners.end(), {piece.v[0], piece.v[1], piece.v[2]});
            tree_handle_.push_back(target_->addTriangleSet(corners));
        }
        tree_of_[i] = found->second;
        object_state_first_[i] = int(object_nodes);
        object_nodes += size_t(trees_[size_t(found->second)]->nodeCount());
    }
    object_states_.assign(object_nodes, NodeState());
    translation_.assign(n, glm::dvec3(0.0));
    drawn_frame_.assign(n, -1);

    // Section 3.2: the scene tree over the objects' boxes at t = 0.
    objectBoxesAt(scene, 0.0, boxes_);
    SceneBspParams tree;
    tree.world = scene.grid.world;
    tree.max_node_objects = options_.node_objects;
    tree.rebuild_delay_frames = options_.rebuild_delay;
    scene_tree_.build(tree, boxes_);
    scene_tree_.reserve(2 * scene_tree_.poolSize() + 64);
    scene_states_.assign(size_t(scene_tree_.poolCapacity()), SceneNodeState());
    moved_.reserve(n);

    // Each node is pushed at most once a frame; a node's objects are sorted once.
    stack_.reserve(size_t(scene_tree_.poolCapacity()) + object_nodes + 1);
    pending_.reserve(size_t(options_.batch));
    waiting_.reserve(size_t(options_.batch));
    walk_.reserve(size_t(scene_tree_.poolCapacity()));
    order_.reserve(n);
    query_log_.clear();
    snapshot_.valid = false;
}

BspOqCuller::SceneNodeState& BspOqCuller::sceneState(int node) {
    // Sized after each update (updateSceneTree), so references into it stay
    // valid through the frame's traversal.
    assert(size_t(node) < scene_states_.size());
    SceneNodeState& s = scene_states_[size_t(node)];
    const uint32_t serial = scene_tree_.nodeSerial(node);
    if (s.serial != serial) {  // a node the lazy reconstruction made anew
        s = SceneNodeState();
        s.serial = serial;
        s.changed_frame = frame_;
    }
    return s;
}

BspOqCuller::NodeState& BspOqCuller::stateOf(const ActiveNode& n) {
    if (n.object < 0) return sceneState(n.node).node;
    return object_states_[size_t(object_state_first_[size_t(n.object)] + n.node)];
}

void BspOqCuller::markChanged(int node) {
    // To the root every time: O(height) a moved object, and no early stop can
    // miss an ancestor of a node the lazy reconstruction made this frame.
    for (; node != SceneBsp::kNone; node = scene_tree_.nodeParent(node))
        sceneState(node).changed_frame = frame_;
}

void BspOqCuller::updateSceneTree(double t) {
    const Scene& scene = *scene_;
    moved_.clear();
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Aabb box = scene.boundsAt(scene.objects[i], t);
        boxes_[i] = box;
        const Aabb& tied = scene_tree_.boxOf(int(i));
        if (box.min != tied.min || box.max != tied.max) {
            moved_.push_back(int(i));
            markChanged(scene_tree_.nodeOf(int(i)));
        }
        if (tree_of_[i] >= 0) translation_[i] = objectTranslationAt(scene, scene.objects[i], t);
    }
    const SceneBspCost cost = scene_tree_.update(boxes_, int(frame_));
    if (scene_states_.size() < size_t(scene_tree_.poolSize()))  // the pool grew past reserve()
        scene_states_.resize(size_t(scene_tree_.poolCapacity()));
    for (int i : moved_) markChanged(scene_tree_.nodeOf(i));
    out_->stats.set(Counter::ObjectUpdates, cost.objects_relinked);
    if (stack_.capacity() < size_t(scene_tree_.poolCapacity()) + object_states_.size() + 1)
        stack_.reserve(size_t(scene_tree_.poolCapacity()) + object_states_.size() + 1);
    if (walk_.capacity() < size_t(scene_tree_.poolCapacity()))
        walk_.reserve(size_t(scene_tree_.poolCapacity()));
}

Aabb BspOqCuller::tightBox(int node) {
    SceneNodeState& s = sceneState(node);
    if (s.tight_frame >= s.changed_frame) return s.tight;
    bool any = false;
    Aabb box;
    walk_.clear();
    walk_.push_back(node);
    while (!walk_.empty()) {
        const int k = walk_.back();
        walk_.pop_back();
        scene_tree_.forEachObjectOf(k, [&](int id) {
            const Aabb& b = scene_tree_.boxOf(id);
            if (any) {
                box.merge(b);
            } else {
                box = b;
                any = true;
            }
        });
        if (!scene_tree_.nodeIsLeaf(k)) {
            walk_.push_back(scene_tree_.nodeLow(k));
            walk_.push_back(scene_tree_.nodeHigh(k));
        }
    }
    s.tight = box;
    s.tight_frame = frame_;
    return box;
}

Aabb BspOqCuller::testBox(const ActiveNode& n, bool& shrunk) {
    return grownForQuery(contentBox(n, shrunk), camera_->position);
}

Aabb BspOqCuller::contentBox(const ActiveNode& n, bool& shrunk) {
    const bool shrink = mode_ == BspOqMode::Full && options_.shrink_delay >= 0;
    if (n.object >= 0) {
        const ObjectBspNode& node = objectTree(n.object)->node(n.node);
        shrunk = shrink;
        return (shrink ? node.bounds : node.cell).translated(translation_[size_t(n.object)]);
    }
    const SceneNodeState& s = sceneState(n.node);
    shrunk = shrink && frame_ - s.changed_frame >= options_.shrink_delay;
    if (shrunk) return tightBox(n.node);
    Aabb box = scene_tree_.nodeCell(n.node);
    // The root's cell does not bound the objects outside the world.
    if (n.node == SceneBsp::kRoot && scene_tree_.outsideCount() > 0)
        scene_tree_.forEachObjectOf(n.node, [&](int id) { box.merge(scene_tree_.boxOf(id)); });
    return box;
}

bool BspOqCuller::nodeEmpty(const ActiveNode& n) const {
    if (n.object >= 0) return objectTree(n.object)->node(n.node).piece_count == 0;
    return scene_tree_.nodeSubtreeObjects(n.node) == 0;
}

void BspOqCuller::setState(NodeState& s, BspNodeState state) {
    s.state = state;
    s.state_frame = frame_;
    s.query = -1;
}

BspOqCuller::Estimate BspOqCuller::firstVisibilityTest(const ActiveNode& n, PixelRect& rect) {
    NodeState& s = stateOf(n);
    if (s.need_query_frame == frame_) {  // it waited for a batch: nothing has changed
        rect = s.rect;
        return Estimate::NeedQuery;
    }
    const Estimate estimate = estimateAfresh(n, s, rect);
    if (estimate == Estimate::NeedQuery) {
        s.need_query_frame = frame_;
        s.rect = rect;
    }
    return estimate;
}

BspOqCuller::Estimate BspOqCuller::estimateAfresh(const ActiveNode& n, NodeState& s,
                                                  PixelRect& rect) {
    if (nodeEmpty(n)) {
        setState(s, BspNodeState::Empty);
        return Estimate::Invisible;
    }
    const Aabb box = testBox(n, s.shrunk);
    s.box = box;
    if (!boxMayIntersectFrustum(box, *camera_)) {
        setState(s, BspNodeState::FrustumCulled);
        return Estimate::Invisible;
    }
    if (occlusionQueryTriviallyVisible(*camera_, box)) {  // ViewerInside
        setState(s, BspNodeState::ViewerInside);
        return Estimate::Visible;
    }
    if (mode_ == BspOqMode::Vfc) {
        setState(s, BspNodeState::InFrustum);
        return Estimate::Visible;
    }
    rect = mapping_.project(box).rect;
    if (mode_ == BspOqMode::Simple) return Estimate::NeedQuery;
    if (rect.empty()) {  // no pixel centre can see it: the query's answer is known
        setState(s, BspNodeState::FrustumCulled);
        return Estimate::Invisible;
    }
    if (s.visible_frame != frame_ - 1) return Estimate::NeedQuery;  // WasInvisibleLastTime
    if (s.skip > 0) {                                               // ExamineRecentQueryResults
        --s.skip;
        ++skips_;
        setState(s, BspNodeState::AssumedVisible);
        return Estimate::Visible;
    }
    return Estimate::NeedQuery;
}

void BspOqCuller::drawObject(int index) {
    const Scene& scene = *scene_;
    const SceneObject& object = scene.objects[size_t(index)];
    const Aabb& box = boxes_[size_t(index)];
    ++objects_tested_;
    if (!boxMayIntersectFrustum(box, *camera_)) return;
    PixelRect written;
    target_->draw(object, index, scene.displacementAt(object, t_), mapping_.project(box).rect,
                  written);
    ++parts_;
    triangles_ += trianglesOf(object);
    if (drawn_frame_[size_t(index)] != frame_) {
        drawn_frame_[size_t(index)] = frame_;
        out_->pvs.push_back(object.id);
    }
}

void BspOqCuller::drawPart(int object, int node) {
    const ObjectBsp& tree = *objectTree(object);
    const ObjectBspNode& part = tree.node(node);
    PixelRect written;
    const Aabb box = part.bounds.translated(translation_[size_t(object)]);
    target_->drawTriangles(tree_handle_[size_t(tree_of_[size_t(object)])], part.first_piece,
                           part.piece_count, object, translation_[size_t(object)],
                           mapping_.project(box).rect, written);
    ++parts_;
    triangles_ += part.piece_count;
    if (drawn_frame_[size_t(object)] != frame_) {
        drawn_frame_[size_t(object)] = frame_;
        out_->pvs.push_back(scene_->objects[size_t(object)].id);
    }
}

void BspOqCuller::processVisibleNode(const ActiveNode& n) {
    stateOf(n).visible_frame = frame_;
    if (n.object >= 0) {
        const ObjectBspNode& node = objectTree(n.object)->node(n.node);
        if (node.isLeaf()) {
            drawPart(n.object, n.node);
            return;
        }
        const glm::dvec3 eye = camera_->position - translation_[size_t(n.object)];
        const bool low_first = eye[node.axis] < node.split;
        stack_.push_back({n.object, low_first ? node.high : node.low});
        stack_.push_back({n.object, low_first ? node.low : node.high});
        return;
    }
    // Algorithm 4: objects without trees drawn now; the near child, the
    // objects with trees (nearest first) and the far child processed next.
    const int node = n.node;
    order_.clear();
    scene_tree_.forEachObjectOf(node, [&](int id) {
        const glm::dvec3 d = boxes_[size_t(id)].center() - camera_->position;
        double key = d.x * d.x + d.y * d.y + d.z * d.z;
        if (!std::isfinite(key)) key = HUGE_VAL;
        order_.push_back({key, id});
    });
    std::sort(order_.begin(), order_.end());
    for (const auto& [key, id] : order_)
        if (tree_of_[size_t(id)] < 0) drawObject(id);
    const bool leaf = scene_tree_.nodeIsLeaf(node);
    bool low_first = true;
    if (!leaf) {
        low_first = camera_->position[scene_tree_.nodeAxis(node)] < scene_tree_.nodeSplit(node);
        stack_.push_back({-1, low_first ? scene_tree_.nodeHigh(node) : scene_tree_.nodeLow(node)});
    }
    for (auto it = order_.rbegin(); it != order_.rend(); ++it)
        if (tree_of_[size_t(it->second)] >= 0) stack_.push_back({it->second, ObjectBsp::kRoot});
    if (!leaf)
        stack_.push_back({-1, low_first ? scene_tree_.nodeLow(node) : scene_tree_.nodeHigh(node)});
}

void BspOqCuller::readBatch() {
    if (pending_.empty()) return;
    ++batches_;
    // The last issued first, so that the nearest node's contents end on top.
    for (auto it = pending_.rbegin(); it != pending_.rend(); ++it) {
        const bool visible = target_->queryResult(it->query);
        NodeState& s = stateOf(it->node);
        s.answers = (s.answers << 1) | (visible ? 1u : 0u);
        s.answer_count = std::min(s.answer_count + 1, kMaxBspHistory);
        s.skip =
            visible && mode_ == BspOqMode::Full ? bspSkipFrames(s.answers, options_.history) : 0;
        if (s.skip > 0 && options_.skip_spread) {
            const uint64_t node =
                uint64_t(uint32_t(it->node.object + 1)) << 32 | uint64_t(uint32_t(it->node.node));
            s.skip = bspSpreadSkip(s.skip, node * 0x100000001B3ull ^ uint64_t(frame_));
        }
        const int32_t logged = s.query;
        setState(s, visible ? BspNodeState::QueriedVisible : BspNodeState::QueriedHidden);
        s.query = logged;
        if (logged >= 0) query_log_[size_t(logged)].visible = visible;
        if (!visible) ++queries_hidden_;
        if (visible) processVisibleNode(it->node);
    }
    pending_.clear();
    ++batch_;
}

void BspOqCuller::fillBatch(int batch_limit) {
    // A node that needs a query waits while its rectangle overlaps one of the
    // batch's or of a node already waiting (whose contents, drawn first, may
    // hide it); the nodes behind it go on, up to as many waiting as the batch
    // may hold. The waiting nodes go back on the stack in their order.
    waiting_.clear();
    while (!stack_.empty() && int(pending_.size()) < batch_limit &&
           int(waiting_.size()) < batch_limit) {
        const ActiveNode n = stack_.back();
        stack_.pop_back();
        PixelRect rect;
        const Estimate estimate = firstVisibilityTest(n, rect);
        if (estimate != Estimate::NeedQuery) {
            ++nodes_tested_;
            if (estimate == Estimate::Visible) processVisibleNode(n);
            continue;
        }
        bool clear = true;
        for (const PendingQuery& p : pending_) clear = clear && !overlaps(p.rect, rect);
        for (const PendingQuery& w : waiting_) clear = clear && !overlaps(w.rect, rect);
        if (!clear) {
            waiting_.push_back({n, OcclusionQuery(), rect});
            continue;
        }
        ++nodes_tested_;
        NodeState& s = stateOf(n);
        s.query = -1;
        if (capture_) {
            s.query = int32_t(query_log_.size());
            query_log_.push_back({rect, -1, n.object >= 0, batch_, false});
        }
        pending_.push_back({n, target_->issueQuery(s.box), rect});
        ++queries_;
    }
    for (auto it = waiting_.rbegin(); it != waiting_.rend(); ++it) stack_.push_back(it->node);
}

void BspOqCuller::cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) {
    assert(ready_ && scene_ == &scene && "reset() before cull()");
    (void)scene;
    out.pvs.clear();
    out.stats = CullStats();
    out_ = &out;
    camera_ = &camera;
    t_ = t;
    ++frame_;
    nodes_tested_ = queries_ = queries_hidden_ = skips_ = parts_ = triangles_ = objects_tested_ =
        batches_ = 0;
    batch_ = 0;
    query_log_.clear();

    updateSceneTree(t);
    int width = 0, height = 0;
    imageSizeForAspect(resolution_, camera.aspect, width, height);
    mapping_.set(camera, width, height);
    target_->begin(camera, width, height, false);

    // Algorithm 2.
    const int batch_limit = mode_ == BspOqMode::Full ? options_.batch : 1;
    stack_.clear();
    pending_.clear();
    stack_.push_back({-1, SceneBsp::kRoot});
    while (!stack_.empty() || !pending_.empty()) {
        readBatch();
        fillBatch(batch_limit);
    }
    target_->end();

    std::sort(out.pvs.begin(), out.pvs.end());
    out.stats.set(Counter::NodesVisited, nodes_tested_);
    out.stats.set(Counter::OcclusionQueries, queries_);
    out.stats.set(Counter::QueriesHidden, queries_hidden_);
    out.stats.set(Counter::QueryBatches, batches_);
    out.stats.set(Counter::CoherenceSkips, skips_);
    out.stats.set(Counter::PartsDrawn, parts_);
    out.stats.set(Counter::TrianglesDrawn, triangles_);
    out.stats.set(Counter::ObjectsTested, objects_tested_);
    if (capture_) fillSnapshot(out);
    out_ = nullptr;
}

void BspOqCuller::fillSnapshot(const FrameResult& out) {
    BspOqSnapshot& snap = snapshot_;
    snap.valid = true;
    snap.mode = mode_;
    snap.frame = frame_;
    snap.t = t_;
    snap.width = mapping_.width();
    snap.height = mapping_.height();
    snap.state_count.fill(0);
    snap.queries = query_log_;
    snap.batch_count = batch_;
    auto record = [&](const NodeState& s, BspNodeRecord& r) {
        const bool now = s.state_frame == frame_;
        r.state = now ? s.state : BspNodeState::NotReached;
        r.box = now ? s.box : r.cell;
        r.shrunk = now && s.shrunk;
        r.history = s.answers;
        r.history_length = s.answer_count;
        r.skip = s.skip;
        r.query = now ? s.query : -1;
        ++snap.state_count[size_t(r.state)];
    };

    snap.scene_nodes.clear();
    scene_tree_.forEachNode([&](int node) {
        BspNodeRecord r;
        r.cell = scene_tree_.nodeCell(node);
        r.node = node;
        r.depth = scene_tree_.nodeDepth(node);
        r.contents = scene_tree_.nodeSubtreeObjects(node);
        r.leaf = scene_tree_.nodeIsLeaf(node);
        record(sceneState(node).node, r);
        if (r.query >= 0) snap.queries[size_t(r.query)].record = int32_t(snap.scene_nodes.size());
        snap.scene_nodes.push_back(r);
    });

    const size_t n = tree_of_.size();
    snap.object_nodes.clear();
    snap.object_first.assign(n, -1);
    snap.object_count.assign(n, 0);
    snap.has_tree.assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
        if (tree_of_[i] < 0) continue;
        snap.has_tree[i] = 1;
        const NodeState* states = &object_states_[size_t(object_state_first_[i])];
        if (states[ObjectBsp::kRoot].state_frame != frame_) continue;
        const ObjectBsp& tree = *objectTree(int(i));
        snap.object_first[i] = int32_t(snap.object_nodes.size());
        snap.object_count[i] = tree.nodeCount();
        for (int k = 0; k < tree.nodeCount(); ++k) {
            const ObjectBspNode& node = tree.node(k);
            BspNodeRecord r;
            r.cell = node.cell.translated(translation_[i]);
            r.node = k;
            r.object = int32_t(i);
            r.depth = node.depth;
            r.contents = node.piece_count;
            r.leaf = node.isLeaf();
            record(states[k], r);
            if (r.query >= 0)
                snap.queries[size_t(r.query)].record = int32_t(snap.object_nodes.size());
            snap.object_nodes.push_back(r);
        }
    }
    snap.stats = out.stats;
}

}  // namespace gridcull
