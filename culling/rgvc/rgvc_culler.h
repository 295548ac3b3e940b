// `rgvc`: regular-grid visibility culling for dynamic 2D scenes, after
// G. C. Batagelo and S.-T. Wu, "Dynamic Scene Occlusion Culling using a Regular
// Grid" (SIBGRAPI 2002), sections 3 and 4 (the 2D case) with TBVs after
// Sudarsky and Gotsman.
//
// Each frame (section 3's four steps):
//  1. Scene discretization (s4.1, s4.5; rgvc_discretize.cpp): O <- Os; every
//     dynamic object in the last frame's PVS (all of them in the first frame) is
//     written into O (voxels wholly inside it) and I (voxels it touches); every
//     other dynamic object keeps or gets a TBV in T; an expired TBV is renewed.
//     Static objects went into Os and I once, in reset().
//  2. View-frustum traversal (s4.2; rgvc_traversal.cpp): chess layers around the
//     viewer's voxel in increasing distance, each walked from its seed voxel on
//     the Bresenham line of sight in the two directions of the paper's six
//     rules; non-occluded voxels add their I objects to the PVS and reveal
//     their TBVs (those objects are discretized at once); early termination
//     after a layer whose frustum voxels are all occluded.
//  3. Occluder extension and 4. occlusion computation (s4.3, s4.4;
//     rgvc_occlusion.h): from each non-occluded opaque voxel, an L-shaped
//     extended occluder and its occlusion polygon, rasterized into H.
//
// Departures, each for conservativeness or robustness, and why:
//  - Discretization tests voxels exactly (grid/conservative_raster.h) instead of
//    growing / shrinking outlines by d / sqrt(2).
//  - The occlusion polygon is exact for the real viewpoint and shrunk by
//    (|nx| + |ny|) d / 2 (rgvc_occlusion.h), not built from voxel centres.
//  - The frustum may be 360 degrees wide and the viewer may be outside the grid:
//    the traversal then starts at the first layer that reaches the grid and walks
//    only the grid's part of each layer (rgvc_frustum.h); early termination is
//    only taken when the layer's frustum part lies wholly inside the grid.
//  - Each layer's walk ends where the wedge's edges cross the ring (plus a
//    margin), not at the first voxel outside the frustum: `far` can cut a layer's
//    frustum part into pieces that such a walk would not reach. When the
//    Bresenham seed itself misses a narrow wedge near the viewer, the walk starts
//    at the nearer end of that part.
//  - Occluder extension is the paper's convex (L-shaped) variant only.
//  - Objects not wholly inside the grid are also kept whenever they touch the
//    frustum (their parts outside the grid are invisible to the matrices).
//  - A TBV whose digital circle would leave the grid is not written into T but
//    kept in a list and revealed when its disc touches the frustum (a ray could
//    otherwise reach the object around the outside of the grid).
//  - TBV validity: RgvcOptions::validity_s (--rgvc-validity), shortened (as the
//    paper suggests) so that the circle leaves the viewer's voxel outside; when even one frame's validity
//    would not, the TBV is written filled. When the viewer's voxel jumps by more
//    than one voxel between frames (a teleport: the 8-connected path condition
//    fails), every boundary TBV whose curve may enclose the new viewer voxel is
//    revealed before the traversal.
//  - A revealed object whose voxels the traversal had already passed
//    non-occluded joins the PVS at once (the traversal will not come back). With
//    the viewer outside every boundary TBV this cannot happen (the curve is met
//    in an earlier layer than the object); it is a second line of defence.
//  - Time going backwards, or a scene with a different object count, resets.
//  - A viewpoint so far away that RegularGrid::voxelOf clamps its voxel (about
//    1e9 voxels) falls back to view-frustum culling for that frame.
//
// Counters: voxels_visited (frustum voxels reached by the traversal, occluded or
// not), tbv_created, tbv_expired, tbv_revealed, object_updates (dynamic objects
// written into O and I this frame).
// 3D scenes are not supported (the registry offers rgvc for 2D only); cull()
// then falls back to view-frustum culling of the objects' bounds (as `vfc`),
// which is conservative.
// Cost per frame: O(dynamic objects) bookkeeping + O(voxels visited) + the
// discretization of the PVS objects + one occlusion rasterization per occluder.
// Buffers are sized in reset(); a steady state allocates nothing.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "culling/api/culler.h"
#include "culling/rgvc/rgvc_frustum.h"
#include "culling/rgvc/rgvc_options.h"
#include "culling/rgvc/rgvc_snapshot.h"
#include "culling/rgvc/rgvc_tbv.h"
#include "grid/bit_matrix.h"
#include "grid/bresenham.h"
#include "grid/id_list_matrix.h"
#include "grid/regular_grid.h"

