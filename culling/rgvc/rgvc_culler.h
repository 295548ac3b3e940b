// `rgvc`: regular-grid visibility culling for dynamic scenes, after
// G. C. Batagelo and S.-T. Wu, "Dynamic Scene Occlusion Culling using a Regular
// Grid" (SIBGRAPI 2002): sections 3 and 4 (2D) and 5 (3D), with TBVs after
// Sudarsky and Gotsman. One culler for both dimensions: the frame loop, the PVS,
// the TBV bookkeeping and the matrices are shared; traversal, discretization,
// occlusion and the TBVs' shape in T have a 2D and a 3D form.
//
// Each frame (section 3's four steps):
//  1. Scene discretization (s4.1, s4.5, s5.1; rgvc_discretize*.cpp): O <- Os;
//     every dynamic object in the last frame's PVS (all of them in the first
//     frame) is written into O (voxels wholly inside it; in 3D inside its inner
//     model) and I (voxels it touches); TBVs whose validity ran out are renewed.
//     Static objects went into Os and I once, in reset(). Hidden objects cost
//     nothing in frames where their TBV neither expires nor is revealed. The
//     TBVs' bookkeeping (state, validity, expiry, the expiration queue, V) is
//     the shared TBV manager's (culling/tbv/tbv_manager.h); rgvc_tbv_life.cpp
//     writes TBVs into T and takes them out.
//  2. View-frustum traversal (s4.2, s5.2; rgvc_traversal*.cpp): chess layers
//     around the viewer's voxel in increasing distance from the seed voxels of
//     the Bresenham line of sight (2D: rings walked in the paper's two
//     directions; 3D: cube shells swept face by face); non-occluded voxels add
//     their I objects to the PVS and reveal their TBVs (those objects are
//     discretized at once); early termination after a layer whose frustum
//     voxels all block.
//  3. Occluder extension and 4. occlusion computation: 2D (s4.3, s4.4;
//     rgvc_occlusion.h) from each non-occluded opaque voxel, an extended
//     occluder (the convex L or, with --rgvc-extension 1, the staircase) and its
//     occlusion polygons rasterized into H; 3D (s5.3;
//     rgvc_occlusion3d.h) each layer's blocking voxels extruded from the eye
//     into a direction map, against which later voxels are marked in H.
//
// Departures, each for conservativeness, robustness or cost, and why:
//  - 2D discretization tests voxels exactly (grid/conservative_raster.h) instead
//    of growing / shrinking outlines by d / sqrt(2); 3D uses the section 5.1
//    models exactly (spheres and boxes are their own inner and outer models; a
//    mesh's inner model is its interior boxes, culling/scene/mesh_interior.h,
//    none for an open mesh; its outer model its bounding box).
//  - The 2D occlusion polygon is exact for the real viewpoint and shrunk by
//    (|nx| + |ny|) d / 2 (rgvc_occlusion.h), not built from voxel centres.
//  - The frustum may be 360 degrees wide (2D), and the viewer may be outside the
//    grid: the traversal then starts at the first layer that reaches the grid
//    and walks only the grid's part of each layer; early termination is only
//    taken when no ray of the frustum can still enter the grid further out.
//  - 2D: each layer's walk ends where the wedge's edges cross the ring (plus a
//    margin), not at the first voxel outside the frustum: `far` can cut a
//    layer's frustum part into pieces that such a walk would not reach. When the
//    Bresenham seed itself misses a narrow wedge near the viewer, the walk
//    starts at the nearer end of that part.
//  - 3D: the frustum has no near plane (rgvc_frustum3d.h says why), and opaque
//    voxels in front of the near plane do not occlude.
//  - 2D occluder extension: the paper's convex L or its staircase (non-convex)
//    variant, RgvcOptions::extension; a staircase's non-convex hidden region is
//    covered by its two Ls' convex polygons (rgvc_occlusion.h).
//  - Objects not wholly inside the grid are also kept whenever they touch the
//    frustum (their parts outside the grid are invisible to the matrices).
//  - An object found in a visible voxel joins the PVS only if its own bounds
//    pass vfc's frustum test: a voxel in the frustum may hold objects that are
//    not (so the PVS is never larger than vfc's).
//  - A TBV is cut to the box the object can ever reach (the world box for
//    linear and random motion, which fold back at its walls; the keyframes'
//    box), and written into T as the boundary of that cut region. Only an object
//    that can leave the grid has a TBV kept out of T, revealed when it touches
//    the frustum (a ray could otherwise reach it around the outside of the grid).
//  - TBV validity: RgvcOptions::validity_s (--rgvc-validity), adaptive by
//    default (Sudarsky & Gotsman, s3.4; culling/tbv/tbv_validity.h) so that a
//    period too long for the scene corrects itself instead of having its TBV
//    revealed every frame, spread (spreadValidity, never below one frame unless
//    --rgvc-validity is shorter) so
//    that TBVs made together do not expire together, and shortened (as the
//    paper suggests) so that the TBV
//    leaves the viewer's voxel outside; when even one frame's validity would
//    not, the TBV is written filled. When the viewer's voxel jumps by more than
//    one voxel between frames (a teleport), every boundary TBV that may enclose
//    the new viewer voxel is revealed before the traversal.
//  - The paper gives an object that left the PVS its TBV in the next frame's
//    step 1 (criterion 1); here it gets it at the end of the frame it left
//    (Sudarsky & Gotsman's step 4, the TBV manager's endFrame), at the same
//    time t and against that frame's viewer voxel; it is written into T at
//    the next frame's start, as in the paper, so that T after a frame is T as
//    its traversal saw it, and its validity counts from that frame (it is one
//    frame longer from t, and the TBV grows by that frame's motion). The next
//    frame's viewer moves from that voxel, so the boundary argument (an
//    8-connected walk crosses a 4-connected curve on one of its voxels) and
//    the teleport rule hold as before.
//  - A revealed object whose voxels the traversal had already passed
//    non-occluded joins the PVS at once (the traversal will not come back).
//  - Time going backwards, or a scene with a different object count, resets.
//  - A viewpoint so far away that RegularGrid::voxelOf clamps its voxel (about
//    1e9 voxels) falls back to view-frustum culling for that frame.
//
// Counters: voxels_visited (frustum voxels reached by the traversal, occluded or
// not), tbv_created, tbv_expired, tbv_revealed, object_updates (dynamic objects
// written into O and I this frame).
// Cost per frame: O(objects in the last PVS + TBVs expiring or revealed) for the
// bookkeeping, O(voxels visited) for the traversal, plus the discretization of
// those objects and the occlusion work (2D: up to two polygons per L of an
// occluder, one L or a staircase of two; 3D: the direction-map cells under the
// layer's new occluders, tested once per layer).
// Buffers are sized in reset(); a steady state allocates nothing.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "culling/api/culler.h"
#include "culling/rgvc/rgvc_frustum.h"
#include "culling/rgvc/rgvc_frustum3d.h"
#include "culling/rgvc/rgvc_occlusion3d.h"
#include "culling/rgvc/rgvc_options.h"
#include "culling/rgvc/rgvc_snapshot.h"
#include "culling/rgvc/rgvc_tbv.h"
#include "culling/tbv/tbv_manager.h"
#include "grid/bit_matrix.h"
#include "grid/bresenham.h"
#include "grid/bresenham3d.h"
#include "grid/id_list_matrix.h"
#include "grid/regular_grid.h"

