// The bsp panel (bsp-oq, bsp-oq-simple, bsp-vfc in a 3D scene): the mode and
// frame; the nodes of the scene and object trees by state, each a toggle with
// its colour and meaning (the overlay's key); the frame's occlusion queries and
// batches with the rectangles' toggle, batch slider and colour key; the
// frame's counters; the focused object's tree; the focused node's state, box,
// contents, skip counter and recent query answers as a row of marks, latest
// first. Reads the snapshot, never changes it; changes only the view state.
#pragma once
#include "culling/bsp_oq/bsp_oq_snapshot.h"
#include "culling/scene/scene.h"
#include "ui/bsp_oq/bsp_oq_view.h"

namespace gridcull {

// What the panel shows besides the snapshot.
struct BspOqPanelInput {
    const Scene* scene = nullptr;
    const char* algo = "";
    int focus_object = -1;  // object index (under the mouse, else picked); -1: none
    bool focus_pinned = false;
    BspNodeRef focus_node;  // under the mouse, else picked
    bool node_pinned = false;
};

// Draws into the current ImGui window.
void drawBspOqPanel(const BspOqSnapshot& bsp, const BspOqPanelInput& input, BspOqViewState& view);

}  // namespace gridcull
