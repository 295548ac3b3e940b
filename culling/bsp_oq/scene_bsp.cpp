// The scene tree: Kovalčík & Sochor, "Fast rendering of complex dynamic
// scenes", section 3.2 (relinking up then down, lazy local reconstruction) and
// 3.3 (traversal, in the header). scene_bsp.h says where it departs from the
// paper: half-open cells, the split rule, and our rule for "after several
// frames".
#include "culling/bsp_oq/scene_bsp.h"

#include <climits>

namespace gridcull {

namespace {

template <class T>
std::vector<T> copyWithCapacity(const std::vector<T>& v) {
    std::vector<T> copy;
    copy.reserve(v.capacity());
    copy.assign(v.begin(), v.end());
    return copy;
}

}  // namespace

SceneBsp::SceneBsp(const SceneBsp& other)
    : params_(other.params_),
      nodes_(copyWithCapacity(other.nodes_)),
      free_head_(other.free_head_),
      live_nodes_(other.live_nodes_),
      serial_(other.serial_),
      objects_(copyWithCapacity(other.objects_)),
      next_in_node_(copyWithCapacity(other.next_in_node_)),
      prev_in_node_(copyWithCapacity(other.prev_in_node_)),
      outside_count_(other.outside_count_),
      frame_(other.frame_),
      noted_(copyWithCapacity(other.noted_)),
      scratch_objects_(copyWithCapacity(other.scratch_objects_)),
      scratch_keys_(copyWithCapacity(other.scratch_keys_)),
      scratch_nodes_(copyWithCapacity(other.scratch_nodes_)),
      sort_scratch_(copyWithCapacity(other.sort_scratch_)) {}

namespace {

// The axes by decreasing extent, ties in axis order (no allocation, unlike
// std::stable_sort).
void axesByExtent(const glm::dvec3& e, int order[3]) {
    for (int i = 1; i < 3; ++i)
        for (int j = i; j > 0 && e[order[j]] > e[order[j - 1]]; --j)
            std::swap(order[j], order[j - 1]);
}

bool wellFormed(const Aabb& box) {  // NaN passes: such a box goes to the root
    for (int a = 0; a < 3; ++a)
        if (box.min[a] > box.max[a]) return false;
    return true;
}

bool finiteBox(const Aabb& box) {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(box.min[a]) || !std::isfinite(box.max[a])) return false;
    return true;
}

bool sameBox(const Aabb& a, const Aabb& b) {
    return a.min == b.min && a.max == b.max;  // NaN never equal: relinked each time
}

}  // namespace

void objectBoxesAt(const Scene& scene, double t, std::vector<Aabb>& boxes) {
    boxes.resize(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i)
        boxes[i] = scene.boundsAt(scene.objects[i], t);
}

bool SceneBsp::cellContains(int node, const Aabb& box) const {
    const Node& n = at(node);
    for (int a = 0; a < 3; ++a) {
        if (!(box.min[a] >= n.cell.min[a])) return false;
        const bool open = (n.open_max >> a) & 1;
        if (!(open ? box.max[a] < n.cell.max[a] : box.max[a] <= n.cell.max[a])) return false;
    }
    return true;
}

bool SceneBsp::outOfShape(int node) const {
    const Node& n = at(node);
    const int outside = node == kRoot ? outside_count_ : 0;
    if (n.low == kNone)
        return n.depth < params_.max_depth && n.object_count - outside > params_.max_node_objects;
    return n.subtree_objects - outside <= params_.max_node_objects;
}

int SceneBsp::allocNode() {
    int index;
    if (free_head_ != kNone) {
        index = free_head_;
        free_head_ = nodes_[size_t(index)].next_free;
    } else {
        index = poolSize();
        nodes_.emplace_back();
        // The noted list and the rebuild walk hold one entry per pool index at
        // most: they grow with the pool's capacity (its high-water mark).
        if (noted_.capacity() < nodes_.capacity()) noted_.reserve(nodes_.capacity());
        if (scratch_nodes_.capacity() < nodes_.capacity())
            scratch_nodes_.reserve(nodes_.capacity());
    }
    Node& n = nodes_[size_t(index)];
    const bool in_list = n.in_noted_list;  // an entry of the freed node may remain
    n = Node();
    n.in_noted_list = in_list;
    n.live = true;
    n.serial = ++serial_;
    ++live_nodes_;
    return index;
}

