// What the window shows of octree + hierarchical z-buffer culling with TBVs
// (hzb-tbv, hzb-tbvi, hzb; culling/hzb_tbv/hzb_tbv_snapshot.h) and the colours
// it uses, shared by the panel (ui/hzb_tbv/hzb_tbv_panel.h), which changes the
// view state and keys the colours, and the overlays (ui/hzb_tbv/hzb_tbv_overlay.h
// in World space, ui/hzb_tbv/hzb_pyramid_images.h in View space), which draw it.
//
// Names are Sudarsky & Gotsman's (sections 3.3 to 3.7 and 4): TBV, expiration
// date, validity period, the expiration queue Q, octree node, Z-pyramid.
// Colours are the palette's hues that the object states (blue, sky blue,
// vermillion, dim grey) and the camera (yellow) leave free, and greys:
//   TBVs by remaining validity, as a fraction of their validity period:
//     bluish green (long-lived) -> orange -> reddish purple (about to expire);
//   octree nodes by outcome: white Z-culled (hidden by the Z-pyramid: white is
//     the palette's "found hidden"), grey entered, dim grey frustum-culled;
//   Z-pyramid texels: grey levels, near = light, far = dark, empty = black.
#pragma once
#include <cstdint>

#include <vector>

#include "culling/hzb_tbv/hzb_tbv_snapshot.h"
#include "ui/overlay_preset.h"
#include "ui/palette.h"

namespace gridcull {

// A TBV's remaining validity as a fraction of its validity period, in bands.
enum class HzbTbvBand : uint8_t {
    Long,    // more than 2/3 of its period left, or it never expires
    Middle,  // 1/3 to 2/3 left
    Short,   // less than 1/3 left: expires soon
};
constexpr int kHzbTbvBandCount = 3;

// The fraction of the TBV's validity period left (1 for a TBV that never
// expires, clamped to [0, 1]); the object must have a TBV.
double hzbTbvFractionLeft(const HzbTbvObject& object);
HzbTbvBand hzbTbvBandOf(const HzbTbvObject& object);
const char* hzbTbvBandName(HzbTbvBand band);
const char* hzbTbvBandMeaning(HzbTbvBand band);
Swatch hzbTbvBandSwatch(HzbTbvBand band);

Swatch hzbNodeOutcomeSwatch(HzbNodeOutcome outcome);
float hzbNodeOutcomeAlpha(HzbNodeOutcome outcome);
float hzbNodeOutcomeWidth(HzbNodeOutcome outcome);
const char* hzbNodeOutcomeMeaning(HzbNodeOutcome outcome);
const char* hzbObjectStatusMeaning(HzbObjectStatus status);

// At most this many octree nodes are drawn (the first ones shown, in the
// traversal's front-to-back order), so that a deep tree stays readable.
constexpr int kHzbMaxNodesDrawn = 1500;
// Z-pyramid images: this many levels from the first one shown, coarser to the
// right; with no level picked, the first is the finest captured level with at
// most kHzbAutoPyramidSide texels on its long side.
constexpr int kHzbPyramidImages = 3;
constexpr int kHzbAutoPyramidSide = 64;

// The "all" preset but frustum-culled nodes; a family view starts with its
// first preset instead (hzbTbvOverlayPresets).
struct HzbTbvViewState {
    bool show_tbvs = true;
    // By HzbNodeOutcome: frustum-culled nodes off (the clutter outside the view).
    bool show_nodes[kHzbNodeOutcomeCount] = {false, true, true};
    bool show_pyramid = true;
    int pyramid_level = -1;  // the first Z-pyramid level shown (the pyramid's numbering); -1: auto

    bool shown(HzbNodeOutcome o) const { return show_nodes[int(o)]; }
};

// The overlay presets, the first the one a view starts with: "occlusion only"
// (the Z-pyramid's levels and the octree nodes it hid), "traversal" (the
// octree nodes the front-to-back traversal took up, by outcome, frustum-culled
// ones included), "TBVs" (the hidden objects' TBVs by validity left) and
// "all". The pyramid level shown stays as picked.
std::vector<OverlayPreset> hzbTbvOverlayPresets();
void hzbTbvApplyPreset(HzbTbvViewState& view, OverlayPreset preset);

// The index in snapshot.pyramid_levels of the first level shown: the captured
// level nearest the picked one (a level finer than any captured one gives the
// finest captured, one past the top the top); auto: the finest captured level
// with at most kHzbAutoPyramidSide texels on its long side. -1 when nothing was
// captured.
int hzbFirstPyramidImage(const HzbTbvSnapshot& snapshot, const HzbTbvViewState& view);

// TBVs per band at the end of the frame.
struct HzbTbvBandCounts {
    int64_t count[kHzbTbvBandCount] = {};
    int64_t of(HzbTbvBand b) const { return count[int(b)]; }
};
HzbTbvBandCounts countHzbTbvBands(const HzbTbvSnapshot& snapshot);

}  // namespace gridcull
