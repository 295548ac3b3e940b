// The 3D view frustum of regular-grid culling (Batagelo & Wu, section 5.2):
// the camera's pyramid from its apex (the four side planes of
// Camera::frustumPlanes) cut at `far`, without the near plane.
//
// Why no near plane: a ray to a visible point crosses, between the eye and the
// near plane, voxels that the TBV test and the PVS need to see (a TBV's shell
// may lie there), and early termination needs every ray of the pyramid to cross
// each layer in a visited voxel. Voxels in front of the near plane are visited
// like any other; they only never act as occluders (rgvc_occlusion3d.h).
//
// "A voxel is in the frustum" means the plane test: for each of the five planes
// some corner of the closed voxel lies on the inner side, with a slack of
// kFrustum3Slack voxel widths. That is a superset of the voxels meeting the
// frustum (a box beside a corner of the pyramid can pass); the superset only
// costs a few visits. rowRange() gives, for a row of voxels, exactly the voxels
// that pass, in O(1).
#pragma once
#include <array>
#include <cstdint>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "culling/scene/camera.h"
#include "grid/regular_grid.h"

namespace gridcull {

constexpr double kFrustum3Slack = 1e-9;  // voxel widths

class RgvcFrustum3 {
public:
    // Takes the camera and the grid the frustum will be used with.
    void set(const Camera& camera, const RegularGrid& grid);

    const glm::dvec3& apex() const { return apex_; }
    const glm::dvec3& forward() const { return forward_; }
    double near() const { return near_; }
    double far() const { return far_; }

    // The plane test of the closed box [lo, hi].
    bool touchesBox(const glm::dvec3& lo, const glm::dvec3& hi) const;
    bool touchesVoxel(const glm::i64vec3& v) const;
    // Narrows [i0, i1] to the voxels along `axis` (0, 1, 2) that pass the plane
    // test, the other two indices being those of `at`. False when none does.
    bool rowRange(int axis, const glm::i64vec3& at, int64_t& i0, int64_t& i1) const;
    // The voxel index box (may reach outside the grid) that holds every voxel
    // passing the test; clamped to +-2^40 so that a huge far stays finite.
    void voxelBounds(glm::i64vec3& lo, glm::i64vec3& hi) const;
    // The directions of the pyramid's four edges (not normalized).
    std::array<glm::dvec3, 4> edgeDirections() const;
    // The smallest depth along the view direction over the closed voxel.
    double minDepthOfVoxel(const glm::i64vec3& v) const;

private:
    std::array<glm::dvec4, 5> planes_{};  // four sides and far, normals inwards
    glm::dvec3 apex_{0.0};
    glm::dvec3 forward_{1.0, 0.0, 0.0};
    glm::dvec3 origin_{0.0};  // grid.world.min
    glm::dvec3 voxel_{1.0};   // voxel size
    double near_ = 0.0;
    double far_ = 0.0;
    double slack_ = 0.0;
    double depth_half_ = 0.0;  // sum |forward_i| * voxel_i / 2
    glm::dvec3 far_corners_[4]{};
};

}  // namespace gridcull
