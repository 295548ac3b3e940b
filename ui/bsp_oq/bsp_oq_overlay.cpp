// The bsp family's overlays (ui/bsp_oq/bsp_oq_overlay.h).
#include "ui/bsp_oq/bsp_oq_overlay.h"

#include <cstdio>

namespace gridcull {

namespace {

constexpr float kQueryAlpha = 0.9f;
constexpr double kLabelInset = 2.0;  // view pixels from the rectangle's corner

}  // namespace

BspOverlayCounts drawBspOqNodes(const BspOqSnapshot& snapshot, const BspOqViewState& view,
                                int tree_object, BspNodeRef focus, DebugDraw& draw) {
    BspOverlayCounts counts;
    if (!snapshot.valid) return counts;
    const BspDrawnCounts drawn = forEachDrawnBspNode(
        snapshot, view, tree_object, [&](const BspNodeRecord& node, BspNodeRef) {
            draw.wireBox(node.box.min, node.box.max,
                         {bspNodeStateSwatch(node.state), bspNodeStateAlpha(node.state)},
                         bspNodeStateWidth(node.state));
        });
    counts.scene_nodes = drawn.scene;
    counts.object_nodes = drawn.object;
    // The focused node even when its state is off: it was picked to be seen.
    if (const BspNodeRecord* node = bspNodeOf(snapshot, focus)) {
        draw.wireBox(node->box.min, node->box.max, {bspNodeStateSwatch(node->state)},
                     kBspFocusWidth);
        counts.focus = true;
    }
    return counts;
}

BspOverlayCounts drawBspOqQueries(const BspOqSnapshot& snapshot, const BspOqViewState& view,
                                  const ImageFrame& frame, DebugDraw& draw) {
    BspOverlayCounts counts;
    if (!snapshot.valid || !view.show_queries) return counts;
    for (const BspQueryRecord& q : snapshot.queries) {
        if (!view.batchShown(q.batch) || q.rect.empty()) continue;
        const ViewRect r = frame.pixelsToView(q.rect);
        const Paint paint{bspQuerySwatch(q.visible), kQueryAlpha};
        draw.outlineRect(r, paint, kBspQueryWidth);
        ++counts.queries;
        if (r.x1 - r.x0 < kBspMinLabelledWidth || r.y1 - r.y0 < kBspMinLabelledHeight) continue;
        char label[16];
        std::snprintf(label, sizeof label, "%d", int(q.batch));
        draw.text(DrawSpace::View, {r.x0 + kLabelInset, r.y0 + kLabelInset, 0.0}, label, paint,
                  kBspLabelScale);
        ++counts.labels;
    }
    return counts;
}

}  // namespace gridcull
