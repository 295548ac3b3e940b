// The Z-pyramid of the hierarchical z-buffer (N. Greene, M. Kass, G. Miller,
// "Hierarchical Z-buffer visibility", SIGGRAPH 1993), as O. Sudarsky and
// C. Gotsman, "Dynamic scene occlusion culling" (IEEE TVCG 1999), describe and
// use it (section 2.1.1 and Fig. 1; section 4 founds the octree-based algorithm
// on it): "The lowest level of the pyramid is a plain Z-buffer; in all other
// levels, there is a pixel for every 2x2 square of pixels in the next lower
// level, with a value equal to the greatest (farthest) z among these four
// pixels."
//
// Depth is the shared rasterizer's (culling/raster/id_depth_buffer.h):
// view-space depth along the camera's forward axis in world units, +infinity
// where nothing was drawn (empty pixels are as far as can be). Level 0 is the
// buffer's width x height depths; level l+1 is ceil(w/2) x ceil(h/2) of level l,
// up to a 1 x 1 top. At an odd edge the last texel of the next level covers one
// texel (or a 1 x 2 or 2 x 1 pair) and takes the farthest of those that exist: it
// never reads past the edge, so every texel at level l is the farthest depth of
// its footprint, the level-0 pixels [x 2^l, min((x+1) 2^l, w) - 1] x [y 2^l,
// min((y+1) 2^l, h) - 1]. A NaN depth counts as +infinity (the conservative
// reading).
//
// The Z query (boxMayBeVisible): a box's screen rectangle (level-0 pixels, as
// culling/raster/screen_mapping.h's ScreenMapping::project gives it) and its
// nearest depth znear. The query takes the lowest level at which the
// rectangle's footprint is at most 2 x 2 texels and answers hidden only when
// every one of those texels is strictly nearer than znear; a tie, a NaN and an
// unbuilt pyramid count as visible. An empty rectangle (no pixel of the image can
// see the box) is hidden. Since every texel is the farthest depth of its
// footprint, which covers the rectangle, "hidden" implies that every level-0
// pixel of the rectangle is nearer than znear: the query is conservative.
//
// Departures from the paper, and why:
// - query() reads one level's 2 x 2 texels (at most 4 reads, O(1)) and stops,
//   instead of Greene's descent from the level where one texel covers the
//   projection into the four texels below whenever that texel cannot decide.
//   Still conservative; it culls less where the rectangle's 2 x 2 block reaches
//   beyond the occluder. queryRefined() descends, within a budget of reads.
// - build() makes the pyramid from a whole z-buffer; refresh() then follows
//   the culler's drawing object by object, over each object's rectangle (as
//   Greene propagates each change up the pyramid), not primitive by primitive.
//
// Memory: resize() (or build() at a new size) allocates every level at once;
// build() at the same size allocates nothing. Levels are readable for display
// (level(), row-major, top row first).
#pragma once
#include <cstddef>
#include <vector>

#include "culling/api/pixel_rect.h"
#include "culling/raster/id_depth_buffer.h"
#include "culling/raster/pixel_range.h"
#include "culling/raster/screen_mapping.h"

namespace gridcull {

// One level of the pyramid, for reading or display.
struct ZPyramidLevel {
    int width = 0;
    int height = 0;
    const double* data = nullptr;  // width * height texels, row-major, top row first
    double at(int x, int y) const { return data[size_t(y) * size_t(width) + size_t(x)]; }
};

// What a Z query decided and what it read.
struct ZQueryResult {
    bool may_be_visible = true;
    int level = -1;       // the level read; -1 when none was
    int texels_read = 0;  // query(): <= 4; queryRefined(): <= its max_reads
};

class ZPyramid {
public:
    // Allocates every level for a width x height level 0 (each >= 1); no-op when
    // the size is unchanged. Texels are left as they were (+infinity when new).
    void resize(int width, int height);
    // Level 0 = the buffer's depths, then every level above. Resizes first if the
    // buffer's size differs. O(pixels).
    void build(const IdDepthBuffer& buffer);
    // The same from width * height row-major depths (top row first).
    void build(int width, int height, const double* depths);
    // Every texel +infinity: the pyramid of a cleared buffer, without reading it.
    void clear();
    // Copies the buffer's depths over columns `cols` and rows `rows` (level-0
    // pixels, clipped to the image) into level 0 and recomputes, on every level
    // above, the texels whose footprint meets them: Greene's propagation of a
    // change up the pyramid, after each object a culler draws (the buffer must
    // have this pyramid's size). O(the rectangle's pixels); allocates nothing.
    void refresh(const IdDepthBuffer& buffer, const ScreenRange& cols, const ScreenRange& rows);

    int width() const { return levels_.empty() ? 0 : levels_[0].width; }
    int height() const { return levels_.empty() ? 0 : levels_[0].height; }
    int levelCount() const { return int(levels_.size()); }
    ZPyramidLevel level(int l) const;

    // The Z query (see above). `rect` is in level-0 pixels and is clipped to the
    // image first. O(1): at most levelCount() steps to pick the level, 4 reads.
    ZQueryResult query(const PixelRect& rect, double znear) const;
    bool boxMayBeVisible(const PixelRect& rect, double znear) const {
        return query(rect, znear).may_be_visible;
    }
    bool boxMayBeVisible(const BoxOnScreen& box) const {
        return query(box.rect, box.znear).may_be_visible;
    }

    // The same query, refined as Greene's hierarchical z-buffer descends: each
    // texel read that cannot hide the box (not strictly nearer than znear) is
    // replaced by its texels one level down that meet the rectangle, until
    // level 0 or until `max_reads` texels have been read (then: visible). Hidden
    // only when every texel it ends on is nearer, so as conservative as query()
    // and never culling less. O(max_reads); allocates nothing.
    ZQueryResult queryRefined(const PixelRect& rect, double znear, int max_reads) const;

    // The lowest level at which rect's texel range is at most 2 x 2 (rect inside
    // the image, not empty).
    int queryLevel(const PixelRect& rect) const;

private:
    struct Level {
        int width = 0;
        int height = 0;
        size_t offset = 0;  // into texels_
    };
    double* texelsOf(int l) { return texels_.data() + levels_[size_t(l)].offset; }
    void reduceAll();  // levels 1.. from level 0
    // Level l + 1's texels [x0, x1] x [y0, y1] from level l (inside level l + 1).
    void reduce(int l, int x0, int x1, int y0, int y1);

    std::vector<Level> levels_;
    std::vector<double> texels_;  // every level, level 0 first
};

}  // namespace gridcull
