// `exact`: the reference visible set. Every conservative culler (vfc and every
// occlusion-culling family) is tested against it: its PVS must contain every id
// this oracle reports at the same frame. It shares no algorithm's code: only the
// scene, the camera, culling/scene/ray_intersect.h and the shared rasterizer
// (culling/raster/), which image-space cullers use too and which is tested on
// its own against a per-pixel ray cast. It keeps no state between frames, and
// never over-estimates by design.
//
// 3D: an object-ID buffer (culling/raster/id_depth_buffer.h) of
// OracleOptions::resolution (--oracle-res) pixels on the long side, the other side from
// the camera's aspect (1024 x 576 at 16:9 by default), sampled at pixel centres,
// depth = view-space distance along the forward axis, only [near, far] counts.
// Spheres and boxes are intersected exactly per pixel, meshes rasterized exactly
// per pixel centre (near-plane clipped, perspective-correct depth, two-sided).
// 2D, by default (OracleOptions::rays_per_turn == 0, --oracle-rays 0): the exact
// angular envelope (culling/oracle/exact_oracle_2d.h) of circles, boxes and
// polygons over the wedge, cut at far: no sampling. With rays_per_turn N > 0, the
// sampled angular sweep (culling/oracle/exact_oracle_sweep.h) of
// max(64, ceil(fov / 360 * N)) rays over the wedge, at the centres of equal angular
// bins, exact against each shape; kept as a cross-check of the envelope.
//
// Exactness: in 2D by default, exact up to floating point: every object some ray
// of the wedge sees first over an angular span wider than
// AngularEnvelope::kMinPieceWidth (about 5.7e-14 radians) is reported, and nothing
// else; an object met at a single angle only (a tangent, silhouettes touching as
// seen from the camera) is not; objects at the same distance over a whole
// interval (coincident boundaries) are all seen, up to two per interval.
// Elsewhere the result is exact up to the sampling. An object is reported iff
// some pixel centre (ray) sees it first; nothing hidden is ever reported, and a
// visible part is missed only if it falls between samples. Resolved size: in 3D
// a visible region containing a disc of radius >= 0.71 pixel (half the pixel
// diagonal) always contains a pixel centre; one pixel spans 2 tan(fov_y/2) /
// height in the image plane, about 0.115 degrees at fov 60 and 576 rows. In the
// sampled 2D sweep a visible angular span of at least one bin, fov / rays (0.022
// degrees at 16384 rays per turn), always contains a ray. Smaller or thinner
// visible slivers (e.g. an object seen through a gap narrower than a pixel) may
// be missed.
//
// Sub-sample objects (3D, OracleOptions::refine, --oracle-refine 1; off by
// default, see Cost below): the question the pixel centres leave open is
// asked, not hidden.
// After the buffer is drawn, an object no centre saw is a candidate when its
// bounds reach a pixel whose square is not proven covered nearer than the
// object's least depth inside that pixel (subsample_refiner.h says how a square
// is proven covered: by one convex object, or by two, pair_cover.h;
// pixel_pyramid.h and mesh_footprint.h how far an object reaches into a pixel).
// Its open pixels are cast again with Embree rays at 4 x 4 and then
// 12 x 12 points a pixel (subsample_refiner.h), until one sees it. Both kinds
// are "sub-sample" and kept out of the PVS, which stays what the pixel centres
// see (an image at the oracle's resolution has no pixel of them, so a culler
// that samples the same centres may drop them): an object a ray saw first is
// sub-sample visible (FrameResult::sub_sample_visible), a candidate no ray saw
// is sub-sample undecided, neither visible nor hidden (sub_sample_undecided).
// The window and `cull` show both, and counters count them. The refined answer
// is the PVS and the sub-sample visible ones together. At 4 x 4 the rays are
// exactly the pixel centres of a buffer four times as fine, so the refined
// answer sees everything a 4096-pixel buffer sees (tested on 200 random
// scenes); 12 x 12 (the documented limit, 144 rays a pixel, at most 2^22 rays
// a frame) resolves gaps down to 1/12 pixel. Cost: nothing where
// every unseen object lies behind wide occluders; elsewhere 160 rays for each
// open pixel of each candidate that no ray decides. On the shipped scenes
// (scripts/refine-cost.sh: 1024 pixels, the first 48 frames, medians;
// docs/results/oracle-refine.md) a frame takes 8 to 40 ms in the cities,
// rooms-3d, building-people-3d, hidden-movers-3d, mesh-3d and the sphere
// scenes, 77 to 170 ms in plant-3d, the forests and walkthrough-3d, and 1.2 s
// in bunnies-3d (300 bunnies passing through each other), 1.2x to 14x the
// oracle alone: most candidates left sit behind seams that neither one convex
// object nor a box and another cover (two spheres, two meshes, three objects),
// or behind a face at exactly their depth, and
// end undecided after all their rays. Hence off by default. Embree alone, one
// ray a pixel with the objects placed each frame, is no faster than the
// rasterizer: 67 to 181 ms a frame on the shipped 3D scenes, 1.2x (bunnies-3d)
// to 32x the rasterized oracle (scripts/refine-cost.sh, first 48 frames),
// so the oracle rasterizes and casts rays only to refine.
//
// Shapes outside their dimension (polygons in 3D, meshes in 2D; the loader
// rejects both) are ignored. A camera inside a sphere, box or polygon sees only
// it; inside a closed mesh, wherever the near-plane point is inside it.
//
// Counters: objects_tested = objects drawn into the buffer (not rejected whole as
// beyond [near, far], behind the camera or off screen); pixels_sampled = pixels
// (3D) or rays (2D) per frame (the envelope: one per elementary interval tested).
// Cost per frame: O(pixels + objects log objects + the objects' screen footprints
// + mesh triangles) in 3D, where front-to-back order lets hidden parts be skipped
// per pixel and per 16 x 16 tile; O(rays + the objects' angular footprints *
// edges) in the sampled 2D sweep; the exact envelope costs O(objects log objects +
// the pieces each object visits * the edges of the pieces' owners and the object),
// with no ray count. Measured (RelWithDebInfo, one core): the 2000-sphere default
// scene at 1024 x 576 takes about 6 ms per frame (median over its 150 frames).
// In 2D (medians per frame over every frame, on a machine shared with builds):
// figure1-2d 0.17 ms exact against 0.20 ms sampled at 16384 rays per turn,
// walls-2d 0.009 against 0.095 ms, rooms-2d 0.18 against 0.35 ms,
// hidden-movers-2d (2006 objects) 0.69 against 0.57 ms.
// Buffers are sized in reset() and when the resolution or fov changes, never
// per frame.
#pragma once
#include <utility>
#include <vector>

