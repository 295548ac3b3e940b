// A legend's swatch drawn by the overlay's own code: a small square of the
// panel, filled with what the overlay is drawn over (the view's background,
// or the 2D world's fill), into which a family draws one of its things (a
// cell, a voxel) through the same DebugDraw calls its overlay makes, in View
// space with the square as the view. So the key shows each colour exactly as
// the overlay blends it, hatching and outlines included, and cannot drift
// from it. World-space primitives and text are not drawn: a key is flat.
#pragma once
#include <imgui.h>

#include "ui/debug_draw.h"
#include "ui/palette.h"

namespace gridcull {

class SwatchDraw final : public DebugDraw {
public:
    // Reserves a `side` x `side` pixel square at the ImGui cursor, on the
    // current line, filled with `background`.
    SwatchDraw(float side, Rgb background);
    // The square in its own View space: (0, 0) to (side, side).
    ViewRect rect() const { return {0.0, 0.0, double(side_), double(side_)}; }

    void triangle(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                  Paint paint) override;
    void line(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, Paint paint,
              float width) override;
    void text(DrawSpace, const glm::dvec3&, const char*, Paint, float) override {}

private:
    ImVec2 at(const glm::dvec3& p) const {
        return ImVec2(origin_.x + float(p.x), origin_.y + float(p.y));
    }
    ImDrawList* list_ = nullptr;
    ImVec2 origin_;
    float side_ = 0.0f;
};

// A square of the legend filled with one paint over `background`, as an
// overlay's fill of that paint shows over it.
void paintSwatch(float side, Rgb background, Paint paint);

}  // namespace gridcull
