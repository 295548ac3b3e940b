// Draws the state of regular-grid culling in a 3D scene (culling/rgvc/rgvc_snapshot.h)
// over the view, through the view's camera (World space, ui/debug_draw.h):
//  - the matrices as they stood at the shown chess layer (ui/rgvc/rgvc_history.h),
//    as voxel boxes like Figure 6 of Batagelo & Wu (ui/rgvc/rgvc_voxel_boxes.h)
//    or as one slice of the grid along x, y or z (ui/rgvc/rgvc_slice.h);
//  - the shown layer's cube shell: its visited voxels (a box kind, or the
//    slice's ring) and its outline (the shell's box, cut to the grid; in a slice
//    the shell's cross-section);
//  - the layer's seed voxel (a white box, and one two voxels out) and the
//    line of sight, dashed;
//  - a picked occluder: its voxel, the direction-map cells its pass covered,
//    its layer's cap and the cap's extrusion (ui/rgvc/rgvc_cap3d.h).
// Fills first (boxes back to front, or the slice), then the lines over them,
// as the debug-draw batch's fixed order has it. Colours and toggles:
// ui/rgvc/rgvc_view.h. Cost: the boxes' or the slice's (see there) plus
// O(shell edges + corners of the cap); `scratch` keeps every buffer, so a
// steady state allocates nothing.
#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/debug_draw.h"
#include "ui/rgvc/rgvc_cap3d.h"
#include "ui/rgvc/rgvc_frame_index.h"
#include "ui/rgvc/rgvc_view.h"
#include "ui/rgvc/rgvc_voxel_boxes.h"

namespace gridcull {

struct RgvcOverlay3dScratch {
    RgvcFrameIndex index;
    RgvcVoxelBoxes boxes;
    RgvcCap3d cap;
};

// The position of the camera whose World-to-clip matrix is `view_projection`;
// for a camera at infinity (parallel projection, or a degenerate matrix such
// as the identity) a point far out along its viewing direction from the
// middle of `grid`, which orders boxes the same way.
glm::dvec3 rgvcViewEye(const glm::dmat4& view_projection, const RegularGrid& grid);

// Emits the overlay for a valid 3D `snapshot` as `view` asks. `near`: the
// culling camera's near distance (which opaque voxels block in a cap); `eye`:
// the view camera's position (rgvcViewEye), which orders the boxes.
void drawRgvcOverlay3d(const RgvcSnapshot& snapshot, const RgvcViewState& view, double near,
                       const glm::dvec3& eye, DebugDraw& draw, RgvcOverlay3dScratch& scratch);

}  // namespace gridcull
