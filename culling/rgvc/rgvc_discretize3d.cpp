// Scene discretization of regular-grid culling in 3D (Batagelo & Wu, section
// 5.1): opaque voxels (O, Os) only from a simplified model wholly inside the
// object, spanned voxels (I) from one wholly containing it. A sphere and a box
// are their own models, tested exactly per row of voxels; a mesh spans its
// bounding box and is opaque only inside its interior boxes
// (culling/scene/mesh_interior.h: none for an open mesh), each voxel wholly
// inside one box. Polygons do not exist in 3D scenes (the loader rejects them);
// one that slips through spans its bounds and makes nothing opaque.
#include <algorithm>
#include <cmath>

#include "culling/rgvc/rgvc_culler.h"

namespace gridcull {

namespace {

// Leans every decision the conservative way by this many voxel widths: touched
// ranges grow, inside ranges shrink.
constexpr double kDiscretize3Slack = 1e-9;

struct VoxelAxes {
    glm::dvec3 origin;
    glm::dvec3 size;
    glm::ivec3 count;

    // Voxels along `a` whose closed extent meets [lo, hi].
    bool touching(int a, double lo, double hi, int& i0, int& i1) const {
        const double u0 = (lo - origin[a]) / size[a] - kDiscretize3Slack;
        const double u1 = (hi - origin[a]) / size[a] + kDiscretize3Slack;
        if (!(u0 <= u1)) return false;
        i0 = int(std::clamp(std::floor(u0), 0.0, double(count[a])));
        i1 = int(std::clamp(std::floor(u1), -1.0, double(count[a] - 1)));
        return i0 <= i1;
    }
    // Voxels along `a` lying wholly in [lo, hi]: the candidates from the
    // division, then each end checked with the voxel's own bounds (lower()), so
    // a voxel exactly on the object's face counts and none sticks out by a
    // rounding error.
    bool inside(int a, double lo, double hi, int& i0, int& i1) const {
        const double u0 = (lo - origin[a]) / size[a], u1 = (hi - origin[a]) / size[a];
        if (!(u0 < u1)) return false;
        double c0 = std::clamp(std::ceil(u0 - kDiscretize3Slack), 0.0, double(count[a]));
        double c1 =
            std::clamp(std::floor(u1 + kDiscretize3Slack) - 1.0, -1.0, double(count[a] - 1));
        if (c0 <= c1 && lower(a, int(c0)) < lo) c0 += 1.0;
        if (c0 <= c1 && lower(a, int(c1) + 1) > hi) c1 -= 1.0;
        i0 = int(c0);
        i1 = int(c1);
        return i0 <= i1;
    }
    double lower(int a, int i) const { return origin[a] + double(i) * size[a]; }
};

double gapTo(double c, double lo, double hi) {
    return c < lo ? lo - c : (c > hi ? c - hi : 0.0);
}

// Rows (y, z) with their x spans of the voxels a box touches or lies around.
template <typename Span>
void boxRows(const VoxelAxes& g, const Aabb& box, bool touched, Span&& span) {
    int x0, x1, y0, y1, z0, z1;
    auto range = [&](int a, int& i0, int& i1) {
        return touched ? g.touching(a, box.min[a], box.max[a], i0, i1)
                       : g.inside(a, box.min[a], box.max[a], i0, i1);
    };
    if (!range(0, x0, x1) || !range(1, y0, y1) || !range(2, z0, z1)) return;
    for (int z = z0; z <= z1; ++z)
        for (int y = y0; y <= y1; ++y) span(y, z, x0, x1);
}

template <typename Span>
void sphereRows(const VoxelAxes& g, const glm::dvec3& c, double r, bool touched, Span&& span) {
    int y0, y1, z0, z1;
    if (!g.touching(1, c.y - r, c.y + r, y0, y1) || !g.touching(2, c.z - r, c.z + r, z0, z1))
        return;
    const double rr = r * r;
    for (int z = z0; z <= z1; ++z) {
        const double za = g.lower(2, z), zb = za + g.size.z;
        for (int y = y0; y <= y1; ++y) {
            const double ya = g.lower(1, y), yb = ya + g.size.y;
            int x0, x1;
            if (touched) {
                // The row meets the ball where its nearest point in y-z does.
                const double dy = gapTo(c.y, ya, yb), dz = gapTo(c.z, za, zb);
                const double rest = rr - dy * dy - dz * dz;
                if (rest < 0.0) continue;
                const double half = std::sqrt(rest);
                if (g.touching(0, c.x - half, c.x + half, x0, x1)) span(y, z, x0, x1);
            } else {
                // A voxel lies in the ball when its corners do: the row's farthest
                // y-z corner bounds the x extent.
                const double fy = std::max(std::abs(ya - c.y), std::abs(yb - c.y));
                const double fz = std::max(std::abs(za - c.z), std::abs(zb - c.z));
                const double rest = rr - fy * fy - fz * fz;
                if (rest <= 0.0) continue;
                const double half = std::sqrt(rest);
                if (g.inside(0, c.x - half, c.x + half, x0, x1)) span(y, z, x0, x1);
            }
        }
    }
}

}  // namespace

void RgvcCuller::rasterize3d(const SceneObject& object, const glm::dvec3& shift, int index,
                             bool is_static, bool during_traversal) {
    IdListMatrix& ids = is_static ? identifiers_static_ : identifiers_dynamic_;
    BitMatrix& opaque = is_static ? static_occluder_ : occluder_;
    const VoxelAxes g{grid_.world.min, voxel_size_, grid_.resolution};
    BitMatrix& holds = is_static ? holds_static_ : holds_dynamic_;
    auto touched = [&](int y, int z, int x0, int x1) {
        const int row = ids.row(y, z);
        holds.setRun(row, x0, x1);
        for (int x = x0; x <= x1; ++x) {
            ids.add(x, row, int32_t(index));
            // The traversal has passed this voxel non-occluded and will not come
            // back: it would have found the object there.
            if (during_traversal && open_.get(x, row)) addToPvs(index);
        }
    };
    auto inside = [&](int y, int z, int x0, int x1) {
        const int row = opaque.row(y, z);
        if (during_traversal && snapshot_enabled_)
            for (int x = x0; x <= x1; ++x) noteOpaque(x, row);
        opaque.setRun(row, x0, x1);
    };
    switch (object.shape) {
        case ShapeKind::Sphere:
            sphereRows(g, object.center + shift, object.radius, true, touched);
            sphereRows(g, object.center + shift, object.radius, false, inside);
            return;
        case ShapeKind::Box:
            boxRows(g, object.box.translated(shift), true, touched);
            boxRows(g, object.box.translated(shift), false, inside);
            return;
        case ShapeKind::Mesh:
            boxRows(g, object.bounds.translated(shift), true, touched);
            if (const std::vector<Aabb>* boxes = inner_boxes_[size_t(index)])
                for (const Aabb& box : *boxes)
                    boxRows(g, box.translated(object.center + shift), false, inside);
            return;
        case ShapeKind::Polygon:
            boxRows(g, object.bounds.translated(shift), true, touched);
            return;
    }
}

}  // namespace gridcull
