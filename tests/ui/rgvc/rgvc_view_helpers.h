// What the rgvc window tests share: an rgvc session on a scene file at a
// frame, and readings of the debug-draw batch (which voxels the triangles of
// one swatch cover, per plane).
#pragma once
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"
#include "culling/rgvc/rgvc_snapshot.h"
#include "ui/debug_draw.h"
#include "ui/debugger_session.h"

namespace gridcull::test {

// Opens `file` (under scenes/) with rgvc and runs it to `frame`.
inline void openRgvc(DebuggerSession& session, const char* file, int frame) {
    SceneLoadResult loaded = loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/" + file);
    ASSERT_TRUE(loaded.scene) << file;
    std::string error;
    ASSERT_TRUE(session.open(std::move(*loaded.scene), "", "rgvc", error)) << error;
    session.seek(frame);
    ASSERT_NE(session.debugSnapshot(), nullptr);
    ASSERT_NE(session.debugSnapshot()->as<RgvcSnapshot>(), nullptr);
}

inline bool sameColor(const glm::vec4& c, Swatch swatch) {
    const Rgb rgb = swatchColor(swatch);
    return std::abs(c.r - rgb.r) < 1e-4f && std::abs(c.g - rgb.g) < 1e-4f &&
           std::abs(c.b - rgb.b) < 1e-4f;
}

using VoxelSet = std::set<std::tuple<int, int, int>>;

// The voxels of `grid` whose centre on the plane `axis` = `plane` (world)
// lies inside a World triangle of `swatch` lying on that plane. 2D:
// axis 2, plane 0, the voxels' z is 0.
inline VoxelSet coveredVoxels(const DebugDrawBatch& batch, Swatch swatch, const RegularGrid& grid,
                              int axis, double plane, int index) {
    VoxelSet out;
    const auto& fill = batch.layer(DrawSpace::World).fill;
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    const glm::dvec3 d = grid.voxelSize();
    for (size_t k = 0; k + 2 < fill.size(); k += 3) {
        if (!sameColor(fill[k].color, swatch)) continue;
        glm::dvec3 p[3];
        bool on_plane = true;
        for (int i = 0; i < 3; ++i) {
            p[i] = glm::dvec3(fill[k + size_t(i)].position);
            on_plane = on_plane && std::abs(p[i][axis] - plane) < 1e-3;
        }
        if (!on_plane) continue;
        // Voxel centres in the triangle's bounding box, tested by edge signs.
        const double lo_b = std::min({p[0][b], p[1][b], p[2][b]}),
                     hi_b = std::max({p[0][b], p[1][b], p[2][b]});
        const double lo_c = std::min({p[0][c], p[1][c], p[2][c]}),
                     hi_c = std::max({p[0][c], p[1][c], p[2][c]});
        const int i0 = std::max(0, int(std::floor((lo_b - grid.world.min[b]) / d[b] - 0.5)));
        const int i1 = std::min(grid.resolution[b] - 1,
                                int(std::ceil((hi_b - grid.world.min[b]) / d[b] - 0.5)));
        const int j0 = std::max(0, int(std::floor((lo_c - grid.world.min[c]) / d[c] - 0.5)));
        const int j1 = std::min(grid.resolution[c] - 1,
                                int(std::ceil((hi_c - grid.world.min[c]) / d[c] - 0.5)));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const double u = grid.world.min[b] + (i + 0.5) * d[b];
                const double w = grid.world.min[c] + (j + 0.5) * d[c];
                double s[3];
                for (int e = 0; e < 3; ++e) {
                    const glm::dvec3& a = p[e];
                    const glm::dvec3& n = p[(e + 1) % 3];
                    s[e] = (n[b] - a[b]) * (w - a[c]) - (n[c] - a[c]) * (u - a[b]);
                }
                // Closed: a centre on the diagonal the two triangles of a
                // square share belongs to both (voxel boundaries hold none).
                const bool inside =
                    (s[0] >= 0 && s[1] >= 0 && s[2] >= 0) || (s[0] <= 0 && s[1] <= 0 && s[2] <= 0);
                if (!inside) continue;
                glm::ivec3 v;
                v[axis] = index;
                v[b] = i;
                v[c] = j;
                out.insert({v.x, v.y, v.z});
            }
    }
    return out;
}

}  // namespace gridcull::test
