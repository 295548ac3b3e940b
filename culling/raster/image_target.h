// What the lazy occlusion grid (culling/lazy_grid/lazy_grid.h) reads: the pixel-level
// queries of Hey et al. section 3, over whatever holds the drawn image. The
// software buffers answer them here (SoftwarePixelQueries); the app answers them from
// an OpenGL depth buffer with glReadPixels (app/gl_image_target.h), as the
// paper's section 7 did.
//
// And where the lazy grid's culler draws (ImageTarget): begin a frame, draw an
// object, answer queries. SoftwareImageTarget is the default: the exact
// oracle's rasterizer as z-buffer plus the one-bit occlusion buffer.
#pragma once
#include <cstddef>

#include <glm/vec3.hpp>

#include "culling/scene/camera.h"
#include "culling/raster/id_depth_buffer.h"
#include "culling/raster/screen_mapping.h"
#include "culling/raster/occlusion_buffer.h"
#include "culling/scene/scene.h"

namespace gridcull {

class PixelQueries {
public:
    virtual ~PixelQueries() = default;
    // Pixels of `rect` (inside the image) at which nothing has been drawn.
    virtual long long countFree(const PixelRect& rect) const = 0;
    // The farthest view-space depth in `rect` (inside the image); +infinity when a
    // pixel there is empty.
    virtual double farthestDepth(const PixelRect& rect) const = 0;
};

// The software buffers as pixels; a buffer may be null when no query needs it
// (countFree needs the occlusion buffer, farthestDepth the z-buffer).
class SoftwarePixelQueries final : public PixelQueries {
public:
    SoftwarePixelQueries(const OcclusionBuffer* obuffer, const IdDepthBuffer* zbuffer)
        : obuffer_(obuffer), zbuffer_(zbuffer) {}
    long long countFree(const PixelRect& rect) const override;
    double farthestDepth(const PixelRect& rect) const override;

private:
    const OcclusionBuffer* obuffer_;
    const IdDepthBuffer* zbuffer_;
};

class ImageTarget : public PixelQueries {
public:
    // Starts a frame of width x height pixels seen by `camera`: every pixel free.
    // occlusion_bits: the occlusion-buffer variant will ask countFree.
    virtual void begin(const Camera& camera, int width, int height, bool occlusion_bits) = 0;
    // Draws `object` (index `index` in the scene) moved by `shift`. Returns false
    // when it was rejected whole (nothing written); else sets `written` to the
    // pixels it may have written. `image_area` is its box's rectangle, for a target
    // that cannot tell which pixels it wrote.
    virtual bool draw(const SceneObject& object, int index, const glm::dvec3& shift,
                      const PixelRect& image_area, PixelRect& written) = 0;
    // Called by reset() with the scene to come: size what draw needs for its
    // meshes, so that draw never allocates.
    virtual void prepare(const Scene& scene) = 0;
    // The frame's last call: a target that queues work finishes it here, so that
    // the frame's time includes it.
    virtual void end() {}
};

class SoftwareImageTarget final : public ImageTarget {
public:
    void begin(const Camera& camera, int width, int height, bool occlusion_bits) override;
    bool draw(const SceneObject& object, int index, const glm::dvec3& shift,
              const PixelRect& image_area, PixelRect& written) override;
    long long countFree(const PixelRect& rect) const override { return pixels_.countFree(rect); }
    double farthestDepth(const PixelRect& rect) const override {
        return pixels_.farthestDepth(rect);
    }
    void prepare(const Scene& scene) override;

private:
    IdDepthBuffer zbuffer_;
    OcclusionBuffer obuffer_;
    bool occlusion_bits_ = false;
    SoftwarePixelQueries pixels_{&obuffer_, &zbuffer_};
};

}  // namespace gridcull
