#include "culling/oracle/pair_cover.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "culling/scene/ray_intersect.h"

namespace gridcull {

namespace {

constexpr double kOpen = std::numeric_limits<double>::infinity();

// A convex polygon of at most kMax corners: a pixel square cut by up to
// Silhouette::kMaxCorners half-planes gains at most one corner per cut.
struct Polygon {
    static constexpr int kMax = 4 + Silhouette::kMaxCorners;
    glm::dvec2 corner[kMax];
    int count = 0;
};

double cross(const glm::dvec2& a, const glm::dvec2& b) {
    return a.x * b.y - a.y * b.x;
}

// Which side of the line from p to q a point lies: > 0 on the left (inside a
// counter-clockwise polygon).
double side(const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& point) {
    return cross(q - p, point - p);
}

// The part of `in` where sign * side(p, q, .) >= 0.
Polygon clip(const Polygon& in, const glm::dvec2& p, const glm::dvec2& q, double sign) {
    Polygon out;
    for (int i = 0; i < in.count; ++i) {
        const glm::dvec2& a = in.corner[i];
        const glm::dvec2& b = in.corner[(i + 1) % in.count];
        const double sa = sign * side(p, q, a), sb = sign * side(p, q, b);
        if (sa >= 0.0) out.corner[out.count++] = a;
        if ((sa >= 0.0) != (sb >= 0.0)) out.corner[out.count++] = a + (b - a) * (sa / (sa - sb));
    }
    return out;
}

Polygon pixelSquare(int px, int py) {
    Polygon square;
    square.count = 4;
    square.corner[0] = {px, py};
    square.corner[1] = {px + 1, py};
    square.corner[2] = {px + 1, py + 1};
    square.corner[3] = {px, py + 1};
    return square;
}

// Whether the ray through (x, y) meets the solid, and where it enters.
bool entry(const PixelView& view, const CoverSolid& solid, const glm::dvec2& at, double& depth) {
    const glm::dvec3 dir = view.ray(at.x, at.y);
    double s0, s1;
    const bool line = solid.sphere ? lineSphere(view.eye, dir, solid.center, solid.radius, s0, s1)
                                   : lineBox(view.eye, dir, solid.box, s0, s1);
    return line && solidEntry(s0, s1, view.near, view.far, depth);
}

// The solid's greatest depth anywhere: that of its bounding box's farthest corner.
double greatestDepth(const PixelView& view, const CoverSolid& solid) {
    double greatest = 0.0;
    for (int c = 0; c < 8; ++c) greatest = std::max(greatest, view.toView(solid.box.corner(c)).z);
    return greatest;
}

bool insideOutline(const Silhouette& outline, const glm::dvec2& point) {
    for (int i = 0; i < outline.count; ++i) {
        const glm::dvec2& p = outline.corner[i];
        const glm::dvec2& q = outline.corner[(i + 1) % outline.count];
        // Signed distance to the edge's line, in pixels.
        if (side(p, q, point) < -kSeam * glm::length(q - p)) return false;
    }
    return true;
}

}  // namespace

Silhouette boxSilhouette(const PixelView& view, const Aabb& box) {
    glm::dvec3 corners[8];
    for (int c = 0; c < 8; ++c) corners[c] = view.toView(box.corner(c));
    // The box cut to depth >= near: its corners there and where its edges cross
    // the near plane.
    glm::dvec2 points[8 + 12];
    int count = 0;
    auto add = [&](const glm::dvec3& p) {
        points[count++] = {view.columnOf(p), view.rowOf(p)};
    };
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3& a = corners[c];
        if (a.z >= view.near) add(a);
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (c & bit) continue;
            const glm::dvec3& b = corners[c | bit];
            if ((a.z >= view.near) == (b.z >= view.near)) continue;
            glm::dvec3 cut = a + (b - a) * ((view.near - a.z) / (b.z - a.z));
            cut.z = view.near;
            add(cut);
        }
    }
    // Their hull, by Andrew's monotone chain.
    std::sort(points, points + count, [](const glm::dvec2& p, const glm::dvec2& q) {
        return p.x < q.x || (p.x == q.x && p.y < q.y);
    });
    Silhouette hull;
    glm::dvec2 chain[2 * (8 + 12)];
    int k = 0;
    for (int i = 0; i < count; ++i) {
        while (k >= 2 && side(chain[k - 2], chain[k - 1], points[i]) <= 0.0) --k;
        chain[k++] = points[i];
    }
    for (int i = count - 2, lower = k + 1; i >= 0; --i) {
        while (k >= lower && side(chain[k - 2], chain[k - 1], points[i]) <= 0.0) --k;
        chain[k++] = points[i];
    }
    hull.count = std::min(std::max(k - 1, 0), Silhouette::kMaxCorners);
    for (int i = 0; i < hull.count; ++i) hull.corner[i] = chain[i];
    if (k - 1 > Silhouette::kMaxCorners) hull.count = 0;  // cannot happen: a box shows 6 sides at most
    return hull;
}

