// An independent per-pixel reference for the ID buffer (culling/raster/id_depth_buffer.h),
// written from first principles: per pixel centre, the documented ray
//   eye + s * (forward + u*right + v*up),
//   u = (2 (px + 0.5) / width - 1) * tan(fov_y / 2) * aspect,
//   v = (1 - 2 (py + 0.5) / height) * tan(fov_y / 2),
// is intersected with every shape by code of its own (no culling/scene/ray_intersect.h,
// no screen bounds, no fill rule: a ray-sphere quadratic, a slab test and a
// signed-volume ray-triangle test), and the nearest s in [near, far] is kept.
// Solids (spheres, boxes, closed meshes) are met at depth near when the ray's
// near-plane point is inside them, as the buffer documents.
//
// The buffer keeps no per-pixel id accessor, so a shape's pixels are read by
// drawing it alone (covered = depth < +infinity), and a whole scene is checked by
// its per-pixel depth (which identifies the winner wherever the shapes' depths
// differ) and its visible set (markVisible).
//
// A pixel whose ray grazes a shape (tangent to a sphere, through a box edge or a
// triangle edge, at depth near or far within rounding) may honestly go either
// way: such pixels are "on the boundary" and skipped; tests bound how many.
// Cost: O(pixels * (shapes + triangles)); for small images only.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "culling/raster/id_depth_buffer.h"
#include "culling/scene/camera.h"
#include "culling/scene/scene.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull::test {

// The designed cases' camera: turned off every axis (so no pixel ray is
// axis-parallel by accident), kRasterWidth x kRasterHeight pixels over an
// aspect of 1.5.
constexpr int kRasterWidth = 48;
constexpr int kRasterHeight = 32;
inline Camera obliqueCamera() {
    Camera camera;
    camera.position = {1.0, 2.0, 3.0};
    camera.target = {1.4, 2.3, 13.0};
    camera.fov_deg = 60.0;
    camera.aspect = 1.5;
    camera.near = 0.5;
    camera.far = 50.0;
    return camera;
}

// Depths agree within this relative error. Both sides solve the same exact
// equation along different arithmetic paths (the buffer: view-space quadratics
// and slabs with per-row and per-column slopes, 1/z interpolated in screen space
// for triangles; here: world-space quadratics, slabs and ray-plane hits), so they
// differ by rounding only: a few ulps amplified by the conditioning of the
// problem (about 1e-13 relative for the shapes and slopes of these tests once
// grazing rays are set aside; IdDepthBufferRandom prints the worst it meets,
// 7.9e-14). 1e-9 leaves four orders of margin and is still far below any real
// error: a depth taken from the wrong surface or the wrong pixel is off by many
// orders more.
constexpr double kDepthTolerance = 1e-9;
// A ray within this relative distance of grazing (sphere discriminant against
// b^2, box slab overlap against the entry parameter, hit parameter against near
// or far) is on the boundary: the two sides' rounding (about 1e-15 relative) may
// put it either way. 1e-9 is wide enough for that and so thin that a random
// pixel centre lands in it with probability about 1e-9.
constexpr double kGrazingBand = 1e-9;
// A ray whose smallest barycentric coordinate on a triangle is within this of 0
// passes through the triangle's edge: the buffer decides it by its fill rule in
// screen space, with rounding of about 1e-16 * (pixel coordinate)^2 / (projected
// area): at worst about 1e-8 here (coordinates up to ~1e4 px for vertices
// projected from near the near plane, areas >= ~1 px^2 for any triangle that
// holds a centre), usually far less. Exact edge hits are tested on purpose in
// IdDepthBufferMesh.SharedEdge* with exactly representable coordinates.
constexpr double kEdgeBand = 1e-7;

struct TestShape {
    enum class Kind { Sphere, Box, Mesh };
    Kind kind = Kind::Sphere;
    glm::dvec3 center{0.0};  // Sphere
    double radius = 0.0;     // Sphere
    Aabb box;                // Box
    std::shared_ptr<const TriangleMesh> mesh;
    glm::dvec3 offset{0.0};  // Mesh: world position = vertex + offset
};

