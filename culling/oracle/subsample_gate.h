// Which pixels of the oracle's ID buffer could hide an object below its
// sampling: the first half of the 3D oracle's sub-sample question
// (exact_oracle.h, "Sub-sample objects").
//
// A pixel centre tells what is nearest at one point of the pixel, not over its
// square. The square is proven covered when the pixel's centre and its eight
// neighbours' centres all see the same object Y: every shape the buffer draws
// whole (a sphere or a box, cut to [near, far]) is convex, so Y's projection
// contains the convex hull of those nine centres, which contains the pixel's
// square; and over that hull 1 / depth of Y's front surface is concave (the
// least of the affine 1 / depths of its front faces, or of a sphere's), so Y's
// depth anywhere in the square is at most the largest of the nine. An object
// whose nearest depth exceeds that can show nowhere in the square. Every other
// pixel (an edge between objects, the background, the image's border) is open:
// any object whose nearest depth is not nearer than nothing might show there.
//
// Departure for meshes: a mesh is not convex, yet it is treated like the
// shapes above, so a hole or slit within one mesh narrower than the pixel
// spacing is not asked about (docs/LIMITS.md, "Oracle"). Gaps between objects
// are.
//
// gate(px, py) is that largest depth for a covered pixel and +infinity for an
// open one: an object of nearest depth z may show in the pixel only if
// gate >= z. Tiles of 16 x 16 keep their largest gate, so an object hidden
// behind one wide occluder is dismissed tile by tile. build() is O(pixels) and
// allocates only when the size changes.
#pragma once
#include <cstdint>
#include <vector>

#include "culling/raster/id_depth_buffer.h"
#include "culling/raster/pixel_range.h"

namespace gridcull {

class SubsampleGate {
public:
    // From the buffer after a frame's draws (ids written).
    void build(const IdDepthBuffer& buffer);

    double gate(int px, int py) const { return gate_[size_t(py) * size_t(width_) + size_t(px)]; }
    // Whether any pixel of the rectangle may show an object of nearest depth z.
    bool mayShow(const ScreenRange& cols, const ScreenRange& rows, double z) const;

    static constexpr int kTile = 16;

private:
    int width_ = 0, height_ = 0, tiles_x_ = 0;
    std::vector<double> gate_;
    std::vector<double> row_max_;   // per pixel: the largest depth of it and its row neighbours
    std::vector<uint8_t> row_same_; // per pixel: it and its row neighbours hold the same object
    std::vector<double> tile_max_;  // per tile: its largest gate
};

}  // namespace gridcull