void SceneBsp::freeNode(int node) {
    Node& n = at(node);
    assert(n.object_count == 0 && node != kRoot);
    n.live = false;
    n.noted_frame = -1;
    n.next_free = free_head_;
    free_head_ = node;
    --live_nodes_;
}

void SceneBsp::attach(int node, int object) {
    Node& n = at(node);
    next_in_node_[size_t(object)] = n.first_object;
    prev_in_node_[size_t(object)] = kNone;
    if (n.first_object != kNone) prev_in_node_[size_t(n.first_object)] = object;
    n.first_object = object;
    ++n.object_count;
    objects_[size_t(object)].node = node;
}

void SceneBsp::detach(int object) {
    const int node = objects_[size_t(object)].node;
    Node& n = at(node);
    const int next = next_in_node_[size_t(object)];
    const int prev = prev_in_node_[size_t(object)];
    if (prev != kNone)
        next_in_node_[size_t(prev)] = next;
    else
        n.first_object = next;
    if (next != kNone) prev_in_node_[size_t(next)] = prev;
    --n.object_count;
    assert(n.object_count >= 0);
    objects_[size_t(object)].node = kNone;
}

int SceneBsp::descend(int node, const Aabb& box, SceneBspCost& cost) const {
    for (;;) {
        const Node& n = at(node);
        if (n.low == kNone) return node;
        int next;
        if (box.max[n.axis] < n.split)
            next = n.low;
        else if (box.min[n.axis] >= n.split)
            next = n.high;
        else
            return node;  // straddles the plane
        ++cost.nodes_visited;
        node = next;
    }
}

void SceneBsp::build(const SceneBspParams& params, const std::vector<Aabb>& boxes) {
    assert(params.max_node_objects >= 1);
    assert(params.max_depth >= 0 && params.max_depth <= kMaxSceneBspDepth);
    assert(finiteBox(params.world) && wellFormed(params.world));
    assert(boxes.size() <= size_t(INT_MAX / 2));
    params_ = params;
    const int n = int(boxes.size());
    nodes_.clear();
    free_head_ = kNone;
    live_nodes_ = 0;
    objects_.assign(size_t(n), ObjectRecord());
    next_in_node_.assign(size_t(n), kNone);
    prev_in_node_.assign(size_t(n), kNone);
    outside_count_ = 0;
    frame_ = 0;
    noted_.clear();
    scratch_objects_.resize(size_t(n));
    scratch_keys_.resize(size_t(n));
    sort_scratch_.resize(size_t(n));

    const int root = allocNode();
    assert(root == kRoot);
    Node& r = at(root);
    r.cell = params.world;
    for (int id = 0; id < n; ++id) {
        assert(wellFormed(boxes[size_t(id)]));
        objects_[size_t(id)].box = boxes[size_t(id)];
        scratch_objects_[size_t(id)] = id;
    }
    SceneBspCost cost;
    buildAt(kRoot, 0, n, cost);
    // Room for every node to be noted once, whatever the pool grows to.
    noted_.reserve(std::max(nodes_.capacity(), size_t(2 * n + 1)));
    scratch_nodes_.reserve(noted_.capacity());
}

void SceneBsp::reserve(int nodes) {
    nodes_.reserve(size_t(std::max(nodes, 1)));
    noted_.reserve(nodes_.capacity());
    scratch_nodes_.reserve(nodes_.capacity());
}

