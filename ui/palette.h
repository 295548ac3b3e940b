// The one palette the families' overlays (ui/debug_draw.h), the object states
// and the panels' swatches draw from: the Okabe-Ito colours ("Color Universal
// Design"), told apart with every common colour-vision deficiency, and a few
// greys. A family's overlay picks swatches by name, so a colour reads the same
// in every family's overlay and legend.
#pragma once
#include <cstdint>

namespace gridcull {

// Linear RGB in [0, 1].
struct Rgb {
    float r, g, b;
};

enum class Swatch : uint8_t {
    Blue,        // Okabe-Ito blue: visible objects
    SkyBlue,     // hidden objects (in the PVS, not seen); picked things
    Vermillion,     // false culls
    Yellow,      // the culling camera
    Orange,
    BluishGreen,
    ReddishPurple,
    NearBlack,  // opaque things (an occluder matrix)
    LightGrey,  // veils (occluded regions)
    Grey,       // states not yet known (outdated cells)
    LineGrey,   // grid lines
    DimGrey,    // culled objects, which recede
    White,
    Count
};
constexpr int kSwatchCount = int(Swatch::Count);

Rgb swatchColor(Swatch swatch);
const char* swatchName(Swatch swatch);  // "Okabe-Ito blue", ...

// A colour as drawn: a swatch and an opacity.
struct Paint {
    Swatch swatch = Swatch::White;
    float alpha = 1.0f;
};

// Line widths in view pixels, named so that every overlay uses the same few.
constexpr float kHairline = 1.0f;
constexpr float kFineLine = 1.5f;
constexpr float kBoldLine = 2.0f;
constexpr float kHeavyLine = 3.0f;

}  // namespace gridcull
