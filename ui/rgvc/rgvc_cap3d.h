// A picked 3D occluder's cap (Batagelo & Wu, section 5.3), for the window: the
// occluder (RgvcSnapshot::occluders3d) lies on a face of its chess layer's cube
// shell; the face's blocking voxels (in H, or in O and wholly beyond the near
// plane, as the matrices stood after that layer: ui/rgvc/rgvc_history.h) form
// a bitmap, which BitmapVectorizer (grid/bitmap_vectorize.h) turns into the
// cap's rectilinear polygons with holes, drawn on the face's outer plane (the
// side away from the eye) and extruded away from the eye: for the polygon the
// occluder's voxel lies in, a ray from the eye through each outline corner to
// where it leaves the grid. With them the
// direction-map cells whose covering the occluder's pass made
// (RgvcSnapshot::direction_cause), each drawn where its rays cross the cap's
// plane.
//
// Which face: a voxel on an edge of the shell lies on two or three faces; the
// cap is the one of the first axis (x, then y, then z) on which it is at chess
// distance, the face the traversal swept it with. The culler fuses caps across
// the shell's edges (culling/rgvc/rgvc_occlusion3d.h); this shows one face's.
// Only the face's part inside the grid is a bitmap.
//
// Cost of a build: O(face voxels + direction-map cells); kept until the
// snapshot or the occluder changes. A draw: O(corners + cells).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/rgvc/rgvc_snapshot_stamp.h"
#include "grid/bitmap_vectorize.h"
#include "ui/debug_draw.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {

// Does voxel (x, y, z) block for layer `layer`'s cap: in H then, or in O then
// and wholly beyond the near plane at `near` from the viewpoint along the view
// direction?
bool rgvcBlocksAtLayer(const RgvcSnapshot& s, double near, int x, int y, int z, int64_t layer);

struct RgvcCap3d {
    bool valid = false;
    int occluder = -1;  // index in RgvcSnapshot::occluders3d
    int32_t layer = 0;
    int axis = 0, sign = 1;  // the face: voxels with index viewer[axis] + sign * layer on axis
    int fixed = 0;           // that index
    double plane = 0.0;      // the face's outer side, world coordinate on `axis`
    int b = 1, c = 2;        // the in-face axes, (axis + 1) % 3 and (axis + 2) % 3
    int b0 = 0, c0 = 0;      // voxel indices of bitmap pixel (0, 0)
    int width = 0, height = 0;
    int64_t blocking = 0;  // filled pixels
    int holes = 0;         // loops that are holes
    // The index in the vectorizer's loops of the outer loop of the polygon
    // holding the occluder's voxel (its extrusion is drawn), -1 when none.
    int component = -1;
    BitmapVectorizer vectorizer;
    std::vector<uint8_t> filled;  // the bitmap, pixel (u, w) at w * width + u
    std::vector<int32_t> cells;   // direction-map cells (cellIndex) its pass covered
    // What it was built from.
    RgvcSnapshotStamp built_from;

    // A point of the cap's plane in pixel-corner coordinates (u along b, w along c).
    glm::dvec3 world(const RgvcSnapshot& s, double u, double w) const;
};

// Fills `cap` for occluders3d[index] of `s`, unless it holds that one already
// (a build per snapshot frame and occluder). `near`: the culling camera's.
void buildRgvcCap3d(const RgvcSnapshot& s, double near, int index, RgvcCap3d& cap);

// The most extrusion rays drawn; a polygon with more outline corners draws
// every k-th corner's.
constexpr int kRgvcMaxExtrusionRays = 64;

// Does the closed loop `corners[0, count)` (lattice points) hold point (x, y)
// (not on it)? Crossing count. O(count).
bool rgvcLoopHolds(const glm::ivec2* corners, int count, double x, double y);

// Draws the picked voxel and its cells (PickedOccluder), the cap and its
// extrusion (Polygon), as `view` shows them. World space.
void drawRgvcCap3d(const RgvcSnapshot& s, const RgvcViewState& view, const RgvcCap3d& cap,
                   DebugDraw& draw);

}  // namespace gridcull