#include "culling/api/culler.h"
#include "culling/oracle/exact_oracle_2d.h"
#include "culling/oracle/exact_oracle_sweep.h"
#include "culling/oracle/oracle_options.h"
#include "culling/oracle/subsample_refiner.h"
#include "culling/raster/id_depth_buffer.h"

namespace gridcull {

class ExactOracle final : public Culler {
public:
    // Options are clamped to [1, kMaxOracleResolution] and [0, kMaxOracleRaysPerTurn].
    explicit ExactOracle(const OracleOptions& options = {});
    const char* name() const override { return "exact"; }
    void reset(const Scene& scene) override;
    void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) override;
    std::unique_ptr<Culler> clone() const override { return std::make_unique<ExactOracle>(*this); }

    // The buffer size used for a camera: long side = `resolution`.
    static void imageSize(int resolution, double aspect, int& width, int& height);
    // The ray count used for a 2D wedge of fov_deg.
    static int rayCount(int rays_per_turn, double fov_deg);

private:
    void cull3d(const Scene& scene, const Camera& camera, double t, FrameResult& out);
    void cull2d(const Scene& scene, const Camera& camera, double t, FrameResult& out);
    // Draws every object front to back on `canvas` (the envelope or the sweep).
    template <class Canvas>
    int64_t draw2d(Canvas& canvas, const Scene& scene, double t);
    // Fills out.pvs from the indices marked in seen_, sorted by id.
    void collect(const Scene& scene, FrameResult& out);

    OracleOptions options_;
    IdDepthBuffer id_buffer_;
    AngularEnvelope envelope_;  // 2D, rays_per_turn == 0
    OracleAngularSweep sweep_;  // 2D, rays_per_turn > 0
    std::vector<std::pair<double, int>> order_;  // (nearest possible depth, object index)
    std::vector<char> seen_;                     // per object index
    std::vector<char> drawn_;                    // per object index: drawn into the buffer
    std::vector<int> undecided_;                 // object indices left sub-sample
    SubsampleRefiner refiner_;
    std::vector<glm::dvec3> shifts_;             // per object index: displacement at t
};

}  // namespace gridcull
