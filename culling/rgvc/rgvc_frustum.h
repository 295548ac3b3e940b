// The 2D view frustum of regular-grid culling (Batagelo & Wu, section 4.2): the
// wedge of fov_deg (up to 360) around the view direction, with its apex at the
// camera, cut at `far` (docs/scene-format.md, "Camera"; 2D has no near
// plane). World units, x-y plane.
//
// "A voxel is in the frustum" here means: the closed voxel square meets the
// closed infinite wedge, and its nearest point lies within `far` of the apex.
// That is a superset of the voxels meeting the wedge cut at far (a voxel near
// the far arc's corner may meet the wedge and the disc but not both at once);
// the superset only costs a few extra visits and keeps every test simple and
// conservative. A slack of kWedgeSlack voxel widths leans every decision
// towards "in".
//
// For the chess-layer traversal, layerRun() gives the part of one chess ring
// (grid/chess_ring.h) that may hold frustum voxels, from where the wedge's two
// edges cross the ring, widened by a margin (all of ring 1, whose voxels may
// touch the apex itself); the traversal still tests each voxel, so the run only
// has to be a superset.
#pragma once
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "culling/scene/camera.h"
#include "grid/regular_grid.h"

namespace gridcull {

constexpr double kWedgeSlack = 1e-9;  // voxel widths

// A cyclic interval of perimeter indices of chess ring k: `length` voxels from
// `start` counter-clockwise. length == ringSize(k) is the whole ring. The inner
// part, `inner_length` voxels from `inner_start`, holds voxels that lie wholly
// inside the infinite wedge (both edges cross the ring further out than the
// margin), so only their distance needs testing.
struct RingRun {
    int64_t start = 0;
    int64_t length = 0;
    int64_t inner_start = 0;
    int64_t inner_length = 0;
};

class RgvcWedge {
public:
    // Takes the camera's apex, direction, fov and far, and the voxel size of the
    // grid it will be used with (touchesVoxel, layerRun); the size scales the slack.
    void set(const Camera& camera, const glm::dvec3& voxel_size);

    // fov >= 360: every direction is in.
    bool full() const { return full_; }
    double fovRadians() const { return fov_; }
    glm::dvec2 apex() const { return apex_; }
    glm::dvec2 forward() const { return forward_; }
    // Unit directions of the wedge's clockwise (right) and counter-clockwise
    // (left) edges.
    glm::dvec2 edgeCw() const { return edge_cw_; }
    glm::dvec2 edgeCcw() const { return edge_ccw_; }
    double far() const { return far_; }

    // Does the closed box [x0, x1] x [y0, y1] meet the frustum (see above)?
    bool touchesBox(double x0, double y0, double x1, double y1) const;
    // The frustum test of voxel v of `grid` (v may lie outside the grid).
    bool touchesVoxel(const RegularGrid& grid, glm::i64vec2 v) const;

    // The run of ring k around the voxel `viewer` (the voxel holding the apex)
    // that holds every voxel of that ring in the frustum. k >= 0.
    RingRun layerRun(const RegularGrid& grid, glm::i64vec2 viewer, int64_t k) const;

    // Does every point of ring k (around the voxel `viewer`) lie within far?
    bool layerWithinFar(const RegularGrid& grid, glm::i64vec2 viewer, int64_t k) const;

    // A box (world) holding the frustum: the wedge cut at far.
    void bounds(double& x0, double& y0, double& x1, double& y1) const;

private:
    bool inConvexWedge(double px, double py) const;         // fov < 180 only
    bool strictlyInComplement(double px, double py) const;  // fov >= 180 only
    bool rayMeetsBox(glm::dvec2 dir, double x0, double y0, double x1, double y1) const;
    // Perimeter index on ring k of the voxel where the ray from the apex along
    // `dir` leaves the ring's outer square.
    int64_t exitIndex(const RegularGrid& grid, glm::i64vec2 viewer, int64_t k,
                      glm::dvec2 dir) const;

    glm::dvec2 apex_{0.0};
    glm::dvec2 forward_{1.0, 0.0};
    glm::dvec2 edge_cw_{1.0, 0.0};
    glm::dvec2 edge_ccw_{1.0, 0.0};
    double fov_ = 0.0;
    double far_ = 0.0;
    double far_sq_ = 0.0;  // (far with its slack)^2
    double slack_ = 0.0;
    glm::dvec3 voxel_size_{1.0};
    bool full_ = false;
};

}  // namespace gridcull
