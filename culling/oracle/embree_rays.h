// Rays against the scene's 3D objects with Intel Embree, for the oracle's
// sub-sample refinement (exact_oracle.h, "Sub-sample objects"): a path to the
// nearest object along a ray that shares nothing with the project's own
// rasterizer (culling/raster/).
//
// Spheres are Embree's sphere points, boxes twelve triangles each, and each
// distinct mesh one Embree scene, instanced (translated) once per object that
// uses it. Embree works in single precision, so every frame places the objects
// relative to the camera (place()): a ray's precision then follows its length
// and the objects' sizes, not how far the scene sits from the world's origin.
// Each object's hit is found to float precision, about 1e-7 of the distance;
// docs/LIMITS.md says what that means near edges.
//
// nearest() is the first surface the ray meets in [near, far] with depth along
// the camera's forward axis (the direction's forward component is 1, as the
// rasterizer's rays have it). A solid that the camera's near-plane point lies
// inside is not a surface hit: the caller handles it (subsample_refiner.cpp).
// One Embree device serves every oracle of the process; a copy of this object
// starts empty and builds its scenes again at its next place().
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/scene/scene.h"

namespace gridcull {

class EmbreeRays {
public:
    EmbreeRays();
    ~EmbreeRays();
    EmbreeRays(const EmbreeRays&);
    EmbreeRays& operator=(const EmbreeRays&);

    // Forgets the scene; the next place() builds Embree's geometry for it.
    void reset();
    // Every 3D object of `scene` at its position shifted by shifts[i], relative
    // to `eye`. Builds the geometry at the first call after reset(), then only
    // moves it and rebuilds Embree's hierarchy.
    void place(const Scene& scene, const std::vector<glm::dvec3>& shifts, const glm::dvec3& eye);
    // The index of the object the ray eye + s * dir, s in [near, far], meets
    // first, or -1; `depth` is that s.
    int nearest(const glm::dvec3& dir, double near, double far, double& depth) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace gridcull
