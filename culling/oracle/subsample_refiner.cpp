#include "culling/oracle/subsample_refiner.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "culling/oracle/pair_cover.h"
#include "culling/oracle/pixel_pyramid.h"
#include "culling/scene/ray_intersect.h"

namespace gridcull {

// Level 12 skips the points of level 4 it contains: a = 3 j + 1.
static_assert(SubsampleRefiner::kLastLevel == 3 * SubsampleRefiner::kFirstLevel);

double SubsampleRefiner::nearestInPixel(const View& view, const glm::dvec3 corners[8],
                                        bool sphere, const glm::dvec3& center, double radius,
                                        int px, int py) const {
    const PixelPyramid pyramid = pixelPyramid(view, px, py);
    return sphere ? leastSphereDepthInPyramid(pyramid, center, radius)
                  : leastBoxDepthInPyramid(pyramid, corners);
}

double SubsampleRefiner::coverDepth(const View& view, const Scene& scene,
                                   const std::vector<glm::dvec3>& shifts,
                                   const IdDepthBuffer& buffer, int px, int py) {
    constexpr double kOpen = std::numeric_limits<double>::infinity();
    const size_t p = size_t(py) * size_t(view.width) + size_t(px);
    if (cover_frame_[p] == frame_) return cover_[p];
    // The objects the centres of the pixel and its neighbours inside the image
    // see are the ones to try; a border pixel's corners are rays like any other.
    int ids[9];
    int distinct = 0;
    for (int dy = -1; dy <= 1; ++dy) {
        if (py + dy < 0 || py + dy >= view.height) continue;
        const int32_t* row = buffer.indexRow(py + dy);
        for (int dx = -1; dx <= 1; ++dx) {
            if (px + dx < 0 || px + dx >= view.width) continue;
            const int id = row[px + dx];
            if (id >= 0 && std::find(ids, ids + distinct, id) == ids + distinct) ids[distinct++] = id;
        }
    }
    double best = kOpen;
    for (int k = 0; k < distinct; ++k) {
        const SceneObject& object = scene.objects[size_t(ids[k])];
        const glm::dvec3& shift = shifts[size_t(ids[k])];
        if (object.shape != ShapeKind::Sphere && object.shape != ShapeKind::Box) continue;
        // The rays through the pixel's four corners: when all four meet the
        // object, its convex outline holds the square, no deeper there than at
        // the deepest corner (subsample_gate.h).
        double farthest = 0.0;
        for (int dy = 0; dy <= 1 && farthest < best; ++dy) {
            for (int dx = 0; dx <= 1 && farthest < best; ++dx) {
                const glm::dvec3 dir = view.ray(px + dx, py + dy);
                double s0, s1, s;
                const bool line = object.shape == ShapeKind::Sphere
                                      ? lineSphere(view.eye, dir, object.center + shift,
                                                   object.radius, s0, s1)
                                      : lineBox(view.eye, dir, object.box.translated(shift), s0, s1);
                if (!line || !solidEntry(s0, s1, view.near, view.far, s)) farthest = kOpen;
                else farthest = std::max(farthest, s);
            }
        }
        best = std::min(best, farthest);
    }
    // A seam: two of them, a box and another, may cover it together.
    if (best == kOpen && distinct >= 2) best = pairCoverDepth(view, scene, shifts, ids, distinct, px, py);
    cover_[p] = best;
    cover_frame_[p] = frame_;
    return best;
}

double SubsampleRefiner::pairCoverDepth(const View& view, const Scene& scene,
                                        const std::vector<glm::dvec3>& shifts, const int* ids,
                                        int distinct, int px, int py) const {
    CoverSolid solids[9];
    Silhouette outlines[9];
    for (int k = 0; k < distinct; ++k) {
        const SceneObject& object = scene.objects[size_t(ids[k])];
        const glm::dvec3& shift = shifts[size_t(ids[k])];
        CoverSolid& solid = solids[k];
        if (object.shape == ShapeKind::Sphere) {
            solid.sphere = true;
            solid.center = object.center + shift;
            solid.radius = object.radius;
            solid.box = {solid.center - solid.radius, solid.center + solid.radius};
        } else if (object.shape == ShapeKind::Box) {
            solid.box = object.box.translated(shift);
            // A box holding the eye covers everything alone (at depth near).
            if (!solid.box.contains(view.eye)) outlines[k] = boxSilhouette(view, solid.box);
        }
    }
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < distinct; ++i) {
        if (outlines[i].count < 3) continue;  // a sphere, a mesh, or no outline
        for (int j = 0; j < distinct; ++j) {
            const ShapeKind shape = scene.objects[size_t(ids[j])].shape;
            if (j == i || (shape != ShapeKind::Sphere && shape != ShapeKind::Box)) continue;
            best = std::min(best, gridcull::pairCoverDepth(view, px, py, solids[i], outlines[i],
                                                          solids[j], outlines[j]));
        }
    }
    return best;
}

