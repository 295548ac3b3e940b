// The software image target (culling/api/image_target.h): the shared
// rasterizer's ID-and-depth buffer (raster/id_depth_buffer.h) as z-buffer, plus a
// one-bit occlusion buffer (raster/occlusion_buffer.h) for countFree, both at
// pixel centres, so that an image-space culler sees exactly the pixels the oracle
// samples at the same resolution.
#pragma once
#include <cstddef>

#include <glm/vec3.hpp>

#include "culling/api/image_target.h"
#include "culling/raster/id_depth_buffer.h"
#include "culling/raster/occlusion_buffer.h"
#include "culling/raster/screen_mapping.h"

namespace gridcull {

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
