#include "ui/lazy_grid/lazy_grid_hovered_cell.h"

#include <cmath>

#include <glm/vec4.hpp>

#include "ui/lazy_grid/lazy_grid_overlay.h"

namespace gridcull {

bool lazyCellUnderPointer(const LazyGridSnapshot& snapshot, const OverlayView& view,
                          const glm::dvec3& origin, const glm::dvec3& direction, int& cx, int& cy) {
    if (!view.through_culling_camera || !snapshot.valid || snapshot.cell_size <= 0) return false;
    // Every point of a ray from the eye projects to the pixel it was cast
    // through; one unit along it is in front of the eye.
    const glm::dvec4 clip = view.view_projection * glm::dvec4(origin + direction, 1.0);
    if (!(clip.w > 0.0)) return false;
    const glm::dvec2 at((clip.x / clip.w + 1.0) * 0.5 * view.width,
                        (1.0 - clip.y / clip.w) * 0.5 * view.height);
    const glm::dvec2 p = view.cullingImage(snapshot.width, snapshot.height).toImage(at);
    if (!(p.x >= 0.0 && p.y >= 0.0 && p.x < snapshot.width && p.y < snapshot.height)) return false;
    cx = int(std::floor(p.x)) / snapshot.cell_size;
    cy = int(std::floor(p.y)) / snapshot.cell_size;
    return cx < snapshot.cells_x && cy < snapshot.cells_y;
}

void drawLazyHoveredCell(const LazyGridSnapshot& snapshot, const ImageFrame& frame, int cx, int cy,
                         DebugDraw& draw) {
    draw.outlineRect(lazyCellInView(frame, snapshot, cx, cy), kLazyHoverPaint, kLazyHoverWidth);
}

}  // namespace gridcull
