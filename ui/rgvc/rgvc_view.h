// What the 2D view shows of regular-grid culling (`rgvc`, culling/rgvc/rgvc_snapshot.h)
// and the colours it uses, shared by the rgvc panel (ui/rgvc/rgvc_panel.h), which
// changes it, and the overlay (ui/rgvc/rgvc_overlay.h), which draws it; and the
// description of one voxel for the panel's "voxel under the mouse".
//
// Colours are swatches of the one palette (ui/palette.h).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "culling/rgvc/rgvc_snapshot.h"
#include "culling/scene/scene.h"
#include "ui/palette.h"

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
    Polygon,         // the picked occluder's occlusion polygons
};
constexpr int kRgvcLayerCount = 10;

const char* rgvcLayerName(RgvcLayer layer);
const char* rgvcLayerMeaning(RgvcLayer layer);
Swatch rgvcLayerSwatch(RgvcLayer layer);
// Opacity the overlay draws the layer's fill with (O and H are veils over the objects).
float rgvcLayerAlpha(RgvcLayer layer);
inline Paint rgvcLayerPaint(RgvcLayer layer) {
    return {rgvcLayerSwatch(layer), rgvcLayerAlpha(layer)};
}

struct RgvcViewState {
    bool show[kRgvcLayerCount] = {true, true, true, true, true, true, true, true, true, true};
    int64_t layer = -1;  // chess layer shown up to; -1: every layer (the whole traversal)
    int occluder = -1;   // index into RgvcSnapshot::occluders; -1: none picked

    bool shown(RgvcLayer l) const { return show[int(l)]; }
};

// Everything the culler knows about one voxel. `ids_i` / `ids_t` are object ids
// (Scene::objects[i].id), ascending; their capacity is reused between calls.
struct RgvcVoxelInfo {
    bool valid = false;  // false: outside the grid or no snapshot
    glm::ivec2 voxel{0};
    bool o = false, os = false, h = false;
    std::vector<int> ids_i;
    std::vector<int> ids_t;
    int64_t visit_order = -1;  // index in RgvcSnapshot::visits; -1: not visited
    int64_t layer = -1;        // chess layer of that visit
    bool visited_occluded = false;
};

// Fills `out` for voxel `v` of `snapshot`. Cost: O(visits) for the visit search
// plus the voxel's list lengths; allocates only when the id lists outgrow `out`.
void describeRgvcVoxel(const RgvcSnapshot& snapshot, const Scene& scene, glm::ivec2 v,
                       RgvcVoxelInfo& out);

// The extended occluder a click on voxel `v` picks: the one that starts there,
// else the first (in traversal order) whose L covers it; -1 when none. O(occluders).
int rgvcOccluderAt(const RgvcSnapshot& snapshot, glm::ivec2 v);

// The layer the view shows as current: `requested` clamped to the snapshot's
// traversed layers, or the last one for -1. -1 when nothing was traversed.
int64_t rgvcShownLayer(const RgvcSnapshot& snapshot, int64_t requested);

}  // namespace gridcull