inline TestShape sphereShape(const glm::dvec3& center, double radius) {
    TestShape s;
    s.kind = TestShape::Kind::Sphere;
    s.center = center;
    s.radius = radius;
    return s;
}
inline TestShape boxShape(const glm::dvec3& min, const glm::dvec3& max) {
    TestShape s;
    s.kind = TestShape::Kind::Box;
    s.box = Aabb{min, max};
    return s;
}
inline TestShape meshShape(std::shared_ptr<const TriangleMesh> mesh, const glm::dvec3& offset) {
    TestShape s;
    s.kind = TestShape::Kind::Mesh;
    s.mesh = std::move(mesh);
    s.offset = offset;
    return s;
}

// The surface of the box [-half, half] as 12 triangles (closed, or open to see
// that an open surface has no solid inside). Vertex i takes max.x for bit 0,
// max.y for bit 1, max.z for bit 2; each face is split along one diagonal.
inline std::shared_ptr<TriangleMesh> boxSurfaceMesh(const glm::dvec3& half, bool closed = true) {
    std::vector<glm::dvec3> v;
    for (int i = 0; i < 8; ++i)
        v.push_back(
            {(i & 1) ? half.x : -half.x, (i & 2) ? half.y : -half.y, (i & 4) ? half.z : -half.z});
    return finishMesh(v, {0, 4, 6, 0, 6, 2,   // x = -half.x
                          1, 3, 7, 1, 7, 5,   // x = +half.x
                          0, 1, 5, 0, 5, 4,   // y = -half.y
                          2, 6, 7, 2, 7, 3,   // y = +half.y
                          0, 2, 3, 0, 3, 1,   // z = -half.z
                          4, 5, 7, 4, 7, 6},  // z = +half.z
                      closed);
}

// The closed tetrahedron on four points (every edge in exactly two faces).
inline std::shared_ptr<TriangleMesh> tetrahedronOn(const glm::dvec3& a, const glm::dvec3& b,
                                                   const glm::dvec3& c, const glm::dvec3& d) {
    return finishMesh({a, b, c, d}, {0, 1, 2, 0, 1, 3, 0, 2, 3, 1, 2, 3}, true);
}

// One open triangle.
inline std::shared_ptr<TriangleMesh> triangleOn(const glm::dvec3& a, const glm::dvec3& b,
                                                const glm::dvec3& c) {
    return finishMesh({a, b, c}, {0, 1, 2}, false);
}

// The world point at view-space (x, y, z) of `camera` (x right, y up, z forward).
inline glm::dvec3 atView(const Camera& camera, double x, double y, double z) {
    glm::dvec3 right, up, forward;
    camera.basis(right, up, forward);
    return camera.position + x * right + y * up + z * forward;
}

// What one pixel's ray sees of one shape.
struct RefHit {
    bool hit = false;
    double depth = std::numeric_limits<double>::infinity();
    bool boundary = false;  // grazing: either answer is right
};

// The documented pixel-centre rays of a camera and an image size.
struct PixelRays {
    PixelRays(const Camera& camera, int width, int height)
        : eye(camera.position), near(camera.near), far(camera.far), width(width), height(height) {
        camera.basis(right, up, forward);
        tan_y = std::tan(glm::radians(camera.fov_deg) / 2.0);
        tan_x = tan_y * camera.aspect;
    }
    glm::dvec3 dir(int px, int py) const {
        const double u = (2.0 * (px + 0.5) / width - 1.0) * tan_x;
        const double v = (1.0 - 2.0 * (py + 0.5) / height) * tan_y;
        return forward + u * right + v * up;
    }
    glm::dvec3 eye, right, up, forward;
    double tan_x = 1.0, tan_y = 1.0, near, far;
    int width, height;
};

