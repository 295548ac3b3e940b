// The image cell under the pointer, outlined over the lazy grid's overlay when
// the view looks through the culling camera, so a cell can be read against the
// key (its state, whether a test touched it) without counting rows. White at
// kBoldLine on the cell's own rectangle, as the window outlines the object
// under the pointer (ui/palette.h); touched cells' outlines sit inset from
// theirs (ui/lazy_grid/lazy_grid_overlay.h), so both show.
#pragma once
#include <glm/vec3.hpp>

#include "culling/lazy_grid/lazy_grid_snapshot.h"
#include "ui/debug_draw.h"
#include "ui/family_view.h"
#include "ui/image_frame.h"

namespace gridcull {

constexpr Paint kLazyHoverPaint{Swatch::White, 1.0f};
constexpr float kLazyHoverWidth = kBoldLine;

// The cell (cx, cy) of the snapshot's image that the pointer's ray (World:
// `origin`, `direction`) goes through in `view`: a point of the ray projected
// to view pixels by view.view_projection, then to image pixels by the culling
// image's frame. False when the view does not look through the culling camera,
// the ray points away or it misses the image.
bool lazyCellUnderPointer(const LazyGridSnapshot& snapshot, const OverlayView& view,
                          const glm::dvec3& origin, const glm::dvec3& direction, int& cx, int& cy);

// Emits the outline of cell (cx, cy); `frame` is made for the snapshot's image.
void drawLazyHoveredCell(const LazyGridSnapshot& snapshot, const ImageFrame& frame, int cx, int cy,
                         DebugDraw& draw);

}  // namespace gridcull