int SubsampleRefiner::nearestAt(const View& view, const Scene& scene,
                                const std::vector<glm::dvec3>& shifts, double x, double y) const {
    const glm::dvec3 dir = view.ray(x, y);
    // The rasterizer gives depth near to a sphere or box that holds the eye or
    // the ray's near-plane point, the first drawn winning; Embree's rays start
    // at near and would see such a solid only where they leave it.
    const glm::dvec3 near_point = view.eye + view.near * dir;
    for (const int i : near_solids_) {
        const SceneObject& object = scene.objects[size_t(i)];
        const glm::dvec3& shift = shifts[size_t(i)];
        if (object.shape == ShapeKind::Sphere) {
            const glm::dvec3 c = object.center + shift;
            const double r2 = object.radius * object.radius;
            if (glm::dot(near_point - c, near_point - c) <= r2 ||
                glm::dot(view.eye - c, view.eye - c) <= r2)
                return i;
        } else {
            const Aabb box = object.box.translated(shift);
            if (box.contains(near_point) || box.contains(view.eye)) return i;
        }
    }
    double depth = 0.0;
    return rays_.nearest(dir, view.near, view.far, depth);
}

void SubsampleRefiner::refine(const Scene& scene, const Camera& camera,
                              const std::vector<glm::dvec3>& shifts, const IdDepthBuffer& buffer,
                              const std::vector<std::pair<double, int>>& order,
                              const std::vector<char>& drawn, std::vector<char>& seen,
                              std::vector<int>& undecided, SubsampleCounts& counts) {
    undecided.clear();
    View view;
    view.eye = camera.position;
    camera.basis(view.right, view.up, view.forward);
    view.tan_y = std::tan(glm::radians(camera.fov_deg) * 0.5);
    view.tan_x = view.tan_y * camera.aspect;
    view.near = camera.near;
    view.far = camera.far;
    view.width = buffer.width();
    view.height = buffer.height();
    const size_t pixels = size_t(view.width) * size_t(view.height);
    if (level_.size() != pixels) {
        level_.assign(pixels, 0);
        touched_.clear();
        cover_.assign(pixels, 0.0);
        cover_frame_.assign(pixels, 0);
        frame_ = 0;
    }
    if (++frame_ == 0) {  // the stamps wrapped: none of them may look current
        std::fill(cover_frame_.begin(), cover_frame_.end(), 0u);
        frame_ = 1;
    }
    for (const size_t p : touched_) level_[p] = 0;
    touched_.clear();
    gate_.build(buffer);

    // Every near-plane point of a ray through the image lies within `reach` of
    // the eye, so only a solid that comes that close can hold one (or the eye).
    // The depth key alone would also keep everything behind the camera, which
    // every ray would then test. (The margin covers the rounding of reach.)
    near_solids_.clear();
    const double reach = view.near *
                         std::sqrt(1.0 + view.tan_x * view.tan_x + view.tan_y * view.tan_y) *
                         (1.0 + 1e-9);
    for (const auto& [key, i] : order) {
        if (key > camera.near) break;  // order is by nearest depth
        const SceneObject& object = scene.objects[size_t(i)];
        const glm::dvec3& shift = shifts[size_t(i)];
        if (object.shape == ShapeKind::Sphere) {
            const double gap = glm::length(object.center + shift - view.eye) - object.radius;
            if (gap <= reach) near_solids_.push_back(i);
        } else if (object.shape == ShapeKind::Box) {
            const Aabb box = object.box.translated(shift);
            const glm::dvec3 outside = glm::max(glm::max(box.min - view.eye, view.eye - box.max), 0.0);
            if (glm::dot(outside, outside) <= reach * reach) near_solids_.push_back(i);
        }
    }

    bool placed = false;
    for (const auto& [key, i] : order) {
        if (seen[size_t(i)] || !drawn[size_t(i)]) continue;
        const SceneObject& object = scene.objects[size_t(i)];
        const glm::dvec3& shift = shifts[size_t(i)];
        const bool sphere = object.shape == ShapeKind::Sphere;
        const Aabb bounds = sphere ? Aabb{object.center + shift - object.radius,
                                          object.center + shift + object.radius}
                                   : object.bounds.translated(shift);
        ScreenRange cols, rows;
        double z_min = 0.0;
        if (!buffer.screenBounds(bounds, cols, rows, z_min)) continue;
        const double z = std::max(key, z_min);
        if (!gate_.mayShow(cols, rows, z)) continue;

        // In view space, as the pyramid test wants them.
        glm::dvec3 corners[8];
        for (int c = 0; c < 8; ++c) corners[c] = view.toView(bounds.corner(c));
        const glm::dvec3 center = view.toView(object.center + shift);
        // A mesh reaches the pixels its triangles reach, far fewer than its
        // bounding box does (mesh_footprint.h).
        const bool footprint = object.shape == ShapeKind::Mesh && object.mesh &&
                               footprint_.build(view, *object.mesh, object.center + shift, cols, rows);
        // A box's (or a mesh's bounding box's) outline tells cheaply which pixels
        // it reaches; its least depth there is searched only where something
        // covers the pixel (over the background any depth may show).
        Silhouette outline;
        if (!sphere && !footprint && !bounds.contains(view.eye)) outline = boxSilhouette(view, bounds);
        const bool outlined = outline.count >= 3;
        constexpr double kNothing = std::numeric_limits<double>::infinity();
        pixels_.clear();
        for (int py = rows.lo; py <= rows.hi; ++py)
            for (int px = cols.lo; px <= cols.hi; ++px) {
                const double gate = gate_.gate(px, py);
                if (gate < z) continue;
                const double cover = coverDepth(view, scene, shifts, buffer, px, py);
                if (cover < z) continue;
                if (outlined && !outlineMeetsPixel(outline, px, py)) continue;
                // The object's own least depth in this pixel, when it reaches it.
                double here = z;
                if (!outlined || std::min(gate, cover) != kNothing)
                    here = std::max(z, footprint ? footprint_.leastDepth(px, py)
                                                 : nearestInPixel(view, corners, sphere, center,
                                                                  object.radius, px, py));
                if (here != kNothing && gate >= here && cover >= here)
                    pixels_.push_back(size_t(py) * size_t(view.width) + size_t(px));
            }
        if (pixels_.empty()) continue;
        ++counts.candidates;

        if (!placed) {
            rays_.place(scene, shifts, camera.position);
            placed = true;
        }
        for (const int level : {kFirstLevel, kLastLevel}) {
            for (const size_t p : pixels_) {
                if (seen[size_t(i)] || counts.rays >= kMaxRaysPerFrame) break;
                if (level_[p] >= level) continue;
                const bool skip_first = level_[p] == kFirstLevel;
                if (level_[p] == 0) touched_.push_back(p);
                level_[p] = uint8_t(level);
                const int px = int(p % size_t(view.width)), py = int(p / size_t(view.width));
                for (int b = 0; b < level; ++b) {
                    for (int a = 0; a < level; ++a) {
                        if (skip_first && a % 3 == 1 && b % 3 == 1) continue;
                        const int hit = nearestAt(view, scene, shifts, px + (a + 0.5) / level,
                                                  py + (b + 0.5) / level);
                        ++counts.rays;
                        if (hit >= 0 && !seen[size_t(hit)]) {
                            seen[size_t(hit)] = kSeenByRay;
                            ++counts.found;
                        }
                    }
                }
            }
        }
        if (!seen[size_t(i)]) undecided.push_back(i);
    }
    // A candidate left undecided may have been found by a later one's rays.
    undecided.erase(std::remove_if(undecided.begin(), undecided.end(),
                                   [&](int i) { return seen[size_t(i)] != 0; }),
                    undecided.end());
    counts.undecided = int64_t(undecided.size());
}

}  // namespace gridcull
