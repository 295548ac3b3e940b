// `hzb-tbv`, `hzb-tbvi` and `hzb`: octree-based dynamic scene occlusion culling
// after O. Sudarsky & C. Gotsman, "Dynamic scene occlusion culling" (IEEE TVCG
// 1999), section 3.3 (the four steps of a frame), section 3.6 (explicit and
// implicit update) and section 4 (the octree, updated under the least common
// ancestor), on Greene, Kass & Miller's hierarchical z-buffer (section 2.1.1).
//
// T is a DynamicOctree (dynamic_octree.h) holding static objects, dynamic
// objects in V at their configuration, and hidden dynamic objects' TBVs in their
// place (one entry per object id: the object or its TBV). D, Q and V are the
// TbvManager's (culling/tbv/tbv_manager.h). A frame:
//   1. expired, violated (and Fig. 14's randomly invalidated) TBVs leave T;
//   2. TBVe: every object of V is written in T at its current box (LCA update);
//      TBVi: nothing (T follows the objects through their TBVs only);
//   3. T is traversed front to back from the eye. A node outside the frustum or
//      hidden by the Z-pyramid is skipped with its subtree. Each entry of a node
//      is tested on its box the same way; a visible object is drawn into the
//      software z-buffer (the shared rasterizer, culling/raster) and the pyramid
//      is refreshed under it, so that what is drawn hides what comes after. A
//      TBV that passes is tested again after the traversal, against the whole
//      pyramid; one still visible is revealed: its object's current box is
//      tested and drawn at once, and T is corrected after that (T is not
//      changed while it is being walked; section 3.3's remark on step 3);
//   4. the objects of V that nothing saw get a TBV, which replaces them in T.
// `hzb` is the paper's comparison: no TBVs, every dynamic object written in T
// every frame (LCA update), then step 3.
//
// TBVi here writes an object whose TBV ends in step 1 (expired, violated, or
// invalidated at random) in T at once, where the paper leaves it out of T
// until its step-4 TBV is revealed. The paper's bound, "omitted for at most
// one frame", assumes that step-4 TBV outlives the next step 1; one made with
// a period of one frame (the adaptive floor) can expire at the next frame's
// time by rounding, and a period under a frame (--hzb-validity) or a random
// invalidation (--hzb-invalidate) ends it there for sure, losing the object
// for two frames or for good. With the write, TBVi is late only for an object
// that moved out of the nodes it was written in while in view: one frame.
//
// The PVS is every object whose box passed the frustum and the Z test. With
// TBVe it is conservative: a TBV holds its object for its whole validity
// period, so a TBV hidden under the pyramid hides its object, and a box that
// passes the pyramid's test at the oracle's resolution keeps every object with
// a pixel in the oracle's image (tests/culling/hzb_tbv/). TBVi may show an
// object coming into view one frame late (section 3.6; TbvManager's header says
// when).
//
// Departures from the paper, and why:
// - A TBV is cut to the box the object can ever reach (the world for linear
//   and random motion, which fold back at its walls; the keys' box for a
//   keyframed path; culling/scene/motion_bounds.h), as regular-grid culling
//   cuts its own: a sphere around an object on the floor reaches through the
//   floor, out of the octree (an entry outside it sits at the root, tested
//   before anything is drawn, so found visible every frame), and a chair's
//   sphere past the loop it circles. The cut keeps the TBV conservative: the
//   object is in both.
// - The octree's root is the cube on the world's longest side (the paper's
//   octree subdivides a cube): a flat world's own box would halve its height
//   at every level, and every wall taller than half the world would stay at
//   the root.
// - A TBV found visible during the traversal is revealed only if it is still
//   visible against the pyramid the whole traversal built. An entry sits in
//   the smallest node containing it, so a large TBV (a walking person's over
//   several rooms) is met at a high node, before the walls inside that node
//   are drawn, and would pass against a nearly empty pyramid. The second test
//   only sees more of what was really drawn, so it stays conservative; the
//   revealed object is then tested and drawn as before, in the same frame.
// - The octree holds each entry in the one smallest node containing its box
//   (dynamic_octree.h says why), and the traversal tests a node's box against
//   the pyramid before its entries, as Greene's hierarchical z-buffer does.
// - The z-buffer is the project's software rasterizer, not a GPU's: the oracle
//   samples the same pixel centres, so the culler's image is the oracle's image
//   of the objects drawn so far, and a test that fails is a defect, not a
//   difference between two rasterizers.
// - The pyramid is refreshed over each drawn object's rectangle (Greene's
//   propagation of a depth change up the pyramid), and queried from the level
//   where a box covers at most 2 x 2 texels down, as Greene descends, within
//   kHzbQueryReads texels a query (z_pyramid.h).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "culling/api/culler.h"
#include "culling/hzb_tbv/dynamic_octree.h"
#include "culling/hzb_tbv/hzb_tbv_options.h"
#include "culling/hzb_tbv/hzb_tbv_snapshot.h"
#include "culling/hzb_tbv/z_pyramid.h"
#include "culling/raster/id_depth_buffer.h"
#include "culling/raster/screen_mapping.h"
#include "culling/tbv/tbv_manager.h"

