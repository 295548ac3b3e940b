#include "culling/lazy_grid/lazy_grid_culler.h"

#include <algorithm>
#include <cassert>

#include "culling/baseline/frustum_tests.h"
#include "culling/scene/object_triangles.h"

namespace gridcull {

const DebugSnapshotKind LazyGridSnapshot::kKind{"lazy-grid"};

LazyGridCuller::LazyGridCuller(LazyGridVariant variant, LazyGridUpdate update,
                               const LazyGridOptions& options, int reference_resolution,
                               std::unique_ptr<ImageTarget> target, std::string name)
    : variant_(variant),
      update_(update),
      options_(options),
      resolution_(options.resolution > 0 ? options.resolution : reference_resolution),
      target_(target ? std::move(target) : std::make_unique<SoftwareImageTarget>()),
      name_(std::move(name)) {
    assert(variant == LazyGridVariant::OcclusionBuffer || update == LazyGridUpdate::Lazy);
}

const char* LazyGridCuller::name() const {
    if (!name_.empty()) return name_.c_str();
    if (update_ == LazyGridUpdate::Busy) return "busy-grid";
    if (update_ == LazyGridUpdate::BusyTight) return "busy-grid-tight";
    return variant_ == LazyGridVariant::ZBuffer ? "lazy-grid-z" : "lazy-grid";
}

void LazyGridCuller::imageSize(double aspect, int& width, int& height) const {
    imageSizeForAspect(resolution_, aspect, width, height);
}

std::unique_ptr<Culler> LazyGridCuller::clone() const {
    auto copy = std::make_unique<LazyGridCuller>(*this);
    if (!copy->target_) return nullptr;    // a target that cannot be copied (OpenGL)
    copy->snapshot_ = LazyGridSnapshot{};  // the copy fills its own at its next cull
    return copy;
}

void LazyGridCuller::reset(const Scene& scene) {
    bvh_.build(scene, 0.0);
    target_->prepare(scene);
    test_list_.clear();
    draw_list_.clear();
    test_list_.reserve(bvh_.nodes().size());
    draw_list_.reserve(bvh_.nodes().size());
    snapshot_ = LazyGridSnapshot{};
}

void LazyGridCuller::cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) {
    out.stats = CullStats{};
    out.pvs.clear();
    snapshot_.valid = false;
    if (scene.dimensions != 3) return;  // the registry offers it for 3D scenes only
    assert(bvh_.objectOrder().size() == scene.objects.size() && "reset() with this scene first");

    int width, height;
    imageSize(camera.aspect, width, height);
    mapping_.set(camera, width, height);
    const bool occlusion_buffer = variant_ == LazyGridVariant::OcclusionBuffer;
    target_->begin(camera, width, height, occlusion_buffer);
    const LazyGridExtensions extensions{options_.probability_threshold,
                                        options_.border_whole_fraction,
                                        options_.large_box_fraction};
    grid_.configure(width, height, std::max(1, options_.cell_size), variant_, update_, extensions);
    grid_.begin(target_.get());

    const int rebuilds_before = bvh_.rebuilds();
    bvh_.update(scene, t);
    triangles_drawn_ = 0;
    nodes_visited_ = 0;
    if (snapshot_enabled_) {
        snapshot_.tests.clear();
        snapshot_.touches.clear();
        snapshot_.events.clear();
        snapshot_.test_of_node.assign(bvh_.nodes().size(), -1);
    }

    test_list_.clear();
    draw_list_.clear();
    frustum_planes_ = camera.frustumPlanes();
    if (!bvh_.empty()) {
        offerToTestList(0, camera);
        if (occlusion_buffer)
            traverseFig6(scene, camera, t, out);
        else
            traverseFig4(scene, camera, t, out);
    }
    target_->end();
    std::sort(out.pvs.begin(), out.pvs.end());

    const LazyGridCounters& c = grid_.counters();
    out.stats.set(Counter::PixelQueries, c.pixel_queries);
    out.stats.set(Counter::PixelsRead, c.pixels_read);
    out.stats.set(Counter::CellUpdates, c.cell_updates);
    out.stats.set(Counter::OcclusionTests, c.occlusion_tests);
    out.stats.set(Counter::NodesVisited, nodes_visited_);
    out.stats.set(Counter::TrianglesDrawn, triangles_drawn_);
    out.stats.set(Counter::BvhRebuilds, bvh_.rebuilds() - rebuilds_before);
    if (options_.probability_threshold > 0.0)
        out.stats.set(Counter::ProbabilitySkips, c.probability_skips);
    if (snapshot_enabled_) fillSnapshot();
}

void LazyGridCuller::offerToTestList(int32_t node, const Camera& camera) {
    const Aabb& box = bvh_.nodes()[size_t(node)].box;
    if (!boxMayIntersectFrustum(box, camera, frustum_planes_)) {
        ++nodes_visited_;
        recordFrustumCull(node);
        return;
    }
    const BoxOnScreen on_screen = mapping_.project(box);
    test_list_.push_back({on_screen.znear, node, on_screen});
    std::push_heap(test_list_.begin(), test_list_.end(), later);
}

