// The software image target (culling/api/image_target.h): the shared
// rasterizer's ID-and-depth buffer (raster/id_depth_buffer.h) as z-buffer, plus a
// one-bit occlusion buffer (raster/occlusion_buffer.h) for countFree, both at
// pixel centres, so that an image-space culler sees exactly the pixels the oracle
// samples at the same resolution.
//
// Occlusion queries (culling/api/occlusion_queries.h) run the z-buffer's
// depth-test-only pass (IdDepthBuffer::boxPassesDepthTest) at issue time, so
// they are exact at the rasterizer's pixel centres: conservative with respect to
// the exact oracle at the same resolution. Their answers are held back
// setQueryLatency(n) frames (0 by default: available at once), so that a
// culler can be tested against the latency of a GPU's queries.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

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
    SoftwareImageTarget() = default;
    // A copy answers its pixel queries from its own buffers.
    SoftwareImageTarget(const SoftwareImageTarget& other);
    SoftwareImageTarget& operator=(const SoftwareImageTarget&) = delete;
    std::unique_ptr<ImageTarget> clone() const override {
        return std::make_unique<SoftwareImageTarget>(*this);
    }

    void begin(const Camera& camera, int width, int height, bool occlusion_bits) override;
    void end() override { in_frame_ = false; }
    bool draw(const SceneObject& object, int index, const glm::dvec3& shift,
              const PixelRect& image_area, PixelRect& written) override;
    long long countFree(const PixelRect& rect) const override { return pixels_.countFree(rect); }
    double farthestDepth(const PixelRect& rect) const override {
        return pixels_.farthestDepth(rect);
    }
    void prepare(const Scene& scene) override;
    int addTriangleSet(const std::vector<glm::dvec3>& corners) override;
    bool drawTriangles(int handle, int first, int count, int index, const glm::dvec3& shift,
                       const PixelRect& image_area, PixelRect& written) override;

    OcclusionQuery issueQuery(const Aabb& box) override;
    bool queryAvailable(const OcclusionQuery& query) override;
    bool queryResult(const OcclusionQuery& query) override;
    int queryLatencyFrames() const override { return latency_; }
    OcclusionQueryCounts queryCounts() const override { return counts_; }
    int outstandingQueries() const override { return queries_.outstanding(); }
    void resetQueries() override { queries_.releaseAll(); }
    // Holds every answer back `frames` (>= 0) begin() calls after its issue.
    void setQueryLatency(int frames);
    // The query pool's slots (kOcclusionQueryReserve after prepare(); it doubles
    // when more are outstanding).
    int queryCapacity() const { return queries_.capacity(); }

private:
    struct QueryAnswer {
        bool visible = true;
        long long ready_frame = 0;  // available once frame_ >= ready_frame
    };
    IdDepthBuffer zbuffer_;
    OcclusionBuffer obuffer_;
    bool occlusion_bits_ = false;
    SoftwarePixelQueries pixels_{&obuffer_, &zbuffer_};
    Camera camera_;
    bool in_frame_ = false;
    long long frame_ = 0;  // begin() calls since construction
    int latency_ = 0;
    OcclusionQueryPool<QueryAnswer> queries_;
    OcclusionQueryCounts counts_;
    std::vector<std::vector<glm::dvec3>> triangle_sets_;  // by handle
};

}  // namespace gridcull