namespace gridcull {

class RgvcCuller final : public Culler {
public:
    explicit RgvcCuller(const RgvcOptions& options = {});
    const char* name() const override { return "rgvc"; }
    void reset(const Scene& scene) override;
    void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) override;

    // Fill snapshot() each frame from now on (off by default: it costs a vector
    // entry per visited voxel).
    void setDebugCapture(bool on) override { snapshot_enabled_ = on; }
    const DebugSnapshot* debugSnapshot() const override {
        return snapshot_.valid ? &snapshot_ : nullptr;
    }
    const RgvcSnapshot& snapshot() const { return snapshot_; }
    // The grid this culler uses (the scene's, or the resolution override).
    const RegularGrid& grid() const { return grid_; }
    RgvcMatrixMemory memory() const;

private:
    struct Tbv {
        bool active = false;
        bool edge = false;    // not in T: revealed by its disc touching the frustum
        bool filled = false;  // written filled rather than as its boundary
        glm::dvec3 centre{0.0};
        double radius = 0.0;
        double created = 0.0;
        double expiry = 0.0;
        RgvcTbvCurve curve;
        int edge_slot = -1;  // index in edge_tbvs_
    };

    // rgvc_discretize.cpp (s4.1, s4.5)
    void discretizeStatic(const Scene& scene);
    void discretizeObject(const Scene& scene, int index, bool during_traversal);
    void createTbv(const Scene& scene, int index);
    void removeTbv(int index);
    void revealTbv(const Scene& scene, int index, bool during_traversal);
    void handleDynamicObjects(const Scene& scene, bool teleported);
    bool objectTouchesFrustum(const Scene& scene, int index) const;
    // rgvc_traversal.cpp (s4.2 - s4.4)
    void traverse(const Scene& scene);
    void visitLayer(const Scene& scene, int64_t k);
    void visitArc(const Scene& scene, int64_t k, const RingRun& run, bool within_far, int64_t from,
                  int64_t count, int dir);
    void visitVoxel(const Scene& scene, int x, int y, int64_t k);
    void occludeFrom(int x, int y, int64_t k);
    // rgvc_culler.cpp
    void addToPvs(int index);
    void fillSnapshotFrame(const Camera& camera);

    RgvcOptions options_;
    bool ready_ = false;
    size_t object_count_ = 0;
    RegularGrid grid_;
    glm::dvec3 voxel_size_{1.0};

    BitMatrix occluder_;                // O
    BitMatrix static_occluder_;         // Os
    BitMatrix occlusion_;               // H
    BitMatrix open_;                    // voxels the traversal passed non-occluded this frame
    IdListMatrix identifiers_static_;   // I, static objects
    IdListMatrix identifiers_dynamic_;  // I, dynamic objects, rebuilt every frame
    IdListMatrix tbv_matrix_;           // T
    bool has_static_ = false;
    bool has_dynamic_ = false;

    std::vector<int> dynamic_;          // object indices
    std::vector<int> static_outside_;   // static objects not wholly inside the grid
    std::vector<double> max_speed_;     // per object index
    std::vector<double> bound_radius_;  // per object index, around its anchor
    std::vector<uint8_t> in_last_pvs_;
    std::vector<int64_t> pvs_stamp_;  // == frame_ once in this frame's PVS
    std::vector<Tbv> tbv_;
    std::vector<int> edge_tbvs_;  // object indices with edge TBVs
    std::vector<int> reveal_scratch_;

    // Per frame.
    int64_t frame_ = 0;
    double t_ = 0.0;
    double last_t_ = 0.0;
    RgvcWedge wedge_;
    glm::i64vec2 viewer_{0};
    glm::i64vec2 last_viewer_{0};
    BresenhamLine line_of_sight_{glm::i64vec2(1, 0)};
    int clip_x0_ = 0, clip_x1_ = -1, clip_y0_ = 0, clip_y1_ = -1;  // frustum box in voxels
    const Camera* camera_ = nullptr;
    // Counters of the frame.
    int64_t voxels_visited_ = 0;
    int64_t tbv_created_ = 0;
    int64_t tbv_expired_ = 0;
    int64_t tbv_revealed_ = 0;
    int64_t object_updates_ = 0;
    // Per layer, while traversing.
    int64_t layer_visited_ = 0;
    bool layer_all_occluded_ = true;
    bool layer_leaves_grid_ = false;
    FrameResult* out_ = nullptr;

    bool snapshot_enabled_ = false;
    RgvcSnapshot snapshot_;
};

}  // namespace gridcull