// A solid met by the line over [s0, s1] (eye outside it): the first point at
// depth >= near, if that is not beyond far.
inline RefHit enterSolid(double s0, double s1, double near, double far) {
    RefHit r;
    const double entry = std::max(s0, near);
    r.hit = s1 >= near && entry <= far;
    if (r.hit) r.depth = entry;
    r.boundary =
        std::abs(s1 - near) <= kGrazingBand * near || std::abs(entry - far) <= kGrazingBand * far;
    return r;
}

inline RefHit refSphere(const PixelRays& rays, const glm::dvec3& d, const glm::dvec3& center,
                        double radius) {
    // |m + s d|^2 = r^2 with m = eye - center:  A s^2 + 2 B s + C = 0.
    const glm::dvec3 m = rays.eye - center;
    const double a = glm::dot(d, d), b = glm::dot(d, m), c = glm::dot(m, m) - radius * radius;
    if (c <= 0.0) {  // the eye is inside: every ray meets the solid at once
        RefHit r;
        r.hit = true;
        r.depth = rays.near;
        r.boundary = -c <= kGrazingBand * radius * radius;
        return r;
    }
    const double disc = b * b - a * c;
    const bool grazing = std::abs(disc) <= kGrazingBand * b * b;
    if (disc < 0.0) {
        RefHit r;
        r.boundary = grazing;
        return r;
    }
    const double root = std::sqrt(disc);
    RefHit r = enterSolid((-b - root) / a, (-b + root) / a, rays.near, rays.far);
    r.boundary = r.boundary || grazing;
    return r;
}

inline RefHit refBox(const PixelRays& rays, const glm::dvec3& d, const Aabb& box) {
    RefHit miss;
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        const double e = rays.eye[axis];
        if (d[axis] == 0.0) {  // parallel to the slab: inside it for every s, or never
            if (e < box.min[axis] || e > box.max[axis]) return miss;
            continue;
        }
        const double t_min = (box.min[axis] - e) / d[axis];
        const double t_max = (box.max[axis] - e) / d[axis];
        lo = std::max(lo, std::min(t_min, t_max));
        hi = std::min(hi, std::max(t_min, t_max));
    }
    const bool grazing = std::abs(hi - lo) <= kGrazingBand * std::max(std::abs(lo), std::abs(hi));
    if (lo > hi) {
        miss.boundary = grazing;
        return miss;
    }
    RefHit r;
    if (lo <= 0.0 && hi >= 0.0) {  // the eye is inside
        r.hit = true;
        r.depth = rays.near;
    } else {
        r = enterSolid(lo, hi, rays.near, rays.far);
    }
    r.boundary = r.boundary || grazing;
    return r;
}

// The line eye + s d against triangle (a, b, c), two-sided: the barycentric
// coordinates of its crossing are the signed volumes d . (eb x ec) etc. over
// their sum d . n, and s comes from the plane n . (p - a) = 0.
struct TriangleCrossing {
    bool hit = false;
    bool edge = false;  // within kEdgeBand of an edge, or nearly parallel
    double s = 0.0;
};
inline TriangleCrossing refTriangle(const glm::dvec3& eye, const glm::dvec3& d, const glm::dvec3& a,
                                    const glm::dvec3& b, const glm::dvec3& c) {
    TriangleCrossing x;
    const glm::dvec3 ea = a - eye, eb = b - eye, ec = c - eye;
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double wa = glm::dot(d, glm::cross(eb, ec));
    const double wb = glm::dot(d, glm::cross(ec, ea));
    const double wc = glm::dot(d, glm::cross(ea, eb));
    const double sum = wa + wb + wc;
    if (std::abs(sum) <= kEdgeBand * glm::length(d) * glm::length(n)) {
        x.edge = true;  // seen edge-on: covers no pixel centre, up to rounding
        return x;
    }
    const double margin = std::min({wa / sum, wb / sum, wc / sum});
    x.edge = std::abs(margin) <= kEdgeBand;
    x.hit = margin >= 0.0;
    x.s = glm::dot(n, ea) / sum;
    return x;
}

