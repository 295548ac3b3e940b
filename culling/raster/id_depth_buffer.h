// The shared software rasterizer: an object-ID buffer with a depth per pixel,
// filled by exact per-pixel intersection. The exact oracle's 3D half
// (culling/oracle/exact_oracle.h) and the software image target of the
// image-space cullers (software_image_target.h) are its clients; its own
// brute-force tests (tests/culling/raster/) check it pixel by pixel.
//
// Pixel (px, py), px in [0, width), py in [0, height) from the top, is sampled at
// its centre: the ray eye + s * (forward + u*right + v*up) with
//   u = (2 (px + 0.5) / width - 1) * tan(fov_y / 2) * aspect,
//   v = (1 - 2 (py + 0.5) / height) * tan(fov_y / 2),
// right/up/forward from Camera::basis. The forward component is 1, so s is the
// view-space depth along the forward axis (world units), and a pixel keeps the
// nearest s in [near, far]. The pixel grid covers exactly the camera's frustum
// (aspect from the camera, not from width / height).
//
// Spheres and boxes are intersected exactly (culling/scene/ray_intersect.h); a ray that
// starts inside one, or whose near-plane point is inside, meets it at depth near.
// Boxes use lineBox's slab test with its reciprocals 1 / dir[a] taken from
// per-frame tables where a direction component depends on the row alone
// (right[a] = 0) or the column alone (up[a] = 0): a level camera (forward.y = 0)
// has x and z by column and y by row (x or z by row too when it looks along a
// world axis), so a box's column slab interval is computed once per column and
// its row interval once per row, and a pixel only intersects the two, in runs
// without branches (level_box_run.h, two pixels at a time). The products and
// min/max are lineBox's, so every depth is the same double as the plain
// per-pixel test gives (tests/culling/raster/id_depth_buffer_box_test.cpp, no
// tolerance); other cameras divide per pixel.
// Meshes are rasterized triangle by triangle: near-plane clipping, a fill rule
// that gives a pixel centre on an edge shared by two triangles to exactly one
// of them (the right and bottom edges own theirs, as the image is shown),
// perspective-correct depth, no back-face culling. A closed mesh is solid:
// where its triangles enclose the near-plane point (odd crossing count behind it)
// it is written at depth near, so the cap the near plane cuts off still occludes.
//
// Only candidate pixels are tested, never fewer than can be hit: for a sphere in
// front of the eye plane the rows between its tangent planes through the eye and
// per row the interval of columns solving the ray-sphere quadratic; for anything
// that crosses the eye plane, the projection of its part at depth >= near (the
// near plane clips it to a bounded convex piece); for a box, the projection of
// its corners and near-plane edge crossings; for a triangle, its clipped bounds.
//
// Draw calls compare with a strict "<": of two objects at exactly the same depth
// the one drawn first keeps the pixel. Draw front to back (minDepth*) for speed:
// each call skips pixels whose stored depth is already nearer than the object,
// and whole 16 x 16 tiles whose farthest stored depth is (a coarse max-depth
// buffer refreshed after each draw; a stale tile only errs towards "farther", so
// the skipping never changes the result). No call allocates; resize() does.
// A client that reads depths only turns the object ids off (setWriteIds):
// nothing is then cleared or written in the id buffer. begin() clears only the
// bounding rectangle of what was written since the previous begin(). Spheres
// compute the far root of their quadratic only when the near one is not already
// the answer (same depths, bit for bit; tested like boxes).
#pragma once
#include <algorithm>
#include <climits>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/raster/pixel_range.h"
#include "culling/scene/camera.h"
#include "culling/scene/scene.h"

namespace gridcull {

// The largest side of any image the software buffers are made at, so that no
// option can ask for more memory than a desktop has: 8192 x 4608 pixels take
// about 470 MiB (depth, id and parity per pixel).
constexpr int kMaxImageResolution = 8192;
// The default long side of the software images (the oracle's, and so the
// image-space cullers' that follow it).
constexpr int kDefaultImageResolution = 1024;

// The size of an image over a camera of `aspect` (width / height) with
// `long_side` pixels on its long side (clamped to [1, kMaxImageResolution]) and
// the other side in proportion, at least 1. A non-positive or non-finite aspect
// counts as 1.
void imageSizeForAspect(int long_side, double aspect, int& width, int& height);

class IdDepthBuffer {
public:
    // Allocates width * height pixels (each >= 1); no-op when the size is unchanged.
    void resize(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }
    // Makes room for meshes of up to `vertices` vertices, so drawMesh never allocates.
    void reserveMeshVertices(size_t vertices) { view_vertices_.reserve(vertices); }

    // Whether draws write object indices (default true). A client that reads
    // depths only (the software image target) turns them off: no index is
    // cleared or written, and markVisible must not be called. Takes effect at
    // the next begin().
    void setWriteIds(bool write) { write_ids_ = write; }

    // Takes the camera for the following draw calls and clears every pixel.
    void begin(const Camera& camera);

