#include "culling/raster/software_image_target.h"

#include <algorithm>
#include <cassert>

namespace gridcull {

SoftwareImageTarget::SoftwareImageTarget(const SoftwareImageTarget& other)
    : ImageTarget(other),
      zbuffer_(other.zbuffer_),
      obuffer_(other.obuffer_),
      occlusion_bits_(other.occlusion_bits_),
      camera_(other.camera_),
      in_frame_(other.in_frame_),
      frame_(other.frame_),
      latency_(other.latency_),
      queries_(other.queries_),
      counts_(other.counts_),
      triangle_sets_(other.triangle_sets_) {}

long long SoftwarePixelQueries::countFree(const PixelRect& rect) const {
    assert(obuffer_ && "the occlusion-buffer variant needs the occlusion buffer");
    return obuffer_->countFree(rect);
}

double SoftwarePixelQueries::farthestDepth(const PixelRect& rect) const {
    assert(zbuffer_ && "the z-buffer variant needs the z-buffer");
    double farthest = 0.0;
    for (int py = rect.y0; py <= rect.y1; ++py) {
        const double* row = zbuffer_->depthRow(py);
        for (int px = rect.x0; px <= rect.x1; ++px) farthest = std::max(farthest, row[px]);
    }
    return farthest;
}

void SoftwareImageTarget::prepare(const Scene& scene) {
    size_t vertices = 0;
    for (const SceneObject& object : scene.objects)
        if (object.mesh) vertices = std::max(vertices, object.mesh->vertices.size());
    zbuffer_.reserveMeshVertices(vertices);
    queries_.reserve(kOcclusionQueryReserve);
    queries_.releaseAll();
    counts_ = {};
    triangle_sets_.clear();
}

int SoftwareImageTarget::addTriangleSet(const std::vector<glm::dvec3>& corners) {
    assert(corners.size() % 3 == 0);
    triangle_sets_.push_back(corners);
    return int(triangle_sets_.size()) - 1;
}

bool SoftwareImageTarget::drawTriangles(int handle, int first, int count, int index,
                                        const glm::dvec3& shift, const PixelRect& /*image_area*/,
                                        PixelRect& written) {
    assert(handle >= 0 && size_t(handle) < triangle_sets_.size() && "not a triangle set");
    const std::vector<glm::dvec3>& corners = triangle_sets_[size_t(handle)];
    assert(first >= 0 && count >= 0 && size_t(first + count) * 3 <= corners.size());
    if (count <= 0) return false;
    if (!zbuffer_.drawTriangles(index, corners.data() + 3 * size_t(first), size_t(count), shift))
        return false;
    const ScreenRange cols = zbuffer_.lastDrawCols(), rows = zbuffer_.lastDrawRows();
    written = {cols.lo, rows.lo, cols.hi, rows.hi};
    if (occlusion_bits_) obuffer_.markDrawn(zbuffer_, written);
    return true;
}

void SoftwareImageTarget::begin(const Camera& camera, int width, int height, bool occlusion_bits) {
    zbuffer_.resize(width, height);
    zbuffer_.setWriteIds(false);  // image-space cullers read depths (and bits) only
    zbuffer_.begin(camera);
    camera_ = camera;
    in_frame_ = true;
    ++frame_;
    occlusion_bits_ = occlusion_bits;
    if (occlusion_bits) {
        obuffer_.resize(width, height);
        obuffer_.clear();
    }
}

bool SoftwareImageTarget::draw(const SceneObject& object, int index, const glm::dvec3& shift,
                               const PixelRect& /*image_area*/, PixelRect& written) {
    if (!zbuffer_.drawObject(index, object, shift)) return false;
    const ScreenRange cols = zbuffer_.lastDrawCols(), rows = zbuffer_.lastDrawRows();
    written = {cols.lo, rows.lo, cols.hi, rows.hi};
    if (occlusion_bits_) obuffer_.markDrawn(zbuffer_, written);
    return true;
}

void SoftwareImageTarget::setQueryLatency(int frames) {
    assert(frames >= 0);
    latency_ = frames;
}

OcclusionQuery SoftwareImageTarget::issueQuery(const Aabb& box) {
    assert(in_frame_ && "issueQuery between begin() and end()");
    const OcclusionQuery query = queries_.acquire();
    QueryAnswer& answer = queries_.payload(query);
    ++counts_.issued;
    if (occlusionQueryTriviallyVisible(camera_, box)) {
        ++counts_.trivial;
        answer.visible = true;
    } else {
        answer.visible = zbuffer_.boxPassesDepthTest(box);
    }
    answer.ready_frame = frame_ + latency_;
    return query;
}

bool SoftwareImageTarget::queryAvailable(const OcclusionQuery& query) {
    return frame_ >= queries_.payload(query).ready_frame;
}

bool SoftwareImageTarget::queryResult(const OcclusionQuery& query) {
    const QueryAnswer answer = queries_.payload(query);
    ++counts_.read;
    if (frame_ < answer.ready_frame) ++counts_.stalled;
    queries_.release(query);
    return answer.visible;
}

}  // namespace gridcull
