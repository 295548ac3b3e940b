#include "ui/rgvc/rgvc_hovered_voxel.h"

namespace gridcull {

void drawRgvcHoveredVoxel(const RgvcSnapshot& snapshot, const glm::ivec3& voxel, DebugDraw& draw) {
    const RegularGrid& grid = snapshot.grid;
    const int axes = snapshot.dimensions == 3 ? 3 : 2;
    for (int a = 0; a < axes; ++a)
        if (voxel[a] < 0 || voxel[a] >= grid.resolution[a]) return;
    if (snapshot.dimensions == 3) {
        const Aabb box = grid.voxelBounds(voxel);
        draw.wireBox(box.min, box.max, kRgvcHoverPaint, kRgvcHoverWidth);
        return;
    }
    const glm::dvec3 d = grid.voxelSize();
    const double x0 = grid.world.min.x + voxel.x * d.x, y0 = grid.world.min.y + voxel.y * d.y;
    draw.outlineRect(DrawSpace::World, x0, y0, x0 + d.x, y0 + d.y, kRgvcHoverPaint,
                     kRgvcHoverWidth);
}

}  // namespace gridcull
