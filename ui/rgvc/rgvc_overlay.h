// Draws the state of regular-grid culling (culling/rgvc/rgvc_snapshot.h) over the
// 2D view (3D: ui/rgvc/rgvc_overlay3d.h), like Figure 1 of Batagelo & Wu: H as
// a light veil, O dark, T and I voxels marked, the traversal up to a chess
// layer with that layer and its seed voxel highlighted, the line of sight, and
// a picked extended occluder's extension steps and occlusion polygons. Colours
// and toggles: ui/rgvc/rgvc_view.h.
// O, H, I and T are drawn as they stood after the shown chess layer
// (ui/rgvc/rgvc_history.h), so stepping the layers replays the frame.
//
// Everything is World space, x-y at z = 0, through the DebugDraw interface
// (ui/debug_draw.h). Bit matrices become one rectangle per run of set voxels in
// a row, so a mostly-filled 256 x 256 O or H costs a few hundred quads, not 65k;
// I marks are one small quad per non-empty voxel. Cost per draw: O(grid voxels)
// scanning + O(visits); `scratch` keeps its capacity, so a steady state
// allocates nothing.
#pragma once
#include <cstdint>
#include <vector>

#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/debug_draw.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {

// Emits the overlay for `snapshot` as `view` asks; nothing when the snapshot is
// not valid. `scratch` holds per-voxel traversal marks between calls.
void drawRgvcOverlay(const RgvcSnapshot& snapshot, const RgvcViewState& view, DebugDraw& draw,
                     std::vector<uint8_t>& scratch);

}  // namespace gridcull