inline RefHit refMesh(const PixelRays& rays, const glm::dvec3& d, const TriangleMesh& mesh,
                      const glm::dvec3& offset) {
    RefHit r;
    int crossings = 0;  // at s >= near, for the parity of a closed mesh
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const TriangleCrossing x = refTriangle(rays.eye, d, mesh.vertices[mesh.indices[i]] + offset,
                                               mesh.vertices[mesh.indices[i + 1]] + offset,
                                               mesh.vertices[mesh.indices[i + 2]] + offset);
        if (x.edge) r.boundary = true;
        if (!x.hit) continue;
        if (std::abs(x.s - rays.near) <= kGrazingBand * rays.near ||
            std::abs(x.s - rays.far) <= kGrazingBand * rays.far)
            r.boundary = true;
        if (x.s < rays.near) continue;
        ++crossings;
        if (x.s <= rays.far) r.depth = std::min(r.depth, x.s);
    }
    if (mesh.closed && crossings % 2 == 1) r.depth = rays.near;  // the near-plane point is inside
    r.hit = r.depth <= rays.far;
    if (!r.hit) r.depth = std::numeric_limits<double>::infinity();
    return r;
}

inline RefHit refShape(const PixelRays& rays, int px, int py, const TestShape& shape) {
    const glm::dvec3 d = rays.dir(px, py);
    switch (shape.kind) {
        case TestShape::Kind::Sphere:
            return refSphere(rays, d, shape.center, shape.radius);
        case TestShape::Kind::Box:
            return refBox(rays, d, shape.box);
        case TestShape::Kind::Mesh:
            return refMesh(rays, d, *shape.mesh, shape.offset);
    }
    return {};
}

// The reference image of one shape, row-major.
inline std::vector<RefHit> referenceImage(const Camera& camera, int width, int height,
                                          const TestShape& shape) {
    const PixelRays rays(camera, width, height);
    std::vector<RefHit> image;
    for (int py = 0; py < height; ++py)
        for (int px = 0; px < width; ++px) image.push_back(refShape(rays, px, py, shape));
    return image;
}

inline bool drawShape(IdDepthBuffer& buffer, int index, const TestShape& shape) {
    switch (shape.kind) {
        case TestShape::Kind::Sphere:
            return buffer.drawSphere(index, shape.center, shape.radius);
        case TestShape::Kind::Box:
            return buffer.drawBox(index, shape.box);
        case TestShape::Kind::Mesh:
            return buffer.drawMesh(index, *shape.mesh, shape.offset);
    }
    return false;
}

inline std::vector<double> depthImage(const IdDepthBuffer& buffer) {
    std::vector<double> image;
    for (int py = 0; py < buffer.height(); ++py)
        image.insert(image.end(), buffer.depthRow(py), buffer.depthRow(py) + buffer.width());
    return image;
}

// The buffer's depths with `shape` drawn alone (+infinity where it is not);
// `accepted` gets the draw call's result (false: rejected as a whole).
inline std::vector<double> drawnAlone(const Camera& camera, int width, int height,
                                      const TestShape& shape, bool* accepted = nullptr) {
    IdDepthBuffer buffer;
    buffer.resize(width, height);
    buffer.begin(camera);
    const bool drawn = drawShape(buffer, 0, shape);
    if (accepted) *accepted = drawn;
    return depthImage(buffer);
}

inline bool depthsAgree(double a, double b) {
    return std::abs(a - b) <= kDepthTolerance * std::max(std::abs(a), std::abs(b));
}

// Pixel counts of one comparison; `covered` counts reference hits compared.
struct PixelTally {
    int compared = 0, covered = 0, boundary = 0, wrong = 0;
    double worst_depth_error = 0.0;  // relative, over the pixels both cover
};

