#include "culling/oracle/exact_oracle.h"

#include <algorithm>
#include <cmath>

namespace gridcull {

ExactOracle::ExactOracle(const OracleOptions& options) : options_(options) {
    options_.resolution = std::clamp(options_.resolution, 1, kMaxOracleResolution);
    options_.rays_per_turn = std::clamp(options_.rays_per_turn, 0, kMaxOracleRaysPerTurn);
}

void ExactOracle::imageSize(int resolution, double aspect, int& width, int& height) {
    imageSizeForAspect(resolution, aspect, width, height);
}

int ExactOracle::rayCount(int rays_per_turn, double fov_deg) {
    const double rays = std::ceil(std::clamp(fov_deg, 0.0, 360.0) / 360.0 * rays_per_turn);
    return std::max(64, int(rays));
}

void ExactOracle::reset(const Scene& scene) {
    order_.clear();
    order_.reserve(scene.objects.size());
    seen_.assign(scene.objects.size(), 0);
    drawn_.assign(scene.objects.size(), 0);
    undecided_.clear();
    undecided_.reserve(scene.objects.size());
    refiner_.reset();
    shifts_.assign(scene.objects.size(), glm::dvec3(0.0));
    size_t largest_mesh = 0;
    for (const SceneObject& object : scene.objects)
        if (object.mesh) largest_mesh = std::max(largest_mesh, object.mesh->vertices.size());
    id_buffer_.reserveMeshVertices(largest_mesh);
    if (scene.dimensions == 2 && options_.rays_per_turn == 0) {
        size_t vertices = 0, largest = 0;
        for (const SceneObject& object : scene.objects) {
            const size_t n = object.shape == ShapeKind::Polygon ? object.points.size() : 4;
            vertices += n;
            largest = std::max(largest, n);
        }
        envelope_.reserve(scene.objects.size(), vertices, largest);
    } else if (scene.dimensions == 2) {
        sweep_.resize(rayCount(options_.rays_per_turn, scene.camera.fov_deg), scene.camera.fov_deg);
    } else {
        int width, height;
        imageSize(options_.resolution, scene.camera.aspect, width, height);
        id_buffer_.resize(width, height);
    }
}

void ExactOracle::cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) {
    out.stats = CullStats{};
    out.pvs.clear();
    out.sub_sample_visible.clear();
    out.sub_sample_undecided.clear();
    // Sized in reset(); these only grow when cull() is handed a larger scene.
    if (seen_.size() != scene.objects.size()) {
        seen_.resize(scene.objects.size());
        drawn_.resize(scene.objects.size());
        shifts_.resize(scene.objects.size());
    }
    std::fill(seen_.begin(), seen_.end(), char(0));
    order_.clear();
    if (scene.dimensions == 2)
        cull2d(scene, camera, t, out);
    else
        cull3d(scene, camera, t, out);
    collect(scene, out);
}

void ExactOracle::cull3d(const Scene& scene, const Camera& camera, double t, FrameResult& out) {
    int width, height;
    imageSize(options_.resolution, camera.aspect, width, height);
    id_buffer_.resize(width, height);
    id_buffer_.begin(camera);

    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        const glm::dvec3 shift = scene.displacementAt(object, t);
        shifts_[i] = shift;
        const double key = object.shape == ShapeKind::Sphere
                               ? id_buffer_.minDepthOfSphere(object.center + shift, object.radius)
                               : id_buffer_.minDepthOfBox(object.bounds.translated(shift));
        order_.emplace_back(key, int(i));
    }
    // Front to back, so that hidden pixels are skipped with one compare.
    std::sort(order_.begin(), order_.end());

    int64_t tested = 0;
    for (const auto& [key, i] : order_) {
        const SceneObject& object = scene.objects[size_t(i)];
        const glm::dvec3& shift = shifts_[size_t(i)];
        drawn_[size_t(i)] = id_buffer_.drawObject(i, object, shift) ? 1 : 0;
        tested += drawn_[size_t(i)];
    }
    id_buffer_.markVisible(seen_);
    out.stats.set(Counter::ObjectsTested, tested);
    out.stats.set(Counter::PixelsSampled, int64_t(width) * height);
    if (!options_.refine) return;
    SubsampleCounts counts;
    refiner_.refine(scene, camera, shifts_, id_buffer_, order_, drawn_, seen_, undecided_, counts);
    for (const int i : undecided_) out.sub_sample_undecided.push_back(scene.objects[size_t(i)].id);
    std::sort(out.sub_sample_undecided.begin(), out.sub_sample_undecided.end());
    out.stats.set(Counter::SubSampleCandidates, counts.candidates);
    out.stats.set(Counter::SubSampleVisible, counts.found);
    out.stats.set(Counter::SubSampleUndecided, counts.undecided);
    out.stats.set(Counter::RefineRays, counts.rays);
}

void ExactOracle::cull2d(const Scene& scene, const Camera& camera, double t, FrameResult& out) {
    int64_t tested = 0, rays = 0;
    if (options_.rays_per_turn == 0) {
        envelope_.begin(camera);
        tested = draw2d(envelope_, scene, t);
        envelope_.markVisible(seen_);
        rays = envelope_.raysCast();
    } else {
        sweep_.resize(rayCount(options_.rays_per_turn, camera.fov_deg), camera.fov_deg);
        sweep_.begin(camera);
        tested = draw2d(sweep_, scene, t);
        sweep_.markVisible(seen_);
        rays = sweep_.rays();
    }
    out.stats.set(Counter::ObjectsTested, tested);
    out.stats.set(Counter::PixelsSampled, rays);
}

template <class Canvas>
int64_t ExactOracle::draw2d(Canvas& canvas, const Scene& scene, double t) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        const glm::dvec3 shift = scene.displacementAt(object, t);
        shifts_[i] = shift;
        const double key = object.shape == ShapeKind::Sphere
                               ? canvas.minDistanceOfCircle(object.center + shift, object.radius)
                               : canvas.minDistanceOfBox(object.bounds.translated(shift));
        order_.emplace_back(key, int(i));
    }
    // Front to back: hidden parts are skipped, and ties go to the nearer bound.
    std::sort(order_.begin(), order_.end());

    int64_t tested = 0;
    for (const auto& [key, i] : order_) {
        const SceneObject& object = scene.objects[size_t(i)];
        const glm::dvec3& shift = shifts_[size_t(i)];
        bool drawn = false;
        switch (object.shape) {
            case ShapeKind::Sphere:
                drawn = canvas.drawCircle(i, object.center + shift, object.radius);
                break;
            case ShapeKind::Box:
                drawn = canvas.drawBox(i, object.box.translated(shift));
                break;
            case ShapeKind::Polygon:
                drawn = canvas.drawPolygon(i, object.points.data(), object.points.size(), shift);
                break;
            case ShapeKind::Mesh:
                break;  // 3D only
        }
        tested += drawn ? 1 : 0;
    }
    return tested;
}

void ExactOracle::collect(const Scene& scene, FrameResult& out) {
    for (size_t i = 0; i < seen_.size(); ++i) {
        if (seen_[i] == SubsampleRefiner::kSeenByRay)
            out.sub_sample_visible.push_back(scene.objects[i].id);
        else if (seen_[i])
            out.pvs.push_back(scene.objects[i].id);
    }
    std::sort(out.pvs.begin(), out.pvs.end());
    std::sort(out.sub_sample_visible.begin(), out.sub_sample_visible.end());
}

}  // namespace gridcull
