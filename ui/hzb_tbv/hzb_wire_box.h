// An axis-aligned box's twelve edges as World-space lines: how the hzb overlay
// draws TBVs and octree nodes (ui/hzb_tbv/hzb_tbv_overlay.h).
#pragma once
#include <glm/vec3.hpp>

#include "grid/aabb.h"
#include "ui/debug_draw.h"

namespace gridcull {

inline void drawHzbWireBox(DebugDraw& draw, const Aabb& box, Paint paint, float width) {
    const glm::dvec3& lo = box.min;
    const glm::dvec3& hi = box.max;
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (int k = 0; k < 4; ++k) {
            glm::dvec3 p = lo;
            p[b] = (k & 1) ? hi[b] : lo[b];
            p[c] = (k & 2) ? hi[c] : lo[c];
            glm::dvec3 q = p;
            q[a] = hi[a];
            draw.line(DrawSpace::World, p, q, paint, width);
        }
    }
}

}  // namespace gridcull
