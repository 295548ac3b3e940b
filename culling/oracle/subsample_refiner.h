// The 3D oracle's answer below its sampling (exact_oracle.h, "Sub-sample
// objects"): which objects no pixel centre saw but which may still show between
// the centres, and supersampling to decide them.
//
// After the ID buffer is drawn, an object that no centre saw is a candidate when
// its screen bounds hold an open pixel for it: a pixel that its sphere or box
// reaches (pixel_pyramid.h), or a mesh's triangles (mesh_footprint.h), and whose
// square is not proven covered (subsample_gate.h, coverDepth below) nearer than
// the object's least depth inside that pixel. Its open pixels are then cast again at
// kFirstLevel x kFirstLevel sub-samples, then at kLastLevel x kLastLevel, each
// ray with Embree (embree_rays.h), until a ray's nearest object is the candidate.
// Every unseen object a ray finds first is visible, candidate or not. Sampling
// follows the buffer's: sub-sample (a, b) of pixel (px, py) at level L is the
// continuous pixel point (px + (a + 0.5) / L, py + (b + 0.5) / L), so level 4
// casts exactly the pixel centres of a buffer four times as fine, and level 12
// contains level 4's points (a = 3 j + 1) and skips them.
// A candidate no ray found is undecided: reported as "sub-sample", neither
// visible nor hidden. The rays of a frame stop at kMaxRaysPerFrame; candidates
// left then are undecided too.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "culling/oracle/embree_rays.h"
#include "culling/oracle/mesh_footprint.h"
#include "culling/oracle/pixel_pyramid.h"
#include "culling/oracle/subsample_gate.h"
#include "culling/raster/id_depth_buffer.h"
#include "culling/scene/camera.h"

namespace gridcull {

struct SubsampleCounts {
    int64_t candidates = 0;  // objects no centre saw that may show between centres
    int64_t found = 0;       // objects the refinement rays saw and no centre did
    int64_t undecided = 0;   // candidates no ray saw: the "sub-sample" objects
    int64_t rays = 0;        // refinement rays cast
};

class SubsampleRefiner {
public:
    static constexpr int kFirstLevel = 4;
    static constexpr int kLastLevel = 12;
    static constexpr int64_t kMaxRaysPerFrame = int64_t(1) << 22;
    static constexpr char kSeenByRay = 2;

    void reset() {
        rays_.reset();
        level_.clear();
        touched_.clear();
    }

    // `order` is the oracle's draw order (nearest possible depth, index) and
    // drawn[i] whether the buffer drew object i; seen[i] is nonzero for the
    // objects a centre saw and set to kSeenByRay for every other one a ray
    // finds; `undecided` receives the indices of the undecided ones.
    void refine(const Scene& scene, const Camera& camera, const std::vector<glm::dvec3>& shifts,
                const IdDepthBuffer& buffer, const std::vector<std::pair<double, int>>& order,
                const std::vector<char>& drawn, std::vector<char>& seen,
                std::vector<int>& undecided, SubsampleCounts& counts);

private:
    using View = PixelView;
    // +infinity when object i's sphere or bounds cannot reach into pixel
    // (px, py); else a lower bound of its depth there, so that a cover nearer
    // than the bound hides it in that pixel.
    double nearestInPixel(const View& view, const glm::dvec3 corners[8], bool sphere,
                          const glm::dvec3& center, double radius, int px, int py) const;
    // The farthest depth, over the four corners of the pixel, of a sphere or
    // box that all four corners' rays meet (nearest or not), the least such over
    // the objects the centres of the pixel and its eight neighbours see; else the
    // least depth below which two of them cover it (pairCoverDepth); +infinity
    // when neither holds. Convexity makes such an object cover the whole pixel
    // no farther than that (subsample_gate.h), so an object behind it cannot
    // show there: this closes the edges where one object passes behind another.
    // Cached per frame.
    double coverDepth(const View& view, const Scene& scene, const std::vector<glm::dvec3>& shifts,
                      const IdDepthBuffer& buffer, int px, int py);
    // The least depth below which two of the `distinct` objects the nine
    // centres see, a box and a sphere or box, cover the pixel together
    // (pair_cover.h); +infinity when no pair does.
    double pairCoverDepth(const View& view, const Scene& scene, const std::vector<glm::dvec3>& shifts,
                          const int* ids, int distinct, int px, int py) const;
    // The index of the object the ray through (x, y) sees first, or -1.
    int nearestAt(const View& view, const Scene& scene, const std::vector<glm::dvec3>& shifts,
                  double x, double y) const;

    SubsampleGate gate_;
    MeshFootprint footprint_;
    EmbreeRays rays_;
    std::vector<uint8_t> level_;    // per pixel: the finest level cast this frame (0: none)
    std::vector<double> cover_;     // per pixel: coverDepth, valid where cover_frame_ is frame_
    std::vector<uint32_t> cover_frame_;
    uint32_t frame_ = 0;
    std::vector<size_t> touched_;   // the pixels whose level_ is set
    std::vector<size_t> pixels_;    // one candidate's open pixels
    std::vector<int> near_solids_;  // spheres and boxes that may hold the eye or a near-plane point
};

}  // namespace gridcull
