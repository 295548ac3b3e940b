// An image target (culling/api/image_target.h) on OpenGL: objects drawn into a
// framebuffer, each pixel query answered with glReadPixels of the depth buffer,
// as a GPU implementation of an image-space culler does (Hey, Tobler &
// Purgathofer measured exactly this, "reading the hardware z-buffer ... with the
// glReadPixels function"). It backs the `-gl` algorithms of
// app/app_cullers.h, for `cull` and `bench`, so that a query costs a round trip
// to the GPU.
//
// Objects are drawn depth-only into a width x height framebuffer object with
// the culling camera's view and projection (Camera::viewMatrix,
// projectionMatrix): spheres as a 32 x 16 latitude-longitude mesh, boxes as
// cubes, meshes as they are. A draw cannot tell which pixels it wrote, so it
// reports its box's rectangle (the paper's "image area"). countFree counts
// depth 1.0 (the cleared value) in the rectangle; farthestDepth returns the
// largest depth, turned back into view-space distance, +infinity if any pixel is
// empty. Rows are flipped (GL counts them from the bottom).
//
// Not the oracle's rasterization: OpenGL rasterizes in 32-bit floats with its
// own edge rule, spheres are facetted and depths 24-bit, so the exact oracle at
// the same resolution can see an object past an occluder's silhouette that this
// target's image hides. bench reports such false culls; an image-space culler's
// conservative guarantee is for the software target. Needs a current OpenGL 3.3
// core context for its whole life.
//
// Occlusion queries (culling/api/occlusion_queries.h) are GL_ANY_SAMPLES_PASSED
// query objects around a draw of the box as a cube, with colour and depth writes
// off, against the depth drawn so far: they sample the same pixel centres as the
// software target, so on the same boxes they agree with it up to float
// arithmetic, 24-bit depth and facetted spheres (tests/app/gl_image_target_test
// measures how often). A box containing the eye or crossing the near plane
// answers visible without a query, as on every target. One query object per
// pool slot, made in prepare() (and when the pool doubles), deleted with the
// target. queryAvailable asks GL_QUERY_RESULT_AVAILABLE, queryResult
// GL_QUERY_RESULT (it may wait for the GPU); the latency is 0 frames, since
// end() finishes the frame's work.
#pragma once
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>

#include "app/gl_objects.h"
#include "app/offscreen_target.h"
#include "culling/api/image_target.h"

namespace gridcull {

class GlImageTarget final : public ImageTarget {
public:
    GlImageTarget() = default;
    GlImageTarget(const GlImageTarget&) = delete;
    GlImageTarget& operator=(const GlImageTarget&) = delete;
    ~GlImageTarget() override;
    // Compiles the shader and uploads the unit sphere and cube.
    bool init(std::string& error);
    void prepare(const Scene& scene) override;
    void begin(const Camera& camera, int width, int height, bool occlusion_bits) override;
    bool draw(const SceneObject& object, int index, const glm::dvec3& shift,
              const PixelRect& image_area, PixelRect& written) override;
    long long countFree(const PixelRect& rect) const override;
    double farthestDepth(const PixelRect& rect) const override;
    void end() override;
    int addTriangleSet(const std::vector<glm::dvec3>& corners) override;
    bool drawTriangles(int handle, int first, int count, int index, const glm::dvec3& shift,
                       const PixelRect& image_area, PixelRect& written) override;

    OcclusionQuery issueQuery(const Aabb& box) override;
    bool queryAvailable(const OcclusionQuery& query) override;
    bool queryResult(const OcclusionQuery& query) override;
    int queryLatencyFrames() const override { return 0; }
    OcclusionQueryCounts queryCounts() const override { return counts_; }
    int outstandingQueries() const override { return queries_.outstanding(); }
    void resetQueries() override { queries_.releaseAll(); }

private:
    struct GlQuery {
        GLuint name = 0;       // the query object, 0 until made
        bool trivial = false;  // answered visible without a query
    };
    // Makes the query objects of the slots that have none.
    void makeQueryObjects();
    struct Mesh {
        GlVertexArray vao;
        GlBuffer vertices, indices;
        int index_count = 0;
    };
    Mesh upload(const std::vector<float>& positions, const std::vector<uint32_t>& indices);
    // A triangle set: one vertex buffer, three vertices a triangle, drawn by ranges.
    struct TriangleSet {
        GlVertexArray vao;
        GlBuffer vertices;
        int triangle_count = 0;
    };
    // Reads `rect`'s depths into depth_ (row-major, any order) and returns their count.
    size_t readDepths(const PixelRect& rect) const;
    void drawMesh(const Mesh& mesh, const glm::mat4& model);

    GlProgram program_;
    GLint mvp_location_ = -1;
    Mesh sphere_, cube_;
    std::unordered_map<const TriangleMesh*, Mesh> meshes_;
    std::vector<TriangleSet> triangle_sets_;  // by handle
    OffscreenTarget framebuffer_;
    glm::mat4 view_projection_{1.0f};
    double near_ = 0.1, far_ = 1000.0;
    int height_ = 0;
    mutable std::vector<float> depth_;
    Camera camera_;
    OcclusionQueryPool<GlQuery> queries_;
    OcclusionQueryCounts counts_;
};

}  // namespace gridcull
