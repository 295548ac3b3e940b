// What a lazy occlusion grid culler (culling/lazy_grid/lazy_grid_culler.h) did in its last
// frame, for the window and for tests: the image and cell size, every cell's
// state at the end of the frame, the traversal in order (each bounding volume
// tested with its rectangle, znear, result, deciding step and the cells it
// touched; each object drawn with its zfar), and the BVH's boxes.
//
// Filled only while LazyGridCuller::setDebugCapture(true); otherwise only
// `valid` (false) is kept, so culling pays nothing for it. Everything is owned by
// the snapshot. Object numbers are indices into Scene::objects.
#pragma once
#include <cstdint>
#include <vector>

#include "culling/api/debug_snapshot.h"
#include "culling/lazy_grid/bounding_volume_hierarchy.h"
#include "culling/lazy_grid/lazy_grid.h"

namespace gridcull {

// One occlusion test of a bounding volume (a BVH node).
struct LazyGridTest {
    int32_t node = 0;
    BoxOnScreen box;
    bool in_frustum = true;  // false: culled by hierarchical view-frustum culling, no cells read
    bool occluded = false;
    OcclusionStep step = OcclusionStep::Occluded;
    int32_t first_touch = 0, touch_count = 0;  // into LazyGridSnapshot::touches
};

// One step of the traversal, in order.
struct LazyGridEvent {
    enum Kind : uint8_t { Test, Draw } kind = Test;
    int32_t index = 0;   // Test: into tests; Draw: the object index drawn
    double depth = 0.0;  // Test: the box's znear; Draw: the drawn leaf box's zfar
    PixelRect written;   // Draw: the pixels the draw may have written
};

struct LazyGridSnapshot final : DebugSnapshot {
    static const DebugSnapshotKind kKind;
    LazyGridSnapshot() : DebugSnapshot(kKind) {}

    bool valid = false;
    LazyGridVariant variant = LazyGridVariant::OcclusionBuffer;
    LazyGridUpdate update = LazyGridUpdate::Lazy;
    int width = 0, height = 0;  // the image the grid covers, pixels
    int cell_size = 0, cells_x = 0, cells_y = 0;
    std::vector<LazyGridCell> cells;  // row-major from the top-left, at the end of the frame
    std::vector<LazyGridTest> tests;
    std::vector<CellTouch> touches;
    std::vector<LazyGridEvent> events;
    std::vector<int32_t> test_of_node;  // per BVH node: its test this frame, or -1
    std::vector<BvhNode> nodes;         // the BVH as refitted for this frame
    std::vector<int32_t> leaf_of_object;
    LazyGridCounters counters;
    int64_t triangles_drawn = 0;
};

// The test that decided object `object_index` this frame: its leaf's test, or
// the deepest tested ancestor (which was found occluded or outside the frustum).
// nullptr when nothing on its path was tested (an ancestor never reached).
const LazyGridTest* decidingTest(const LazyGridSnapshot& snapshot, int object_index);

}  // namespace gridcull
