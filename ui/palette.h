// The one palette the families' overlays (ui/debug_draw.h), the object states
// and the panels' swatches draw from: the Okabe-Ito colours ("Color Universal
// Design"), told apart with every common colour-vision deficiency, and a few
// greys. A family's overlay picks swatches by name, so a colour reads the same
// in every family's overlay and legend.
//
// One meaning per colour: the comments below say what each swatch means
// wherever it is used; a family keys the hues left to it (orange, bluish green,
// reddish purple) in its own legend, one meaning each within its view, and
// draws its legend's swatch with the paint its overlay uses, over what the
// overlay is drawn over (ui/legend_swatch.h, or the overlay's own paint code
// where its legend keys a class of cells). Vermillion is the
// false culls' alone (the object state and the timeline's marks): no overlay
// draws it (tests/ui/palette_audit_test.cpp), so a vermillion shape on the
// screen is always a culling bug.
#pragma once
#include <cstdint>

namespace gridcull {

// Linear RGB in [0, 1].
struct Rgb {
    float r, g, b;
};

enum class Swatch : uint8_t {
    Blue,           // visible objects (the object states)
    SkyBlue,        // hidden objects (in the PVS, not seen); in overlays, picked things (a picked occluder)
    Vermillion,     // false culls, and nothing else: never in an overlay
    Yellow,         // the culling camera: its frustum, line of sight (and what a family marks on it), what it sees of a box
    Orange,         // sub-sample objects (the oracle cannot decide them); in overlays a family's own, keyed in its legend
    BluishGreen,    // a family's own, keyed in its legend
    ReddishPurple,  // a family's own, keyed in its legend
    NearBlack,      // opaque things (an occluder matrix), dark backings
    LightGrey,      // veils (occluded regions)
    Grey,           // states not yet known (outdated cells, nodes not reached), static occluders
    LineGrey,       // grid lines, frames
    DimGrey,        // culled objects and outside the frustum, which recede
    White,          // under the pointer (a hovered voxel or cell and its focused test); found hidden (Z-culled nodes, hidden queries)
    Count
};
constexpr int kSwatchCount = int(Swatch::Count);

Rgb swatchColor(Swatch swatch);
const char* swatchName(Swatch swatch);  // "Okabe-Ito blue", ...

// What overlays are drawn over: the scene view's background, and in 2D the
// world's box filled inside it. Legend swatches are drawn over the same.
Rgb viewBackgroundColor();
Rgb worldFillColor();

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