void LazyGridCuller::recordFrustumCull(int32_t node) {
    if (!snapshot_enabled_) return;
    LazyGridTest test;
    test.node = node;
    test.in_frustum = false;
    test.occluded = true;
    test.first_touch = int32_t(snapshot_.touches.size());
    snapshot_.test_of_node[size_t(node)] = int32_t(snapshot_.tests.size());
    snapshot_.events.push_back({LazyGridEvent::Test, int32_t(snapshot_.tests.size()), 0.0, {}});
    snapshot_.tests.push_back(test);
}

bool LazyGridCuller::testNode(const ListEntry& entry) {
    ++nodes_visited_;
    OcclusionStep step;
    std::vector<CellTouch>* trace = snapshot_enabled_ ? &snapshot_.touches : nullptr;
    const int32_t first_touch = trace ? int32_t(trace->size()) : 0;
    const bool occluded = grid_.isOccluded(entry.box, step, trace);
    if (snapshot_enabled_) {
        LazyGridTest test;
        test.node = entry.node;
        test.box = entry.box;
        test.occluded = occluded;
        test.step = step;
        test.first_touch = first_touch;
        test.touch_count = int32_t(snapshot_.touches.size()) - first_touch;
        snapshot_.test_of_node[size_t(entry.node)] = int32_t(snapshot_.tests.size());
        snapshot_.events.push_back(
            {LazyGridEvent::Test, int32_t(snapshot_.tests.size()), entry.box.znear, {}});
        snapshot_.tests.push_back(test);
    }
    return occluded;
}

void LazyGridCuller::drawLeaf(const Scene& scene, const ListEntry& entry, double t,
                              FrameResult& out) {
    const BvhNode& leaf = bvh_.nodes()[size_t(entry.node)];
    for (int32_t k = leaf.first; k < leaf.first + leaf.count; ++k) {
        const int index = bvh_.objectOrder()[size_t(k)];
        const SceneObject& object = scene.objects[size_t(index)];
        const glm::dvec3 shift = scene.displacementAt(object, t);
        PixelRect written;
        if (target_->draw(object, index, shift, entry.box.rect, written))
            grid_.afterDraw(written, entry.box.rect);
        out.pvs.push_back(object.id);
        triangles_drawn_ += trianglesOf(object);
        if (snapshot_enabled_)
            snapshot_.events.push_back({LazyGridEvent::Draw, index, entry.box.zfar, written});
    }
}

LazyGridCuller::ListEntry LazyGridCuller::popFront(std::vector<ListEntry>& list) {
    std::pop_heap(list.begin(), list.end(), later);
    const ListEntry entry = list.back();
    list.pop_back();
    return entry;
}

void LazyGridCuller::traverseFig4(const Scene& scene, const Camera& camera, double t,
                                  FrameResult& out) {
    while (!test_list_.empty()) {
        const ListEntry entry = popFront(test_list_);
        if (testNode(entry)) continue;
        const BvhNode& node = bvh_.nodes()[size_t(entry.node)];
        if (node.isLeaf()) {
            drawLeaf(scene, entry, t, out);
        } else {
            offerToTestList(node.left, camera);
            offerToTestList(node.right, camera);
        }
    }
}

void LazyGridCuller::traverseFig6(const Scene& scene, const Camera& camera, double t,
                                  FrameResult& out) {
    while (!test_list_.empty() || !draw_list_.empty()) {
        const bool draw_next =
            !draw_list_.empty() &&
            (test_list_.empty() || draw_list_.front().key < test_list_.front().key);
        if (draw_next) {
            drawLeaf(scene, popFront(draw_list_), t, out);
            continue;
        }
        const ListEntry entry = popFront(test_list_);
        if (testNode(entry)) continue;
        const BvhNode& node = bvh_.nodes()[size_t(entry.node)];
        if (node.isLeaf()) {
            draw_list_.push_back({entry.box.zfar, entry.node, entry.box});
            std::push_heap(draw_list_.begin(), draw_list_.end(), later);
        } else {
            offerToTestList(node.left, camera);
            offerToTestList(node.right, camera);
        }
    }
}

void LazyGridCuller::fillSnapshot() {
    snapshot_.valid = true;
    snapshot_.variant = variant_;
    snapshot_.update = update_;
    snapshot_.width = mapping_.width();
    snapshot_.height = mapping_.height();
    snapshot_.cell_size = grid_.cellSize();
    snapshot_.cells_x = grid_.cellsX();
    snapshot_.cells_y = grid_.cellsY();
    snapshot_.cells = grid_.cells();
    snapshot_.nodes = bvh_.nodes();
    snapshot_.leaf_of_object.resize(bvh_.objectOrder().size());
    for (size_t i = 0; i < snapshot_.leaf_of_object.size(); ++i)
        snapshot_.leaf_of_object[i] = bvh_.leafOf(int(i));
    snapshot_.counters = grid_.counters();
    snapshot_.triangles_drawn = triangles_drawn_;
}

const LazyGridTest* decidingTest(const LazyGridSnapshot& snapshot, int object_index) {
    if (!snapshot.valid || object_index < 0 ||
        size_t(object_index) >= snapshot.leaf_of_object.size())
        return nullptr;
    for (int32_t node = snapshot.leaf_of_object[size_t(object_index)]; node >= 0;
         node = snapshot.nodes[size_t(node)].parent) {
        const int32_t test = snapshot.test_of_node[size_t(node)];
        if (test >= 0) return &snapshot.tests[size_t(test)];
    }
    return nullptr;
}

}  // namespace gridcull
