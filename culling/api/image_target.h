// Where an image-space culler draws the objects it rates potentially visible and
// asks what it has drawn: an image of width x height pixels over exactly the
// camera's frustum (raster/screen_mapping.h says how boxes map onto it), pixel
// (0, 0) at the top left, depth the view-space distance along the camera's
// forward axis.
//
// The culler does not know what holds the image: the software rasterizer
// (raster/software_image_target.h) by default, or the app's OpenGL framebuffer,
// which answers each query with a read-back as a GPU implementation would. A
// family whose cullers take a target says so in its registry entry (draws_image),
// and the app then offers each of its algorithms with OpenGL as NAME-gl.
//
// One target serves both kinds of image-space culler: pixel queries (countFree,
// farthestDepth: a culler that reads pixels back) and occlusion
// queries (culling/api/occlusion_queries.h: a box tested against the drawn
// depth, answered later, as GL_ANY_SAMPLES_PASSED; Kovalčík & Sochor's BSP
// traversal). A culler uses whichever it needs; the other costs nothing.
//
// Parts of objects. Besides whole scene objects, a target draws ranges of
// triangle sets: a culler that splits objects into parts (the triangles of an
// object's BSP leaf, Kovalčík & Sochor section 3.1) registers each set once,
// in object space, after prepare(), and draws a part as a range of it moved by
// the object's translation. On a GPU a set is one vertex buffer, a part one
// draw call.
#pragma once
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/api/occlusion_queries.h"
#include "culling/api/pixel_rect.h"
#include "culling/scene/camera.h"
#include "culling/scene/scene.h"

namespace gridcull {

// The queries on the drawn image.
class PixelQueries {
public:
    virtual ~PixelQueries() = default;
    // Pixels of `rect` (inside the image) at which nothing has been drawn.
    virtual long long countFree(const PixelRect& rect) const = 0;
    // The farthest view-space depth in `rect` (inside the image); +infinity when a
    // pixel there is empty.
    virtual double farthestDepth(const PixelRect& rect) const = 0;
};

class ImageTarget : public PixelQueries, public OcclusionQueries {
public:
    // Starts a frame of width x height pixels seen by `camera`: every pixel free.
    // occlusion_bits: countFree will be asked (a target may keep a one-bit
    // coverage buffer for it). Occlusion queries issued in earlier frames stay
    // outstanding; a frame is what queryLatencyFrames counts.
    virtual void begin(const Camera& camera, int width, int height, bool occlusion_bits) = 0;
    // Draws `object` (index `index` in the scene) moved by `shift`. Returns false
    // when it was rejected whole (nothing written); else sets `written` to the
    // pixels it may have written. `image_area` is its box's rectangle, for a target
    // that cannot tell which pixels it wrote.
    virtual bool draw(const SceneObject& object, int index, const glm::dvec3& shift,
                      const PixelRect& image_area, PixelRect& written) = 0;
    // Called when the culler is reset for `scene`: size what draw needs for its
    // meshes and reserve the occlusion-query pool (kOcclusionQueryReserve), so
    // that draw and issueQuery never allocate; forgets outstanding queries and
    // zeroes the query counts.
    virtual void prepare(const Scene& scene) = 0;
    // The frame's last call: a target that queues work finishes it here, so that
    // the frame's time includes it.
    virtual void end() {}

    // Registers a triangle set: corners.size() / 3 triangles, three corners
    // each, in object space (corners.size() a multiple of 3). Returns its
    // handle, valid until the next prepare(). Allocates (and on a GPU uploads):
    // call it when the culler is reset, never per frame.
    virtual int addTriangleSet(const std::vector<glm::dvec3>& corners) = 0;
    // Draws triangles [first, first + count) of set `handle`, each corner moved
    // by `shift`, writing `index` as draw() does. Returns false when nothing
    // could be written (the range is empty, or outside [near, far]); else sets
    // `written` to the pixels it may have written, at most `image_area` for a
    // target that cannot tell. Never allocates.
    virtual bool drawTriangles(int handle, int first, int count, int index, const glm::dvec3& shift,
                               const PixelRect& image_area, PixelRect& written) = 0;

    // A copy of the target with its buffers, triangle sets and outstanding
    // queries (Culler::clone); null for a target that cannot be copied (a GPU's).
    virtual std::unique_ptr<ImageTarget> clone() const { return nullptr; }
};

// Owns an image target and copies it with clone(), so that a culler holding one
// keeps its implicit copy constructor; a target that cannot be copied copies as
// null, which the culler's clone() then reports.
class OwnedImageTarget {
public:
    OwnedImageTarget() = default;
    explicit OwnedImageTarget(std::unique_ptr<ImageTarget> target) : target_(std::move(target)) {}
    OwnedImageTarget(const OwnedImageTarget& other)
        : target_(other.target_ ? other.target_->clone() : nullptr) {}
    OwnedImageTarget& operator=(const OwnedImageTarget& other) {
        if (this != &other) target_ = other.target_ ? other.target_->clone() : nullptr;
        return *this;
    }
    OwnedImageTarget(OwnedImageTarget&&) = default;
    OwnedImageTarget& operator=(OwnedImageTarget&&) = default;

    ImageTarget* get() const { return target_.get(); }
    ImageTarget* operator->() const { return target_.get(); }
    ImageTarget& operator*() const { return *target_; }
    explicit operator bool() const { return target_ != nullptr; }

private:
    std::unique_ptr<ImageTarget> target_;
};

}  // namespace gridcull