bool outlineMeetsPixel(const Silhouette& outline, int px, int py) {
    double x_lo = outline.corner[0].x, x_hi = x_lo, y_lo = outline.corner[0].y, y_hi = y_lo;
    for (int i = 1; i < outline.count; ++i) {
        x_lo = std::min(x_lo, outline.corner[i].x);
        x_hi = std::max(x_hi, outline.corner[i].x);
        y_lo = std::min(y_lo, outline.corner[i].y);
        y_hi = std::max(y_hi, outline.corner[i].y);
    }
    if (x_hi < px - kSeam || x_lo > px + 1 + kSeam || y_hi < py - kSeam || y_lo > py + 1 + kSeam)
        return false;
    const glm::dvec2 square[4] = {{px, py}, {px + 1, py}, {px + 1, py + 1}, {px, py + 1}};
    for (int i = 0; i < outline.count; ++i) {
        const glm::dvec2& p = outline.corner[i];
        const glm::dvec2& q = outline.corner[(i + 1) % outline.count];
        const double margin = -kSeam * glm::length(q - p);
        bool all_outside = true;
        for (const glm::dvec2& corner : square) all_outside = all_outside && side(p, q, corner) < margin;
        if (all_outside) return false;
    }
    return true;
}

double pairCoverDepth(const PixelView& view, int px, int py, const CoverSolid& a,
                      const Silhouette& a_outline, const CoverSolid& b,
                      const Silhouette& b_outline) {
    if (a_outline.count < 3 || (!b.sphere && b_outline.count < 3)) return kOpen;
    const Polygon square = pixelSquare(px, py);
    double deepest = 0.0;

    // A's part of the square, and A's depth at its corners.
    Polygon inside_a = square;
    for (int i = 0; i < a_outline.count && inside_a.count > 0; ++i)
        inside_a = clip(inside_a, a_outline.corner[i], a_outline.corner[(i + 1) % a_outline.count], 1.0);
    if (inside_a.count == 0) return kOpen;
    const double a_greatest = greatestDepth(view, a);
    for (int i = 0; i < inside_a.count; ++i) {
        double depth;
        deepest = std::max(deepest, entry(view, a, inside_a.corner[i], depth) ? depth : a_greatest);
    }

    // The pieces outside each edge of A, which B must hold.
    const double b_greatest = greatestDepth(view, b);
    for (int i = 0; i < a_outline.count; ++i) {
        const Polygon piece =
            clip(square, a_outline.corner[i], a_outline.corner[(i + 1) % a_outline.count], -1.0);
        for (int j = 0; j < piece.count; ++j) {
            double depth;
            const bool hit = entry(view, b, piece.corner[j], depth);
            if (b.sphere ? !hit : !insideOutline(b_outline, piece.corner[j])) return kOpen;
            deepest = std::max(deepest, hit ? depth : b_greatest);
        }
    }
    // Rounding in the rays' depths.
    return deepest + 1e-9 * deepest;
}

}  // namespace gridcull
