// A box's twelve edges as World-space lines, for the 3D rgvc overlay's
// highlights (the seed voxel, the shell, a picked voxel).
#pragma once
#include <glm/vec3.hpp>

#include "ui/debug_draw.h"

namespace gridcull {

inline void drawRgvcWireBox(DebugDraw& draw, const glm::dvec3& lo, const glm::dvec3& hi,
                            Paint paint, float width) {
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (int k = 0; k < 4; ++k) {
            glm::dvec3 p = lo, q;
            p[b] = (k & 1) ? hi[b] : lo[b];
            p[c] = (k & 2) ? hi[c] : lo[c];
            q = p;
            q[a] = hi[a];
            draw.line(DrawSpace::World, p, q, paint, width);
        }
    }
}

}  // namespace gridcull