void SceneBsp::buildAt(int node, int begin, int end, SceneBspCost& cost) {
    at(node).subtree_objects = end - begin;
    // Objects not inside the cell stay here (only the root's outside ones can be).
    int* ids = scratch_objects_.data();
    int* inside_begin = std::partition(ids + begin, ids + end, [&](int id) {
        return !cellContains(node, objects_[size_t(id)].box);
    });
    for (int* p = ids + begin; p != inside_begin; ++p) {
        assert(node == kRoot);
        objects_[size_t(*p)].outside = true;
        ++outside_count_;
        attach(node, *p);
    }
    begin = int(inside_begin - ids);
    const int n = end - begin;

    int axis = -1;
    double split = 0.0;
    const Node& nd = at(node);
    if (n > params_.max_node_objects && nd.depth < params_.max_depth) {
        const glm::dvec3 e = nd.cell.extent();
        int order[3] = {0, 1, 2};
        axesByExtent(e, order);
        for (int a : order) {
            for (int k = begin; k < end; ++k)
                scratch_keys_[size_t(k)] = objects_[size_t(ids[k])].box.center()[a];
            double* keys = scratch_keys_.data();
            std::nth_element(keys + begin, keys + begin + n / 2, keys + end);
            const double s = keys[begin + n / 2];
            if (!(s > nd.cell.min[a] && s < nd.cell.max[a])) continue;
            int n_low = 0, n_high = 0;
            for (int k = begin; k < end; ++k) {
                const Aabb& box = objects_[size_t(ids[k])].box;
                n_low += box.max[a] < s;
                n_high += box.min[a] >= s;
            }
            if (n_low < n && n_high < n && n_low + n_high > 0) {
                axis = a;
                split = s;
                break;
            }
        }
    }
    if (axis < 0) {  // a leaf
        for (int k = begin; k < end; ++k) attach(node, ids[k]);
        return;
    }
    // [begin, mid_low): stay, [mid_low, mid_high): low, [mid_high, end): high.
    int* stay_end = std::partition(ids + begin, ids + end, [&](int id) {
        const Aabb& box = objects_[size_t(id)].box;
        return !(box.max[axis] < split) && !(box.min[axis] >= split);
    });
    int* low_end = std::partition(
        stay_end, ids + end, [&](int id) { return objects_[size_t(id)].box.max[axis] < split; });
    for (int* p = ids + begin; p != stay_end; ++p) attach(node, *p);

    const int low = allocNode();
    const int high = allocNode();
    cost.nodes_created += 2;
    Node& parent = at(node);
    parent.axis = axis;
    parent.split = split;
    parent.low = low;
    parent.high = high;
    Node& l = at(low);
    l.cell = parent.cell;
    l.cell.max[axis] = split;
    l.open_max = parent.open_max | (1 << axis);
    l.parent = node;
    l.depth = parent.depth + 1;
    Node& h = at(high);
    h.cell = parent.cell;
    h.cell.min[axis] = split;
    h.open_max = parent.open_max;
    h.parent = node;
    h.depth = parent.depth + 1;
    buildAt(low, int(stay_end - ids), int(low_end - ids), cost);
    buildAt(high, int(low_end - ids), end, cost);
}

void SceneBsp::note(int node) {
    Node& n = at(node);
    if (n.noted_frame >= 0 || !outOfShape(node)) return;
    n.noted_frame = frame_;
    if (!n.in_noted_list) {
        assert(noted_.size() < noted_.capacity());  // one entry per pool index at most
        n.in_noted_list = true;
        noted_.push_back(node);
    }
}

void SceneBsp::move(int object, int new_node, int top, bool outside) {
    ObjectRecord& rec = objects_[size_t(object)];
    const int old_node = rec.node;
    if (rec.outside != outside) {
        outside_count_ += outside ? 1 : -1;
        rec.outside = outside;
        note(kRoot);
    }
    if (old_node == new_node) return;
    detach(object);
    attach(new_node, object);
    for (int v = old_node; v != top; v = at(v).parent) {
        --at(v).subtree_objects;
        note(v);
    }
    for (int v = new_node; v != top; v = at(v).parent) {
        ++at(v).subtree_objects;
        note(v);
    }
    note(top);
}

SceneBspCost SceneBsp::relink(int object, const Aabb& box) {
    assert(wellFormed(box));
    SceneBspCost cost;
    ObjectRecord& rec = objects_[size_t(object)];
    rec.box = box;
    // Up: the first ancestor (or the node itself) whose cell contains the box.
    int top = rec.node;
    ++cost.nodes_visited;
    while (top != kRoot && !cellContains(top, box)) {
        top = at(top).parent;
        ++cost.nodes_visited;
    }
    const bool outside = top == kRoot && !cellContains(kRoot, box);
    // Down: the smallest node containing it.
    const int new_node = outside ? kRoot : descend(top, box, cost);
    move(object, new_node, top, outside);
    return cost;
}

