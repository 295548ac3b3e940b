// Which pixels a triangle mesh may reach, and a lower bound of its depth in each:
// the sub-sample gate's per-pixel test for meshes (subsample_refiner.h). A
// mesh's bounding box reaches far more pixels than the mesh (the bunny's box
// holds twice its silhouette), and each of them can leave a hidden mesh
// undecided.
//
// Each triangle, cut to depth >= near, marks the pixels its projection's
// bounding rectangle touches with its least depth. The mesh's part inside a
// pixel's pyramid lies on triangles whose projection meets the pixel square, so
// every such pixel is marked, no deeper than that part.
//
// Not built (build() false, the caller keeps the bounding box) for a closed mesh
// that the near plane may cut: the rasterizer fills the cut's inside at depth
// near, where no triangle projects. Nor when the triangles' rectangles add up to
// more than kMaxWork times the rectangle asked for (a mesh of large triangles),
// which bounds the cost.
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "culling/oracle/pixel_pyramid.h"
#include "culling/raster/pixel_range.h"
#include "culling/scene/scene.h"

namespace gridcull {

class MeshFootprint {
public:
    static constexpr int kMaxWork = 16;

    // Over the pixels cols x rows, for the mesh placed at `offset` (its
    // vertices are relative to it). Allocates only when the rectangle is larger
    // than any before.
    bool build(const PixelView& view, const TriangleMesh& mesh, const glm::dvec3& offset,
               const ScreenRange& cols, const ScreenRange& rows);

    // In the built rectangle: +infinity where no triangle reaches pixel
    // (px, py), else a lower bound of the mesh's depth (view z) there.
    double leastDepth(int px, int py) const {
        return least_[size_t(py - rows_.lo) * size_t(cols_.hi - cols_.lo + 1) + size_t(px - cols_.lo)];
    }

private:
    ScreenRange cols_, rows_;
    std::vector<double> least_;
};

}  // namespace gridcull
