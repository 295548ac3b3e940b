// What the view shows of regular-grid culling (`rgvc`, culling/rgvc/rgvc_snapshot.h)
// in 2D and 3D and the colours it uses, shared by the rgvc panel
// (ui/rgvc/rgvc_panel.h), which changes it, and the overlays (2D:
// ui/rgvc/rgvc_overlay.h; 3D: ui/rgvc/rgvc_overlay3d.h), which draw it; and the
// description of one voxel for the panel's "voxel under the mouse"
// (ui/rgvc/rgvc_voxel_info.h).
//
// Colours are swatches of the one palette (ui/palette.h), each with one meaning
// here: the picked occluder and its polygons sky blue (picked things), the line
// of sight and the seed voxels on it yellow (the culling camera's), white only
// for the voxel under the pointer (ui/rgvc/rgvc_hovered_voxel.h). The 3D
// overlay draws every fill opaque, so what it shows is exactly the legend's
// swatches (the voxel boxes' frames and the slice's empty voxels are dim grey).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "culling/rgvc/rgvc_snapshot.h"
#include "culling/scene/scene.h"
#include "ui/overlay_preset.h"
#include "ui/palette.h"
#include "ui/rgvc/rgvc_voxel_info.h"

namespace gridcull {

// The layers of the rgvc overlay, each a toggle in the panel.
enum class RgvcLayer {
    Occluder,        // O: opaque voxels, dark
    Occlusion,       // H: occluded voxels, light
    Identifiers,     // I: voxels with object ids, a mark in the voxel
    Tbv,             // T: voxels of TBV curves
    Visited,         // voxels the traversal reached, up to the chosen layer
    CurrentLayer,    // the chosen chess layer
    Seed,            // the chosen layer's seed voxel
    LineOfSight,     // the viewing direction, dashed
    PickedOccluder,  // the picked extended occluder (slider or click): its extension steps
    Polygon,         // the picked occluder's occlusion polygons (3D: its layer's cap)
    StaticOccluder,  // 3D: Os, the static objects' opaque voxels, told apart from O
};
constexpr int kRgvcLayerCount = 11;
// The panel's order: the matrices first.
constexpr RgvcLayer kRgvcLayerOrder[kRgvcLayerCount] = {
    RgvcLayer::Occluder,     RgvcLayer::StaticOccluder,
    RgvcLayer::Occlusion,    RgvcLayer::Identifiers,
    RgvcLayer::Tbv,          RgvcLayer::Visited,
    RgvcLayer::CurrentLayer, RgvcLayer::Seed,
    RgvcLayer::LineOfSight,  RgvcLayer::PickedOccluder,
    RgvcLayer::Polygon};

// Whether the layer exists in scenes of `dimensions` (Os is told apart in 3D only).
bool rgvcLayerApplies(RgvcLayer layer, int dimensions);
const char* rgvcLayerName(RgvcLayer layer);
// What the layer shows, for the legend; `dimensions` 2 or 3.
const char* rgvcLayerMeaning(RgvcLayer layer, int dimensions = 2);
Swatch rgvcLayerSwatch(RgvcLayer layer);
// Opacity the 2D overlay draws the layer's fill with (O and H are veils over the
// objects); the 3D overlay draws every fill opaque.
float rgvcLayerAlpha(RgvcLayer layer);
inline Paint rgvcLayerPaint(RgvcLayer layer) {
    return {rgvcLayerSwatch(layer), rgvcLayerAlpha(layer)};
}

// 3D: what the overlay draws of the matrices: voxel boxes (Figure 6 of the
// paper) or one slice of the grid.
enum class RgvcVoxelMode : uint8_t { Boxes, Slice };

struct RgvcViewState {
    // The toggles of the "all" preset in 2D; a family view starts with its
    // first preset instead (rgvcOverlayPresets).
    bool show[kRgvcLayerCount] = {true, true, true, true, true, true,
                                  true, true, true, true, false};
    int64_t layer = -1;  // chess layer shown up to; -1: every layer (the whole traversal)
    // The picked occluder: 2D, index into RgvcSnapshot::occluders; 3D, into
    // RgvcSnapshot::occluders3d. -1: none picked.
    int occluder = -1;
    // 3D.
    RgvcVoxelMode mode = RgvcVoxelMode::Boxes;
    int slice_axis = 1;    // 0 x, 1 y, 2 z: the slice is the plane of voxels with this index
    int slice_index = -1;  // -1: the plane through the viewer's voxel (clamped to the grid)

    bool shown(RgvcLayer l) const { return show[int(l)]; }
};

// The overlay presets, the first the one a view starts with: "occlusion only"
// (O, Os in 3D, H, and a picked occluder's extension and polygons, the
// paper's steps 3 and 4), "traversal" (the chess layers visited, the current
// one, its seed, the line of sight; 2D also O, where the search found its
// occluders), "TBVs" (T and the ids in I that TBVs hold back) and "all". The
// issue they answer: all ten layers at once mix into colours the legend lacks.
std::vector<OverlayPreset> rgvcOverlayPresets();
// Sets view.show to `preset` for scenes of `dimensions`. Os applies in 3D only;
// T is shown in 3D only when a preset asks for it ("TBVs", "all"): its boxes
// wall in everything behind the TBVs of many hidden movers.
void rgvcApplyPreset(RgvcViewState& view, OverlayPreset preset, int dimensions);

// The slice's index along view.slice_axis in `snapshot`'s grid (the default and
// out-of-range values resolved).
int rgvcSliceIndex(const RgvcSnapshot& snapshot, const RgvcViewState& view);

// The extended occluder a click on voxel `v` picks: the one that starts there,
// else the first (in traversal order) that covers it (its L, or either L of a
// staircase); -1 when none. O(occluders).
int rgvcOccluderAt(const RgvcSnapshot& snapshot, glm::ivec2 v);

// The layer the view shows as current: `requested` clamped to the snapshot's
// traversed layers, or the last one for -1. -1 when nothing was traversed.
int64_t rgvcShownLayer(const RgvcSnapshot& snapshot, int64_t requested);

}  // namespace gridcull