SceneBspCost SceneBsp::relinkFromRoot(int object, const Aabb& box) {
    assert(wellFormed(box));
    SceneBspCost cost;
    ObjectRecord& rec = objects_[size_t(object)];
    // Finding the object from the root along its old box reads its node's path.
    cost.nodes_visited += at(rec.node).depth + 1;
    rec.box = box;
    const bool outside = !cellContains(kRoot, box);
    ++cost.nodes_visited;
    const int new_node = outside ? kRoot : descend(kRoot, box, cost);
    // Counts fixed along both whole paths: the root's count does not change.
    const int old_node = rec.node;
    if (rec.outside != outside) {
        outside_count_ += outside ? 1 : -1;
        rec.outside = outside;
        note(kRoot);
    }
    if (old_node != new_node) {
        detach(object);
        attach(new_node, object);
        for (int v = old_node; v != kNone; v = at(v).parent) {
            --at(v).subtree_objects;
            note(v);
        }
        for (int v = new_node; v != kNone; v = at(v).parent) {
            ++at(v).subtree_objects;
            note(v);
        }
    }
    return cost;
}

SceneBspCost SceneBsp::update(const std::vector<Aabb>& boxes, int frame) {
    assert(int(boxes.size()) == objectCount());
    assert(frame >= frame_);
    frame_ = frame;
    SceneBspCost cost;
    for (int id = 0; id < objectCount(); ++id) {
        if (sameBox(boxes[size_t(id)], objects_[size_t(id)].box)) continue;
        cost += relink(id, boxes[size_t(id)]);
        ++cost.objects_relinked;
    }
    cost += rebuildDueNodes(frame);
    return cost;
}

SceneBspCost SceneBsp::rebuildDueNodes(int frame) {
    SceneBspCost cost;
    frame_ = std::max(frame_, frame);
    if (params_.rebuild_delay_frames < 0 || noted_.empty()) return cost;
    // Shallowest first: a rebuilt ancestor frees its noted descendants.
    std::sort(noted_.begin(), noted_.end(), [&](int x, int y) {
        const int dx = nodes_[size_t(x)].live ? nodes_[size_t(x)].depth : INT_MAX;
        const int dy = nodes_[size_t(y)].live ? nodes_[size_t(y)].depth : INT_MAX;
        return dx != dy ? dx < dy : x < y;
    });
    size_t kept = 0;
    for (size_t k = 0; k < noted_.size(); ++k) {
        const int v = noted_[k];
        Node& n = nodes_[size_t(v)];
        if (!n.live || n.noted_frame < 0) {  // freed, or reused and not noted
            n.in_noted_list = false;
            continue;
        }
        if (frame - n.noted_frame < params_.rebuild_delay_frames) {
            noted_[kept++] = v;
            continue;
        }
        n.noted_frame = -1;
        n.in_noted_list = false;
        if (outOfShape(v)) {
            rebuildSubtree(v, cost);
            ++cost.subtrees_rebuilt;
        }
    }
    noted_.resize(kept);
    return cost;
}

void SceneBsp::rebuildSubtree(int node, SceneBspCost& cost) {
    // Gather the subtree's objects (the root's outside ones too: buildAt keeps
    // them at the root), free the descendants.
    int count = 0;
    scratch_nodes_.clear();
    scratch_nodes_.push_back(node);
    while (!scratch_nodes_.empty()) {
        const int v = scratch_nodes_.back();
        scratch_nodes_.pop_back();
        Node& n = at(v);
        while (n.first_object != kNone) {
            const int id = n.first_object;
            detach(id);
            if (objects_[size_t(id)].outside) {
                objects_[size_t(id)].outside = false;
                --outside_count_;
            }
            scratch_objects_[size_t(count++)] = id;
        }
        if (n.low != kNone) {
            assert(scratch_nodes_.size() + 2 <= scratch_nodes_.capacity());
            scratch_nodes_.push_back(n.low);
            scratch_nodes_.push_back(n.high);
        }
        if (v != node) {
            freeNode(v);
            ++cost.nodes_freed;
        }
    }
    Node& n = at(node);
    assert(count == n.subtree_objects);
    n.low = n.high = kNone;
    n.axis = -1;
    n.split = 0.0;
    buildAt(node, 0, count, cost);
}

}  // namespace gridcull
