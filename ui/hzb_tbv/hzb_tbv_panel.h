// The hzb panel (hzb-tbv, hzb-tbvi, hzb in a 3D scene): the update mode; the
// dynamic objects D by state (visible, under a TBV, expired, revealed,
// violated) and the focused object's state and TBV; the TBV colour key by
// remaining validity with a toggle; the expiration queue Q's next events; the
// octree nodes the traversal reached by outcome, each a toggle with its colour;
// the Z-pyramid images' toggle, level slider and grey key; the frame's counters.
// Reads the snapshot, never changes it; changes only the view state it is given.
#pragma once
#include "culling/hzb_tbv/hzb_tbv_snapshot.h"
#include "culling/scene/scene.h"
#include "ui/hzb_tbv/hzb_tbv_view.h"

namespace gridcull {

// Rows of Q's next events the panel lists (the snapshot keeps kHzbNextExpiries).
constexpr int kHzbExpiryRows = 8;

// What the panel shows besides the snapshot.
struct HzbTbvPanelInput {
    const Scene* scene = nullptr;
    const char* algo = "";
    // The object (index into scene->objects, -1: none) the panel details: the
    // one under the mouse, else the picked one (`pinned`).
    int focus_object = -1;
    bool focus_pinned = false;
};

// Draws into the current ImGui window.
void drawHzbTbvPanel(const HzbTbvSnapshot& hzb, const HzbTbvPanelInput& input,
                     HzbTbvViewState& view);

}  // namespace gridcull
