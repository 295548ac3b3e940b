// The voxel boxes of the 3D rgvc overlay, as in Figure 6 of Batagelo & Wu: the
// opaque (O) and occluded (H) voxels of a 3D grid as boxes in World space, seen
// through the view's camera; with them the TBV voxels (T, by the 2-of-3 test)
// and the shown chess layer's visited voxels (its part of the cube shell).
// Each box is one swatch of the legend, drawn opaque, each face framed in dim
// grey (kFrameSwatch) so that boxes read as boxes; nothing is blended, so the
// view holds no colour the legend does not name.
//
// Depth without a depth buffer (the debug-draw interface has none): a box face
// is emitted only if it faces the eye and the neighbouring voxel behind it
// (towards the eye) is not drawn, and faces go back to front by the voxel's
// Manhattan distance, in voxels, from the eye's voxel. That order is exact for
// unit boxes in perspective: if box A hides part of box B, some ray from the
// eye meets A on its way to B, so on every axis A's index lies between the
// eye's and B's, and A is nearer on the axes where they differ. A face's own
// neighbour is nearer still, so skipping covered faces hides nothing.
//
// Cost: classifying every voxel, O(grid voxels) (600k at 100 x 60 x 100, tens
// of milliseconds), only when the snapshot, the layer or the toggles change;
// finding and sorting the faces, O(grid voxels) with a light constant, only
// when the eye moves to another voxel; then O(faces drawn) per draw, 4
// triangles each. Only faces between a drawn and an undrawn voxel, facing the
// eye, are drawn, so a solid region costs its visible surface, not its
// volume; past kMaxFramedFaces faces the frames are left out. Measured
// (RelWithDebInfo, asserts on, a busy 2-core machine) at 100 x 60 x 100: the
// default scene, 15k faces, 30 to 40 ms to classify, 4 to 8 ms a draw; the
// walkthrough at that grid, 100k faces, 70 ms and 17 to 23 ms. Buffers are
// kept: a steady state allocates nothing.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/debug_draw.h"
#include "ui/rgvc/rgvc_frame_index.h"
#include "ui/rgvc/rgvc_snapshot_stamp.h"
#include "ui/rgvc/rgvc_view.h"

namespace gridcull {

enum class RgvcBoxKind : uint8_t { None, Occluder, StaticOccluder, Occlusion, Tbv, Shell };

// The legend row a box kind belongs to.
RgvcLayer rgvcBoxLayer(RgvcBoxKind kind);

// What voxel (x, y, z) is drawn as at `layer` (the matrices as they stood then,
// ui/rgvc/rgvc_history.h), given the toggles of `view`: T first, then O (Os
// when Os is shown and the voxel is static-opaque), then H, then a voxel the
// traversal visited in that layer; None when nothing shown holds it. `index`
// must be updated for the snapshot and layer. O(1) but for T (list lengths).
RgvcBoxKind rgvcBoxKindAt(const RgvcSnapshot& s, const RgvcViewState& view,
                          const RgvcFrameIndex& index, int64_t layer, int x, int y, int z);

// The voxel holding world point p, not clamped (it may lie outside the grid).
glm::ivec3 rgvcVoxelOfPoint(const RegularGrid& grid, const glm::dvec3& p);

class RgvcVoxelBoxes {
public:
    // Emits the boxes of `view` at `layer` seen from `eye` (the view camera's
    // position, world), World space.
    void draw(const RgvcSnapshot& s, const RgvcViewState& view, const RgvcFrameIndex& index,
              int64_t layer, const glm::dvec3& eye, DebugDraw& draw);
    // Faces the last draw emitted.
    int64_t faceCount() const { return int64_t(sorted_.size()); }

    // Side of a face's frame, as a fraction of the voxel, and its colour.
    static constexpr double kFrame = 0.08;
    static constexpr Swatch kFrameSwatch = Swatch::DimGrey;
    // Beyond this many faces each is drawn without its frame (2 triangles, not
    // 4): so many faces are a few pixels each, their frames under a pixel.
    static constexpr int64_t kMaxFramedFaces = 40000;

private:
    // What the kinds and the faces were computed for.
    struct Key {
        RgvcSnapshotStamp stamp;
        int64_t layer = 0;
        uint32_t toggles = 0;
        bool operator==(const Key& o) const {
            return stamp == o.stamp && layer == o.layer && toggles == o.toggles;
        }
    };
    void classify(const RgvcSnapshot& s, const RgvcViewState& view, const RgvcFrameIndex& index,
                  int64_t layer);
    void findFaces(const RgvcSnapshot& s, const glm::ivec3& eye_voxel);

    struct Face {
        uint32_t voxel = 0;  // linear index
        uint8_t dir = 0;     // 2 * axis + (0: + side, 1: - side)
        uint8_t kind = 0;
        uint32_t key = 0;  // Manhattan distance from the eye's voxel, less the smallest
    };
    Key kinds_key_;
    bool faces_valid_ = false;
    glm::ivec3 faces_eye_{0};
    bool any_ = false;
    std::vector<uint8_t> kinds_;
    std::vector<Face> faces_;
    std::vector<Face> sorted_;
    std::vector<uint32_t> counts_;
};

}  // namespace gridcull