    // A lower bound of the depth of any point of the shape (may be < near or < 0).
    double minDepthOfSphere(const glm::dvec3& center, double radius) const;
    double minDepthOfBox(const Aabb& box) const;

    // Each draw writes `index` into the pixels it wins and returns false when the
    // object was rejected as a whole (outside [near, far] or off screen).
    // Cost: O(pixels of the object's screen bound), plus O(triangles) for meshes.
    bool drawSphere(int index, const glm::dvec3& center, double radius);
    bool drawBox(int index, const Aabb& box);
    // mesh.vertices[i] + offset are the world positions (offset = the object's
    // center plus its displacement).
    bool drawMesh(int index, const TriangleMesh& mesh, const glm::dvec3& offset);
    // `triangles` triangles of three corners each (corners[3t..3t+2]) + offset,
    // as an open surface (no near-plane fill: a part of a mesh is not closed).
    // Cost: O(triangles + pixels of their screen bounds).
    bool drawTriangles(int index, const glm::dvec3* corners, size_t triangles,
                       const glm::dvec3& offset);

    // The scene object moved by `shift`, by its shape (a polygon, 2D only, draws
    // nothing and returns false).
    bool drawObject(int index, const SceneObject& object, const glm::dvec3& shift);

    // The depth test alone, for occlusion queries (culling/api/occlusion_queries.h):
    // does some pixel centre whose ray enters `box` at a depth s in [near, far]
    // have s < its stored depth (+infinity where empty)? That is, would
    // drawBox(box) write any pixel? Nothing is written. Parts of the box nearer
    // than near are clipped as drawBox clips them; a box containing the eye passes
    // (drawBox would fill the screen at near). Cost: O(pixels of the box's
    // screen bound) at worst, stopping at the first passing pixel and skipping the
    // tiles whose farthest depth is already nearer than the box.
    bool boxPassesDepthTest(const Aabb& box) const;

    // Sets seen[index] = 1 for every index left in the buffer; seen must be large
    // enough for every index drawn. O(pixels).
    void markVisible(std::vector<char>& seen) const;

    // Read access for the clients that use this buffer as a software z-buffer
    // (SoftwareImageTarget): row py's depths (+infinity where nothing was drawn),
    // and the pixel rectangle that the last draw call returning true may have
    // written (a call returning false writes nothing and leaves it as it was).
    const double* depthRow(int py) const { return depth_.data() + size_t(py) * size_t(width_); }
    // Row py's object indices (-1 where nothing was drawn); needs setWriteIds(true).
    const int32_t* indexRow(int py) const { return index_.data() + size_t(py) * size_t(width_); }
    // The pixels whose squares the part of `box` at depth >= near may cover
    // (widened by up to one pixel), and that part's least depth; false when the
    // box lies wholly outside [near, far] or off screen. A box containing the
    // eye covers the whole screen from depth near.
    bool screenBounds(const Aabb& box, ScreenRange& cols, ScreenRange& rows, double& z_min) const;
    ScreenRange lastDrawCols() const { return last_cols_; }
    ScreenRange lastDrawRows() const { return last_rows_; }

private:
    struct ScreenVertex {
        double x, y;   // continuous pixel coordinates, pixel centres at +0.5
        double inv_z;  // 1 / depth
    };
    glm::dvec3 toView(const glm::dvec3& world) const;
    double columnOf(double u) const;  // continuous pixel column of slope u
    double rowOf(double v) const;     // continuous pixel row of slope v
    void fillNear(int index);         // the whole screen at depth near: the camera is inside
    // A draw whose every pixel is already nearer: accepted, nothing written.
    bool hiddenWhole() {
        last_cols_ = last_rows_ = ScreenRange{};
        return true;
    }
    // The candidate pixels of `box` (the eye outside it) and the least depth of its
    // part at depth >= near; false when it is rejected whole.
    bool boxCandidates(const Aabb& box, ScreenRange& cols, ScreenRange& rows, double& z_min) const;
    // Calls visit(px, py, s) for each candidate pixel whose ray enters `box` at a
    // depth s in [near, far] nearer than the stored depth, row by row, until
    // visit returns true. Shared by drawBox (which writes) and
    // boxPassesDepthTest (which stops at the first). Under a level camera (each
    // axis by column or by row) it hands whole runs of a row to
    // level_run(py, lo, hi, row_lo, row_hi) instead, the row's slab interval
    // being [row_lo, row_hi] and the columns' in box_col_lo_ / box_col_hi_;
    // the run decides its pixels with levelBoxEntry and returns true to stop.
    template <typename Visit, typename LevelRun>
    void forBoxHits(const Aabb& box, double z_min, const ScreenRange& cols, const ScreenRange& rows,
                    Visit&& visit, LevelRun&& level_run) const;
    // Rasterizes one view-space triangle with z >= near everywhere: depth-tested
    // into the buffer, or (parity) toggling parity_ without any depth test.
    void rasterTriangle(int index, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                        bool parity);
    // Clips a view-space triangle at z = near and rasterizes what remains.
    void clipAndRaster(int index, const glm::dvec3 tri[3], bool parity);

