// Sizes in the panels are written in design pixels, for ImGui's 13-pixel
// default font; scaledPixels turns them into pixels at the current font size,
// so that the whole column grows with --ui-scale and Ctrl+plus (a projector at
// twice the size keeps the same proportions).
#pragma once
#include <imgui.h>

namespace gridcull {

constexpr float kDesignFontPixels = 13.0f;

inline float scaledPixels(float design) {
    return design * ImGui::GetFontSize() / kDesignFontPixels;
}

}  // namespace gridcull
