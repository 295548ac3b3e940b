#include "ui/legend_swatch.h"

namespace gridcull {

namespace {

ImU32 colorOf(Paint paint) {
    const Rgb c = swatchColor(paint.swatch);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, paint.alpha));
}

}  // namespace

SwatchDraw::SwatchDraw(float side, Rgb background)
    : list_(ImGui::GetWindowDrawList()), origin_(ImGui::GetCursorScreenPos()), side_(side) {
    ImGui::Dummy(ImVec2(side, side));
    list_->PushClipRect(origin_, ImVec2(origin_.x + side, origin_.y + side), true);
    list_->AddRectFilled(origin_, ImVec2(origin_.x + side, origin_.y + side),
                         ImGui::ColorConvertFloat4ToU32(
                             ImVec4(background.r, background.g, background.b, 1.0f)));
    list_->PopClipRect();
    // A hairline frame just outside the square, so a dark key (O's near
    // black) still shows where it is on the dark panel.
    const Rgb frame = swatchColor(Swatch::LineGrey);
    list_->AddRect(ImVec2(origin_.x - 1.0f, origin_.y - 1.0f),
                   ImVec2(origin_.x + side + 1.0f, origin_.y + side + 1.0f),
                   ImGui::ColorConvertFloat4ToU32(ImVec4(frame.r, frame.g, frame.b, 1.0f)));
}

void SwatchDraw::triangle(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b,
                          const glm::dvec3& c, Paint paint) {
    if (space != DrawSpace::View) return;
    list_->PushClipRect(origin_, ImVec2(origin_.x + side_, origin_.y + side_), true);
    // Without ImGui's anti-aliased fringe, which would double along the seam
    // of a rectangle's two translucent triangles (the GL overlay has none).
    const ImDrawListFlags flags = list_->Flags;
    list_->Flags &= ~ImDrawListFlags_AntiAliasedFill;
    list_->AddTriangleFilled(at(a), at(b), at(c), colorOf(paint));
    list_->Flags = flags;
    list_->PopClipRect();
}

void SwatchDraw::line(DrawSpace space, const glm::dvec3& a, const glm::dvec3& b, Paint paint,
                      float width) {
    if (space != DrawSpace::View) return;
    list_->PushClipRect(origin_, ImVec2(origin_.x + side_, origin_.y + side_), true);
    list_->AddLine(at(a), at(b), colorOf(paint), width);
    list_->PopClipRect();
}

void paintSwatch(float side, Rgb background, Paint paint) {
    SwatchDraw draw(side, background);
    draw.fillRect(draw.rect(), paint);
}

}  // namespace gridcull