// Every pixel of `drawn` against the reference: covered iff the reference hits,
// and then at the reference depth. Boundary pixels are skipped. Reports the
// first few wrong pixels as failures named by `what`.
inline PixelTally expectPixelsMatch(const std::vector<double>& drawn,
                                    const std::vector<RefHit>& ref, int width,
                                    const std::string& what) {
    PixelTally tally;
    for (size_t p = 0; p < ref.size(); ++p) {
        if (ref[p].boundary) {
            ++tally.boundary;
            continue;
        }
        ++tally.compared;
        if (ref[p].hit) ++tally.covered;
        const bool covered = drawn[p] < std::numeric_limits<double>::infinity();
        if (covered && ref[p].hit) {
            tally.worst_depth_error =
                std::max(tally.worst_depth_error, std::abs(drawn[p] - ref[p].depth) / ref[p].depth);
        }
        if (covered == ref[p].hit && (!covered || depthsAgree(drawn[p], ref[p].depth))) continue;
        if (++tally.wrong <= 5) {
            ADD_FAILURE() << what << ": pixel (" << int(p) % width << ", " << int(p) / width
                          << ") drawn "
                          << (covered ? "at depth " + std::to_string(drawn[p]) : "empty")
                          << ", reference "
                          << (ref[p].hit ? "hit at depth " + std::to_string(ref[p].depth) : "miss");
        }
    }
    return tally;
}

// One shape drawn alone against its reference image; a draw call that rejects
// the shape as a whole must leave every pixel to the reference's misses.
inline PixelTally expectShapeMatches(const Camera& camera, int width, int height,
                                     const TestShape& shape, const std::string& what) {
    bool accepted = false;
    const std::vector<double> drawn = drawnAlone(camera, width, height, shape, &accepted);
    const PixelTally tally =
        expectPixelsMatch(drawn, referenceImage(camera, width, height, shape), width, what);
    if (tally.covered > 0) {
        EXPECT_TRUE(accepted) << what << ": rejected but seen";
    }
    return tally;
}

// The whole list drawn into one buffer in `order` (shape indices): per pixel the
// nearest reference depth, and the visible set between the pixels' unique
// winners (required) and every shape that may win some pixel (tied within
// kDepthTolerance, or on a boundary there). Returns the pixels compared.
inline int expectSceneMatches(const Camera& camera, int width, int height,
                              const std::vector<TestShape>& shapes, const std::vector<int>& order,
                              const std::string& what) {
    std::vector<std::vector<RefHit>> refs;
    for (const TestShape& s : shapes) refs.push_back(referenceImage(camera, width, height, s));
    IdDepthBuffer buffer;
    buffer.resize(width, height);
    buffer.begin(camera);
    for (int k : order) drawShape(buffer, k, shapes[size_t(k)]);
    const std::vector<double> drawn = depthImage(buffer);
    std::vector<char> seen(shapes.size(), 0);
    buffer.markVisible(seen);

    std::set<int> required, allowed;
    int compared = 0, wrong = 0;
    for (size_t p = 0; p < drawn.size(); ++p) {
        double best = std::numeric_limits<double>::infinity();
        bool boundary = false;
        for (const auto& ref : refs) {
            boundary = boundary || ref[p].boundary;
            if (ref[p].hit) best = std::min(best, ref[p].depth);
        }
        std::vector<int> winners;
        for (size_t k = 0; k < refs.size(); ++k) {
            const RefHit& r = refs[k][p];
            if (r.boundary || (r.hit && (r.depth == best || depthsAgree(r.depth, best))))
                winners.push_back(int(k));
        }
        allowed.insert(winners.begin(), winners.end());
        if (boundary) continue;
        if (winners.size() == 1) required.insert(winners.front());
        ++compared;
        const bool ok = best == std::numeric_limits<double>::infinity()
                            ? drawn[p] == best
                            : depthsAgree(drawn[p], best);
        if (!ok && ++wrong <= 5) {
            ADD_FAILURE() << what << ": pixel (" << int(p) % width << ", " << int(p) / width
                          << ") depth " << drawn[p] << ", nearest reference " << best;
        }
    }
    for (size_t k = 0; k < shapes.size(); ++k) {
        if (required.count(int(k))) {
            EXPECT_TRUE(seen[k]) << what << ": shape " << k << " lost";
        }
        if (!allowed.count(int(k))) {
            EXPECT_FALSE(seen[k]) << what << ": shape " << k << " hidden";
        }
    }
    return compared;
}

}  // namespace gridcull::test