namespace gridcull {

class RgvcCuller final : public Culler {
public:
    explicit RgvcCuller(const RgvcOptions& options = {});
    const char* name() const override { return "rgvc"; }
    void reset(const Scene& scene) override;
    void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) override;
    std::unique_ptr<Culler> clone() const override;

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
    // How the TBV lies in T (its validity, expiry and state are the TBV
    // manager's).
    struct Tbv {
        bool edge = false;    // not in T: revealed when it touches the frustum
        bool filled = false;  // written filled rather than as its boundary
        glm::dvec3 centre{0.0};
        double radius = 0.0;  // 2D: the disc's; 3D: the cube's half side
        Aabb box;             // 3D: the cube cut to the object's reach (world)
        RgvcTbvCurve curve;   // 2D
        RgvcVoxelBox cells;   // the voxels the TBV may cover (3D) / its clip box (2D)
        int edge_slot = -1;   // index in edge_tbvs_
    };

    // rgvc_discretize.cpp (s4.1, s4.5) and rgvc_discretize3d.cpp (s5.1)
    void discretizeStatic(const Scene& scene);
    void discretizeObject(const Scene& scene, int index, bool during_traversal);
    void rasterize2d(const SceneObject& object, const glm::dvec3& shift, int index, bool is_static,
                     bool during_traversal);
    void rasterize3d(const SceneObject& object, const glm::dvec3& shift, int index, bool is_static,
                     bool during_traversal);
    bool objectTouchesFrustum(const Scene& scene, int index) const;
    // rgvc_tbv_life.cpp: the TBVs' life cycle (s4.1, s5.2)
    // The object's TBV for `validity` seconds from now (may shorten it, or make
    // it +infinity for an object that cannot move), written into T now, or
    // (write false) at the next frame's start, its validity then counted from
    // that frame.
    TbvShape makeTbv(const Scene& scene, int index, double& validity, bool write);
    bool hasTbv(int index) const { return tbvs_.hasTbv(index); }
    void revealTbv(const Scene& scene, int index, bool during_traversal);
    void writeTbv(int index, bool add);
    bool tbvMayEncloseViewer(const Tbv& b) const;
    void shapeTbv(Tbv& b, double radius);
    void handleDynamicObjects(const Scene& scene, bool teleported);
    // rgvc_traversal.cpp (s4.2 - s4.4)
    void traverse(const Scene& scene);
    void visitLayer(const Scene& scene, int64_t k);
    void visitArc(const Scene& scene, int64_t k, const RingRun& run, bool within_far, int64_t from,
                  int64_t count, int dir);
    void visitVoxel(const Scene& scene, int x, int y, int64_t k);
    void occludeFrom(int x, int y, int64_t k);
    // rgvc_traversal3d.cpp (s5.2, s5.3)
    void traverse3d(const Scene& scene);
    void visitShell(const Scene& scene, int64_t k);
    void visitVoxel3d(const Scene& scene, int x, int y, int z, int64_t k);
    void revealTbvsAt3d(const Scene& scene, int x, int y, int z);
    bool visitEmptyRun3d(int x0, int x1, int y, int z);
    void occludeFromLayer3d(int64_t k);
    bool blocksInLayer3d(int x, int y, int z) const;
    // rgvc_culler.cpp
    void addToPvs(int index);
    void fillSnapshotFrame(const Camera& camera);
    RgvcTbvView tbvView(const Scene& scene, int index) const;
    // Snapshot only: records voxels entering H or O during the traversal.
    void noteOccluded(int x, int row, int32_t cause);
    void noteOpaque(int x, int row);
    void setUpFrame2d(const Camera& camera, bool& unreachable, bool& teleported);
    void setUpFrame3d(const Camera& camera, bool& unreachable, bool& teleported);