    // The coarse max-depth buffer. A write marks its pixel dirty; refreshTiles()
    // recomputes the tiles under the dirty rectangle. Between the two, a tile's
    // value is still >= every depth in it, which is all the skipping relies on.
    static constexpr int kTile = 16;
    void markDirty(int px, int py) {
        dirty_cols_.lo = std::min(dirty_cols_.lo, px);
        dirty_cols_.hi = std::max(dirty_cols_.hi, px);
        dirty_rows_.lo = std::min(dirty_rows_.lo, py);
        dirty_rows_.hi = std::max(dirty_rows_.hi, py);
    }
    void markAllDirty() {
        dirty_cols_ = {0, width_ - 1};
        dirty_rows_ = {0, height_ - 1};
    }
    void refreshTiles();
    // Calls span(lo, hi) for the runs of [col_lo, col_hi] in row py left once
    // the tiles whose farthest depth is already <= z are skipped (neighbouring
    // tiles that are not skipped make one run), until span returns true.
    template <typename Span>
    void forTileSpans(int py, int col_lo, int col_hi, double z, Span&& span) const {
        const double* tiles = tile_far_.data() + size_t(py / kTile) * size_t(tiles_x_);
        int run_lo = -1;  // start of the current run, -1 between runs
        for (int px = col_lo; px <= col_hi;) {
            const int end = std::min(col_hi, (px / kTile + 1) * kTile - 1);
            if (tiles[px / kTile] > z) {
                if (run_lo < 0) run_lo = px;
            } else if (run_lo >= 0) {
                if (span(run_lo, px - 1)) return;
                run_lo = -1;
            }
            px = end + 1;
        }
        if (run_lo >= 0) span(run_lo, col_hi);
    }
    // Calls visit(px) for px in [col_lo, col_hi] of row py, skipping the tiles
    // whose farthest depth is already <= z.
    // (Its own loop rather than forTileSpans': the compiler then inlines a
    // sphere's per-pixel body, which it did not through two lambdas.)
    template <typename Visit>
    void forTileSegments(int py, int col_lo, int col_hi, double z, Visit&& visit) const {
        const double* tiles = tile_far_.data() + size_t(py / kTile) * size_t(tiles_x_);
        for (int px = col_lo; px <= col_hi;) {
            const int end = std::min(col_hi, (px / kTile + 1) * kTile - 1);
            if (tiles[px / kTile] > z)
                for (int x = px; x <= end; ++x) visit(x);
            px = end + 1;
        }
    }
    // May some pixel in the rectangle hold a depth farther than z?
    bool mayBeNearer(const ScreenRange& cols, const ScreenRange& rows, double z) const;

    int width_ = 0;
    int height_ = 0;
    std::vector<double> depth_;
    std::vector<int32_t> index_;   // -1 where nothing was hit (when write_ids_)
    bool write_ids_ = true;
    std::vector<uint8_t> parity_;  // per-pixel crossing parity of one closed mesh
    std::vector<double> column_u_;
    std::vector<double> row_v_;
    // The box slab test's per-frame tables (begin(), forBoxHits): per axis,
    // whether 1 / dir[a] is constant along a row, along a column, or neither;
    // the column reciprocals (3 x width) and the columns where one is 1 / 0.
    enum class AxisMode : uint8_t { Row, Column, Pixel };
    AxisMode axis_mode_[3] = {AxisMode::Pixel, AxisMode::Pixel, AxisMode::Pixel};
    std::vector<double> column_inv_;
    std::vector<uint8_t> column_zero_;
    bool any_column_zero_ = false;
    // One box's slab interval per column from the column axes (forBoxHits).
    mutable std::vector<double> box_col_lo_, box_col_hi_;
    std::vector<glm::dvec3> view_vertices_;  // one mesh's vertices in view space
    std::vector<double> tile_far_;           // per tile: its farthest stored depth
    int tiles_x_ = 0;
    int tiles_y_ = 0;
    ScreenRange dirty_cols_{INT_MAX, -1};  // written since the last refreshTiles()
    ScreenRange dirty_rows_{INT_MAX, -1};
    ScreenRange last_cols_{INT_MAX, -1};  // the dirty rectangle of the last draw
    ScreenRange last_rows_{INT_MAX, -1};
    // Everything written since begin() (the next begin() clears only that), and
    // whether the next begin() must clear every pixel (after resize(), or ids
    // turned on after frames that did not clear them).
    ScreenRange frame_cols_{INT_MAX, -1};
    ScreenRange frame_rows_{INT_MAX, -1};
    bool clear_all_ = true;
    bool ids_cleared_ = false;

    glm::dvec3 eye_{0.0}, right_{1, 0, 0}, up_{0, 1, 0}, forward_{0, 0, 1};
    double tan_x_ = 1.0, tan_y_ = 1.0;
    double near_ = 0.1, far_ = 1000.0;
};

}  // namespace gridcull