namespace gridcull {

class HzbTbvCuller final : public Culler {
public:
    // use_tbvs false: `hzb` (mode is then unused).
    HzbTbvCuller(std::string name, bool use_tbvs, TbvUpdateMode mode, const HzbTbvOptions& options,
                 int reference_resolution);
    const char* name() const override { return name_.c_str(); }
    void reset(const Scene& scene) override;
    void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) override;
    std::unique_ptr<Culler> clone() const override;

    // For tests and the window: the structures as the last frame left them.
    const DynamicOctree& octree() const { return octree_; }
    const ZPyramid& pyramid() const { return pyramid_; }
    const TbvManager& tbvs() const { return tbv_; }

    // The window's snapshot (hzb_tbv_snapshot.h), filled by each cull() while on.
    void setDebugCapture(bool on) override { capture_ = on; }
    const DebugSnapshot* debugSnapshot() const override {
        return capture_ && snapshot_.valid ? &snapshot_ : nullptr;
    }
    const HzbTbvSnapshot& snapshot() const { return snapshot_; }

private:
    // The object's box at the frame's time.
    Aabb currentBox(int index) const;
    // Frustum and Z-pyramid test of a box (one occlusion test).
    bool boxMayBeVisible(const Aabb& box);
    // Puts `box` in T for the entry `index` (insert, or LCA update).
    void writeInOctree(int index, const Aabb& box);
    // Writes the object at its current box in T (an object update).
    void writeObject(int index);
    // Step 3 at one entry of a node.
    void visitEntry(int index);
    // Step 3's end: the TBVs that passed their test during the traversal are
    // tested again against the whole pyramid; those still visible are revealed.
    void retestTbvs();
    // Tests the object on its current box; if it may be visible, draws it,
    // refreshes the pyramid under it and adds it to the PVS.
    void testAndDraw(int index);
    // Step 4's TBV for the object, from now for `validity` seconds: the
    // motion's (motionTbv) cut to the object's reach.
    TbvShape makeTbv(int index, double validity);
    // The TBV of the --hzb-tbv-shape choice from the object's motion bound.
    TbvShape motionTbv(int index, double validity);

    std::string name_;
    bool use_tbvs_;
    TbvUpdateMode mode_;
    HzbTbvOptions options_;
    int resolution_;

    const Scene* scene_ = nullptr;
    double t_ = 0.0;
    int64_t frame_ = 0;
    bool ready_ = false;
    std::vector<double> max_speed_;
    std::vector<double> bound_radius_;
    std::vector<Aabb> reach_;  // per object: where it can ever be (motion_bounds.h)
    std::vector<int> dynamic_;
    std::vector<int64_t> tested_stamp_;  // the frame the object was last tested in
    std::vector<double> key_times_;      // one keyframed object's key times (swept TBVs)
    std::vector<int> reveals_;           // step 3's revealed objects, to rewrite in T after it
    std::vector<int> retests_;           // TBVs that passed their test during the traversal

    DynamicOctree octree_;
    IdDepthBuffer buffer_;
    ScreenMapping mapping_;
    ZPyramid pyramid_;
    TbvManager tbv_;

    FrameResult* out_ = nullptr;
    const Camera* camera_ = nullptr;

    // Debug capture: a node the traversal reached, and the rest of the
    // snapshot at the end of the frame. Read-only over the structures.
    void captureNode(const OctreeNodeView& node, bool entered);
    void fillSnapshot(const FrameResult& out);
    bool capture_ = false;
    HzbTbvSnapshot snapshot_;
    std::vector<std::pair<int, double>> expiry_scratch_;  // Q's next events
};

}  // namespace gridcull
