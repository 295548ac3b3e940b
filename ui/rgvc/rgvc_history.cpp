#include "ui/rgvc/rgvc_history.h"

namespace gridcull {

bool rgvcHAt(const RgvcSnapshot& s, int x, int y, int z, int64_t layer) {
    if (!s.occlusion || !s.occlusion->get(x, y + z * s.grid.resolution.y)) return false;
    const size_t v = rgvcLinear(s.grid, x, y, z);
    return v < s.h_layer.size() && s.h_layer[v] <= layer;
}

bool rgvcOAt(const RgvcSnapshot& s, int x, int y, int z, int64_t layer) {
    if (!s.occluder || !s.occluder->get(x, y + z * s.grid.resolution.y)) return false;
    const size_t v = rgvcLinear(s.grid, x, y, z);
    // No layer: opaque before the traversal started.
    return v >= s.o_layer.size() || s.o_layer[v] == kRgvcNoLayer || s.o_layer[v] <= layer;
}

bool rgvcOsAt(const RgvcSnapshot& s, int x, int y, int z) {
    return s.static_occluder && s.static_occluder->get(x, y + z * s.grid.resolution.y);
}

int32_t rgvcRevealLayerOf(const RgvcSnapshot& s, int index) {
    for (const RgvcRevealView& r : s.reveals)
        if (r.tbv.object_index == index) return r.layer;
    return kRgvcNoLayer;
}

bool rgvcTbvFormHolds(const RgvcSnapshot& s, const RgvcTbvView& tbv, int x, int y, int z) {
    if (tbv.edge) return false;
    if (s.dimensions == 3) {
        const glm::i64vec3 v(x, y, z);
        return tbv.filled ? tbv.cells.contains(v) : onTbvBoxSurface(tbv.cells, v);
    }
    bool found = false;
    rgvcForEachTbvVoxel(s, tbv,
                        [&](int vx, int vy, int) { found = found || (vx == x && vy == y); });
    return found;
}

}  // namespace gridcull
