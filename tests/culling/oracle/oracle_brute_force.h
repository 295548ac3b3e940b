// A brute-force reference for the exact oracle (culling/oracle/exact_oracle.h): it casts
// every pixel's (ray's) documented sample ray against every object, with no
// screen bounds, no ordering and no early-outs, and keeps the nearest hit. It
// shares only culling/scene/ray_intersect.h with the oracle, so comparing the two
// checks everything the oracle adds on top of those functions.
// Cost: O(samples * (objects + mesh triangles)); for tests at low resolution.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "culling/oracle/exact_oracle.h"
#include "culling/scene/camera.h"
#include "culling/scene/ray_intersect.h"

namespace gridcull::test {

// The brute-force reference: per sample, every object's hit, nearest wins. Depths
// within a relative 1e-9 of the nearest count as a tie (the oracle computes the
// same surface in another coordinate frame and may round the other way); a
// sample's id is required when it has no tie and allowed when it is in one.
struct Reference {
    std::set<int> required, allowed;
    void sample(const std::vector<std::pair<double, int>>& hits) {
        if (hits.empty()) return;
        double best = std::numeric_limits<double>::infinity();
        for (const auto& h : hits) best = std::min(best, h.first);
        int tied = 0, winner = -1;
        for (const auto& h : hits) {
            if (h.first <= best * (1.0 + 1e-9) + 1e-12) {
                ++tied;
                winner = h.second;
                allowed.insert(h.second);
            }
        }
        if (tied == 1) required.insert(winner);
    }
};

inline void referenceHits3d(const Scene& scene, double t, const glm::dvec3& eye,
                            const glm::dvec3& dir, double near, double far,
                            std::vector<std::pair<double, int>>& hits) {
    for (const SceneObject& o : scene.objects) {
        const glm::dvec3 shift = scene.displacementAt(o, t);
        double s0, s1, s;
        if (o.shape == ShapeKind::Sphere) {
            if (lineSphere(eye, dir, o.center + shift, o.radius, s0, s1) &&
                solidEntry(s0, s1, near, far, s))
                hits.push_back({s, o.id});
        } else if (o.shape == ShapeKind::Box) {
            if (lineBox(eye, dir, o.box.translated(shift), s0, s1) &&
                solidEntry(s0, s1, near, far, s))
                hits.push_back({s, o.id});
        } else if (o.shape == ShapeKind::Mesh) {
            const TriangleMesh& m = *o.mesh;
            const glm::dvec3 offset = o.center + shift;
            // A line that misses the mesh's bounds misses every triangle.
            if (!lineBox(eye, dir, m.bounds.translated(offset), s0, s1)) continue;
            double nearest = std::numeric_limits<double>::infinity();
            int crossings = 0;
            for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
                if (!lineTriangle(eye, dir, m.vertices[m.indices[i]] + offset,
                                  m.vertices[m.indices[i + 1]] + offset,
                                  m.vertices[m.indices[i + 2]] + offset, s) ||
                    s < near)
                    continue;
                ++crossings;
                if (s <= far) nearest = std::min(nearest, s);
            }
            // A closed mesh is solid: a near-plane point inside it sees it at near.
            if (m.closed && crossings % 2 == 1) nearest = near;
            if (nearest <= far) hits.push_back({nearest, o.id});
        }
    }
}

inline void referenceHits2d(const Scene& scene, double t, const glm::dvec3& eye,
                            const glm::dvec3& dir, double far,
                            std::vector<std::pair<double, int>>& hits) {
    for (const SceneObject& o : scene.objects) {
        const glm::dvec3 shift = scene.displacementAt(o, t);
        double s0, s1, s;
        bool hit = false;
        if (o.shape == ShapeKind::Sphere) {
            hit = lineSphere(eye, dir, o.center + shift, o.radius, s0, s1) &&
                  solidEntry(s0, s1, 0.0, far, s);
        } else if (o.shape == ShapeKind::Box) {
            hit = lineBox(eye, dir, o.box.translated(shift), s0, s1) &&
                  solidEntry(s0, s1, 0.0, far, s);
        } else if (o.shape == ShapeKind::Polygon) {
            if (pointInPolygon2d(eye, o.points.data(), o.points.size(), shift)) {
                s = 0.0;
                hit = true;
            } else {
                hit = rayPolygonEdges2d(eye, dir, o.points.data(), o.points.size(), shift, s) &&
                      s <= far;
            }
        }
        if (hit) hits.push_back({s, o.id});
    }
}

inline Reference bruteForce(const Scene& scene, double t, const OracleOptions& options) {
    const Camera cam = cameraAt(scene, t);
    Reference ref;
    std::vector<std::pair<double, int>> hits;
    if (scene.dimensions == 3) {
        int w, h;
        ExactOracle::imageSize(options.resolution, cam.aspect, w, h);
        glm::dvec3 right, up, fwd;
        cam.basis(right, up, fwd);
        const double tan_y = std::tan(glm::radians(cam.fov_deg) / 2), tan_x = tan_y * cam.aspect;
        for (int py = 0; py < h; ++py) {
            for (int px = 0; px < w; ++px) {
                const double u = (2.0 * (px + 0.5) / w - 1.0) * tan_x;
                const double v = (1.0 - 2.0 * (py + 0.5) / h) * tan_y;
                hits.clear();
                referenceHits3d(scene, t, cam.position, fwd + u * right + v * up, cam.near, cam.far,
                                hits);
                ref.sample(hits);
            }
        }
    } else {
        const int rays = ExactOracle::rayCount(options.rays_per_turn, cam.fov_deg);
        const glm::dvec3 fwd = cam.forward();
        const double fov = glm::radians(cam.fov_deg);
        const double start = std::atan2(fwd.y, fwd.x) - fov / 2;
        for (int i = 0; i < rays; ++i) {
            const double a = start + (i + 0.5) * fov / rays;
            hits.clear();
            referenceHits2d(scene, t, cam.position, {std::cos(a), std::sin(a), 0.0}, cam.far, hits);
            ref.sample(hits);
        }
    }
    return ref;
}

}  // namespace gridcull::test
