// The slice of the 3D rgvc overlay: one plane of voxels of the grid (index
// `slice_index` along `slice_axis`), each drawn as a square in World space on
// the plane through the voxels' centres, showing the matrices as they stood at
// the shown layer (ui/rgvc/rgvc_history.h). One square per voxel, in the swatch
// of the first shown layer that holds it: T (the 2-of-3 test), O (or Os), H,
// the shown layer's visited voxels (solid), voxels visited in earlier layers
// (a smaller tile, so the layer's ring stands out); then a small centre mark
// where I holds ids. Everything opaque, nothing blended, over the plane drawn
// in kRgvcSliceBackdrop (the scene behind does not show through); the
// plane's extent is outlined in the grid-line grey.
//
// Cost per draw: O(voxels of the plane); squares of one swatch in a row merge
// into one rectangle, tiles and marks are one quad per voxel.
#pragma once
#include <cstdint>

#include <glm/vec3.hpp>

#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/debug_draw.h"
#include "ui/rgvc/rgvc_frame_index.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {

enum class RgvcSliceCell : uint8_t {
    None,
    Tbv,
    Occluder,
    StaticOccluder,
    Occlusion,
    Layer,    // visited in the shown layer
    Visited,  // visited in an earlier layer
};

// What voxel (x, y, z) of the slice shows at `layer`. `index` must be updated
// for the snapshot and layer.
RgvcSliceCell rgvcSliceCellAt(const RgvcSnapshot& s, const RgvcViewState& view,
                              const RgvcFrameIndex& index, int64_t layer, int x, int y, int z);
// The legend row of a slice cell.
RgvcLayer rgvcSliceCellLayer(RgvcSliceCell cell);

// The world coordinate, on the slice's axis, of the plane the slice is drawn on.
double rgvcSlicePlane(const RegularGrid& grid, int axis, int index);

// The colour of the slice's voxels that no shown layer holds: the receding
// grey of culled objects, under every swatch of the legend.
constexpr Swatch kRgvcSliceBackdrop = Swatch::DimGrey;

// Side of an I mark and of an earlier-visited tile, as fractions of the voxel.
constexpr double kRgvcMarkFraction = 0.4;
constexpr double kRgvcTileFraction = 0.7;

void drawRgvcSlice(const RgvcSnapshot& s, const RgvcViewState& view, const RgvcFrameIndex& index,
                   int64_t layer, DebugDraw& draw);

}  // namespace gridcull