    RgvcOptions options_;
    bool ready_ = false;
    int dimensions_ = 2;
    size_t object_count_ = 0;
    RegularGrid grid_;
    glm::dvec3 voxel_size_{1.0};

    BitMatrix occluder_;                // O
    BitMatrix static_occluder_;         // Os
    BitMatrix occlusion_;               // H
    BitMatrix open_;                    // voxels the traversal passed non-occluded this frame
    IdListMatrix identifiers_static_;   // I, static objects
    IdListMatrix identifiers_dynamic_;  // I, dynamic objects, rebuilt every frame
    // 3D: one bit per voxel whose static / dynamic I list is not empty, so that
    // the traversal reads a dense bitmap, not a list head, for an empty voxel.
    BitMatrix holds_static_;
    BitMatrix holds_dynamic_;
    IdListMatrix tbv_matrix_;  // T (2D), Txy (3D)
    IdListMatrix tbv_xz_;      // Txz (3D)
    IdListMatrix tbv_yz_;      // Tyz (3D)
    bool has_static_ = false;
    bool has_dynamic_ = false;

    std::vector<int> dynamic_;          // object indices
    std::vector<int> static_outside_;   // static objects not wholly inside the grid
    std::vector<double> max_speed_;     // per object index
    std::vector<double> bound_radius_;  // per object index, around its anchor (2D)
    std::vector<Aabb> reach_;           // per object index: where it can ever be
    std::vector<uint8_t> reach_in_grid_;
    std::vector<const std::vector<Aabb>*> inner_boxes_;  // per object index (3D meshes)
    std::vector<std::pair<const TriangleMesh*, std::vector<Aabb>>> mesh_interiors_;
    std::vector<int64_t> pvs_stamp_;       // == frame_ once in this frame's PVS
    std::vector<int64_t> rejected_stamp_;  // == frame_ once found outside the frustum
    std::vector<Tbv> tbv_;
    std::vector<std::vector<uint64_t>> tbv_nodes_;  // per object: (plane << 32 | node) in T
    // D, Q and V of Sudarsky & Gotsman: each dynamic object's TBV state,
    // validity period and expiry, the expiration queue, and the objects written
    // into O and I (V: those in the last PVS, and those revealed this frame).
    TbvManager tbvs_;
    std::vector<int> renewals_;   // this frame's expired TBVs, renewed after step 1
    std::vector<int> unwritten_;  // TBVs made at the last frame's end, not yet in T
    std::vector<int> edge_tbvs_;  // object indices with edge TBVs
    std::vector<int> reveal_scratch_;
    std::vector<uint32_t> tbv_seen_;  // 3D 2-of-3 test: per object, the last test that saw it
    uint32_t tbv_test_ = 0;

