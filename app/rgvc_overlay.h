// Draws the state of regular-grid culling (culling/rgvc/rgvc_snapshot.h) over the 2D
// view, like Figure 1 of Batagelo & Wu: H as a light veil, O dark, T and I voxels
// marked, the traversal up to a chess layer with that layer and its seed voxel
// highlighted, the line of sight, and a picked extended occluder's extension
// steps and occlusion polygons. Colours and toggles: ui/rgvc/rgvc_view.h.
// O, H, I and T are drawn as they stand at the end of the frame (the snapshot
// keeps no history of them): the layer stepper limits the traversal shown only.
//
// Geometry is world x-y at z = 0. Bit matrices become one quad per run of set
// voxels in a row, so a mostly-filled 256 x 256 O or H costs a few hundred quads,
// not 65k; I marks are one small quad per non-empty voxel. Cost per draw:
// O(grid voxels) scanning + O(visits); vectors keep their capacity, so a steady
// state allocates nothing. Needs a current GL 3.3 core context.
#pragma once
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "app/line_renderer.h"
#include "app/overlay_geometry.h"
#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {

// The overlay's triangles (GL_TRIANGLES) and lines (GL_LINES), without GL, so
// tests can check the mapping. `fill` gets the translucent layers back to front.
struct RgvcOverlayGeometry {
    std::vector<ColorVertex> fill;
    std::vector<ColorVertex> lines;        // thin: line of sight, seed box
    std::vector<ColorVertex> thick_lines;  // the picked occluder and its polygons
    std::vector<uint8_t> mask;             // scratch: per voxel, the traversal state shown
};

// Rebuilds `out` (keeping capacities) for `snapshot` as `view` asks. Nothing when
// the snapshot is not valid.
void buildRgvcOverlay(const RgvcSnapshot& snapshot, const RgvcViewState& view,
                      RgvcOverlayGeometry& out);

class RgvcOverlay {
public:
    bool init(std::string& error) { return line_renderer_.init(error); }
    void draw(const RgvcSnapshot& snapshot, const RgvcViewState& view,
              const glm::mat4& view_projection);

private:
    LineRenderer line_renderer_;
    RgvcOverlayGeometry geometry_;
};

}  // namespace gridcull
