// `lazy-grid`, `lazy-grid-z`, `busy-grid`, `busy-grid-tight`: occlusion culling with the lazy
// occlusion grid of H. Hey, R. F. Tobler, W. Purgathofer, "Real-time occlusion
// culling with a lazy occlusion grid" (2001), 3D scenes only.
//
// Per frame: the BVH (culling/lazy_grid/bounding_volume_hierarchy.h) is refitted to t (or
// rebuilt), the software buffers and the grid (culling/lazy_grid/lazy_grid.h) are cleared,
// and the BVH is traversed front to back with hierarchical view-frustum culling
// (Camera::frustumPlanes, the conservative box test of vfc):
// - lazy-grid-z, the z-buffer variant with the simple traversal of section 4.1,
//   Fig. 4: one list ordered by znear; a box found not occluded has its children
//   sorted into the list, a leaf's objects are drawn at once.
// - lazy-grid and busy-grid, the occlusion-buffer variant with the traversal of
//   section 4.2, Fig. 6: a test-list ordered by znear and a draw-list of leaves
//   rated potentially visible ordered by zfar; the frontmost leaf is drawn only
//   when its zfar is smaller than every znear in the test-list, so every object
//   drawn is wholly in front of every box tested afterwards (ties are tested
//   first). busy-grid updates every cell of a drawn object's image area at once
//   (section 7's "busy update", full cells included, as stated there);
//   busy-grid-tight, a stronger baseline of ours, only the cells under the pixels
//   it wrote that are not full; lazy-grid marks the cells under those pixels
//   outdated.
// The lists are binary heaps (the paper allows heaps; its lists were short).
//
// "Drawing" an object goes through an ImageTarget (culling/api/image_target.h).
// The default, SoftwareImageTarget, rasterizes it with the shared rasterizer
// (culling/raster/id_depth_buffer.h: exact per pixel centre, front-to-back
// skipping; the oracle's too) at the view's resolution, and then sets its
// written pixels in the one-bit occlusion buffer for the occlusion-buffer
// variant. The PVS is the set of objects drawn.
//
// Departures from the paper, and why:
// - Software buffers stand in for the hardware z-buffer and glReadPixels of
//   section 7: no GL in culling/, and the headless commands must give the same
//   answer as the window.
// - A leaf holds one object (the forest's "own bounding box" per primitive); the
//   city's 1500-triangle leaves do not apply, our buildings are single boxes.
// - The view's resolution is LazyGridOptions::resolution (--lazy-res) pixels on
//   the long side (0: the oracle's), the other side from the camera's aspect.
//
// Conservative at the resolution it renders: with --lazy-res equal to the
// oracle's, the PVS contains every object the oracle sees (same pixel centres,
// same depths; the differential tests check this). At another resolution an
// object seen only between this image's pixel centres may be dropped, as any
// image-based method at that resolution would.
//
// Counters: pixel_queries, pixels_read, occlusion_tests, nodes_visited (boxes
// taken from the lists, frustum-culled ones included), triangles_drawn
// (culling/scene/object_triangles.h), bvh_rebuilds, probability_skips (section 6).
// Cost per frame: O(pixels) to clear the buffers, O(objects) to refit, plus the
// traversal: O(log nodes) per node, O(cells) per test, O(pixels) per query and per
// object drawn. Steady state allocates nothing (snapshots aside).
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "culling/api/culler.h"
#include "culling/lazy_grid/bounding_volume_hierarchy.h"
#include "culling/lazy_grid/lazy_grid.h"
#include "culling/lazy_grid/lazy_grid_options.h"
#include "culling/lazy_grid/lazy_grid_snapshot.h"
#include "culling/raster/screen_mapping.h"
#include "culling/raster/software_image_target.h"

namespace gridcull {

class LazyGridCuller final : public Culler {
public:
    // `reference_resolution` is the image side used when options.resolution is
    // 0 (the oracle's, so false culls compare like with like). Draws into the
    // software buffers (SoftwareImageTarget) unless given another target, e.g.
    // the app's OpenGL one; `name` then replaces name() ("" keeps it).
    LazyGridCuller(LazyGridVariant variant, LazyGridUpdate update,
                   const LazyGridOptions& options = {},
                   int reference_resolution = kDefaultImageResolution,
                   std::unique_ptr<ImageTarget> target = nullptr, std::string name = "");
    const char* name() const override;
    void reset(const Scene& scene) override;
    void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) override;
    std::unique_ptr<Culler> clone() const override;

    const LazyGridOptions& options() const { return options_; }
    // Fill snapshot() each frame from now on (off by default).
    void setDebugCapture(bool on) override { snapshot_enabled_ = on; }
    const DebugSnapshot* debugSnapshot() const override {
        return snapshot_.valid ? &snapshot_ : nullptr;
    }
    const LazyGridSnapshot& snapshot() const { return snapshot_; }
    const LazyOcclusionGrid& grid() const { return grid_; }

    // The image side used: options.resolution, or the reference when 0.
    int resolution() const { return resolution_; }
    // The image size for a camera of `aspect`: long side = resolution().
    void imageSize(double aspect, int& width, int& height) const;

private:
    struct ListEntry {
        double key;  // znear (test-list) or zfar (draw-list)
        int32_t node;
        BoxOnScreen box;
    };
    // Heap order: the smallest key on top, ties by node index.
    static bool later(const ListEntry& a, const ListEntry& b) {
        return a.key > b.key || (a.key == b.key && a.node > b.node);
    }
    static ListEntry popFront(std::vector<ListEntry>& list);  // the smallest key
    void traverseFig4(const Scene& scene, const Camera& camera, double t, FrameResult& out);
    void traverseFig6(const Scene& scene, const Camera& camera, double t, FrameResult& out);
    // Sorts node into the test-list if it may intersect the frustum.
    void offerToTestList(int32_t node, const Camera& camera);
    // Runs isOccluded on a node taken from the test-list, recording it.
    bool testNode(const ListEntry& entry);
    void drawLeaf(const Scene& scene, const ListEntry& leaf, double t, FrameResult& out);
    void recordFrustumCull(int32_t node);
    void fillSnapshot();

    LazyGridVariant variant_;
    LazyGridUpdate update_;
    LazyGridOptions options_;
    int resolution_ = kDefaultImageResolution;
    BoundingVolumeHierarchy bvh_;
    ScreenMapping mapping_;
    std::array<glm::dvec4, 6> frustum_planes_{};  // the frame's camera.frustumPlanes()
    OwnedImageTarget target_;  // copied by clone(), null when it cannot be
    std::string name_;
    LazyOcclusionGrid grid_;
    std::vector<ListEntry> test_list_, draw_list_;
    int64_t triangles_drawn_ = 0;
    int64_t nodes_visited_ = 0;
    bool snapshot_enabled_ = false;
    LazyGridSnapshot snapshot_;
};

}  // namespace gridcull