    // Per frame.
    int64_t frame_ = 0;
    double t_ = 0.0;
    double last_t_ = 0.0;
    RgvcWedge wedge_;
    glm::i64vec2 viewer_{0};
    glm::i64vec2 last_viewer_{0};
    BresenhamLine line_of_sight_{glm::i64vec2(1, 0)};
    int clip_x0_ = 0, clip_x1_ = -1, clip_y0_ = 0, clip_y1_ = -1;  // frustum box in voxels
    // 3D.
    RgvcFrustum3 frustum3_;
    RgvcDirectionMap direction_map_;
    glm::i64vec3 viewer3_{0};
    glm::i64vec3 last_viewer3_{0};
    BresenhamLine3 line_of_sight3_{glm::i64vec3(1, 0, 0)};
    glm::i64vec3 clip_lo3_{0}, clip_hi3_{-1};  // frustum voxel box cut to the grid
    bool eye_in_grid_ = false;
    std::vector<glm::ivec3> layer_occluders_;  // the current layer's new occluders
    bool direction_covered_ = false;           // the direction map holds a covered cell this frame
    uint32_t direction_pass_ = 0;  // numbers the layers' passes over the map, across frames
    const Camera* camera_ = nullptr;
    const Scene* scene_ = nullptr;
    // Counters of the frame.
    int64_t voxels_visited_ = 0;
    int64_t object_updates_ = 0;
    // Per layer, while traversing.
    int64_t current_layer_ = -1;  // -1 before the traversal
    int64_t layer_visited_ = 0;
    bool layer_all_occluded_ = true;
    bool layer_leaves_grid_ = false;
    FrameResult* out_ = nullptr;

    bool snapshot_enabled_ = false;
    RgvcSnapshot snapshot_;
};

}  // namespace gridcull
