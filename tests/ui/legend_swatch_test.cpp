// Legend swatches (ui/legend_swatch.h) are drawn by the overlay's own calls: a
// rectangle filled through SwatchDraw lands in the square the panel reserved,
// with the paint's colour and opacity; World-space primitives are left out.
#include <gtest/gtest.h>
#include <imgui.h>

#include "ui/legend_swatch.h"

namespace gridcull {
namespace {

TEST(LegendSwatch, TheOverlaysCallsLandInTheSquareWithTheirPaint) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(200, 200);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::Begin("legend");
    ImDrawList* list = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const int before = list->VtxBuffer.Size;
    {
        SwatchDraw key(13.0f, worldFillColor());
        key.fillRect(key.rect(), Paint{Swatch::Orange, 0.4f});
        key.line(DrawSpace::World, {0, 0, 0}, {5, 5, 5}, Paint{}, 1.0f);
    }
    const Rgb orange = swatchColor(Swatch::Orange);
    const ImU32 want = ImGui::ColorConvertFloat4ToU32(ImVec4(orange.r, orange.g, orange.b, 0.4f));
    int orange_vertices = 0;
    for (int k = before; k < list->VtxBuffer.Size; ++k) {
        const ImDrawVert& v = list->VtxBuffer[k];
        if (v.col != want) continue;
        ++orange_vertices;
        EXPECT_GE(v.pos.x, origin.x - 1e-3f);
        EXPECT_LE(v.pos.x, origin.x + 13.0f + 1e-3f);
        EXPECT_GE(v.pos.y, origin.y - 1e-3f);
        EXPECT_LE(v.pos.y, origin.y + 13.0f + 1e-3f);
    }
    EXPECT_EQ(orange_vertices, 6) << "two triangles, no anti-aliased fringe";
    EXPECT_NEAR(ImGui::GetCursorScreenPos().y - origin.y,
                13.0f + ImGui::GetStyle().ItemSpacing.y, 1e-3f)
        << "the square is reserved in the layout";
    ImGui::End();
    ImGui::Render();
    ImGui::DestroyContext();
}

}  // namespace
}  // namespace gridcull
