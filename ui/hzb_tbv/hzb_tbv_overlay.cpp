// The hzb family's World-space overlay (ui/hzb_tbv/hzb_tbv_overlay.h).
#include "ui/hzb_tbv/hzb_tbv_overlay.h"

#include <algorithm>

namespace gridcull {

namespace {

constexpr float kTbvAlpha = 0.9f;

int drawNodes(const HzbTbvSnapshot& s, const HzbTbvViewState& view, DebugDraw& draw) {
    int drawn = 0;
    for (const HzbNodeVisit& node : s.nodes) {
        if (!view.shown(node.outcome)) continue;
        if (drawn == kHzbMaxNodesDrawn) break;
        ++drawn;
        draw.wireBox(node.box.min, node.box.max,
                     {hzbNodeOutcomeSwatch(node.outcome), hzbNodeOutcomeAlpha(node.outcome)},
                     hzbNodeOutcomeWidth(node.outcome));
    }
    return drawn;
}

int drawTbvs(const HzbTbvSnapshot& s, int focus_object, DebugDraw& draw) {
    int drawn = 0;
    for (const HzbTbvObject& o : s.objects) {
        if (!o.has_tbv) continue;
        ++drawn;
        const bool focused = o.object_index == focus_object;
        draw.wireBox(o.tbv.min, o.tbv.max,
                     {hzbTbvBandSwatch(hzbTbvBandOf(o)), focused ? 1.0f : kTbvAlpha},
                     focused ? kHzbFocusedTbvWidth : kHzbTbvWidth);
    }
    return drawn;
}

}  // namespace

HzbOverlayCounts countHzbNodesShown(const HzbTbvSnapshot& snapshot, const HzbTbvViewState& view) {
    HzbOverlayCounts counts;
    for (int o = 0; o < kHzbNodeOutcomeCount; ++o)
        if (view.show_nodes[o]) counts.nodes_shown += int(snapshot.node_count[size_t(o)]);
    counts.nodes_drawn = std::min(counts.nodes_shown, kHzbMaxNodesDrawn);
    return counts;
}

HzbOverlayCounts drawHzbTbvOverlay(const HzbTbvSnapshot& snapshot, const HzbTbvViewState& view,
                                   int focus_object, DebugDraw& draw) {
    HzbOverlayCounts counts;
    if (!snapshot.valid) return counts;
    // Nodes first: lines of one width draw in emission order, so TBVs of the
    // same width land on top of nodes.
    counts = countHzbNodesShown(snapshot, view);
    counts.nodes_drawn = drawNodes(snapshot, view, draw);
    if (view.show_tbvs) counts.tbvs = drawTbvs(snapshot, focus_object, draw);
    return counts;
}

}  // namespace gridcull
