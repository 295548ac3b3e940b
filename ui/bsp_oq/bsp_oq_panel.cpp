// The bsp panel (ui/bsp_oq/bsp_oq_panel.h).
#include "ui/bsp_oq/bsp_oq_panel.h"

#include <cstdio>

#include <imgui.h>

#include "ui/ui_units.h"

namespace gridcull {

namespace {

constexpr ImGuiColorEditFlags kSwatchFlags = ImGuiColorEditFlags_NoTooltip |
                                             ImGuiColorEditFlags_NoDragDrop |
                                             ImGuiColorEditFlags_AlphaPreview;
const ImVec2 kSwatchSize(13, 13);

void swatch(const char* id, Swatch s) {
    const Rgb c = swatchColor(s);
    ImGui::ColorButton(id, ImVec4(c.r, c.g, c.b, 1.0f), kSwatchFlags, kSwatchSize);
    ImGui::SameLine();
}

void header(const BspOqSnapshot& bsp) {
    // bsp.frame counts the frames culled since the culler was reset, so it is
    // one more than the playback's frame number on a run from frame 0.
    ImGui::Text("%s, %lld frames culled, image %d x %d", bspOqModeName(bsp.mode),
                (long long)bsp.frame, bsp.width, bsp.height);
    int trees = 0, entered = 0;
    for (size_t i = 0; i < bsp.has_tree.size(); ++i) {
        trees += bsp.has_tree[i] ? 1 : 0;
        entered += bsp.object_first[i] >= 0 ? 1 : 0;
    }
    ImGui::Text("scene tree: %zu nodes", bsp.scene_nodes.size());
    ImGui::Text("object trees entered: %d of %d", entered, trees);
}

void nodeStates(const BspOqSnapshot& bsp, BspOqViewState& view, int tree_object) {
    ImGui::TextUnformatted("nodes by state (boxes as tested):");
    for (int k = 0; k < kBspNodeStateCount; ++k) {
        const auto state = BspNodeState(k);
        ImGui::PushID(k);
        ImGui::Checkbox("##node", &view.show_nodes[k]);
        ImGui::SameLine();
        swatch(bspNodeStateName(state), bspNodeStateSwatch(state));
        const long long n = (long long)bsp.state_count[size_t(k)];
        // The meaning as a tooltip: the column is too narrow for it beside the count.
        if (view.show_nodes[k])
            ImGui::Text("%-19s %6lld", bspNodeStateName(state), n);
        else
            ImGui::TextDisabled("%-19s %6lld", bspNodeStateName(state), n);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", bspNodeStateMeaning(state));
        ImGui::PopID();
    }
    const BspDrawnCounts drawn =
        forEachDrawnBspNode(bsp, view, tree_object, [](const BspNodeRecord&, BspNodeRef) {});
    ImGui::Text("boxes drawn: %d scene, %d object (cap %d)", drawn.scene, drawn.object,
                kBspMaxNodesDrawn);
}

void queries(const BspOqSnapshot& bsp, BspOqViewState& view) {
    long long visible = 0;
    for (const BspQueryRecord& q : bsp.queries) visible += q.visible ? 1 : 0;
    ImGui::Text("occlusion queries: %zu in %d batches", bsp.queries.size(), int(bsp.batch_count));
    ImGui::Checkbox("rectangles (culling camera view)", &view.show_queries);
    if (bsp.batch_count > 0) {
        ImGui::SetNextItemWidth(-1.0f);
        ImGui::SliderInt("##batch", &view.batch, -1, bsp.batch_count - 1,
                         view.batch < 0 ? "every batch" : "batch %d", ImGuiSliderFlags_AlwaysClamp);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The batch whose rectangles are drawn (--bsp-show-batch)");
    }
    swatch("query visible", bspQuerySwatch(true));
    ImGui::Text("answered visible %5lld", visible);
    swatch("query hidden", bspQuerySwatch(false));
    ImGui::Text("answered hidden  %5lld   (label: batch)", (long long)bsp.queries.size() - visible);
}

void counters(const BspOqSnapshot& bsp) {
    for (int k = 0; k < kCounterCount; ++k) {
        const auto c = Counter(k);
        if (!bsp.stats.has(c)) continue;
        ImGui::Text("%-18s %lld", counterName(c), (long long)bsp.stats.get(c));
    }
}

void focusedObject(const BspOqSnapshot& bsp, const BspOqPanelInput& input) {
    const int i = input.focus_object;
    if (!input.scene || i < 0 || i >= int(input.scene->objects.size())) {
        ImGui::TextDisabled("point at (click) an object: its tree");
        return;
    }
    const int id = input.scene->objects[size_t(i)].id;
    const char* how = input.focus_pinned ? "picked" : "under the mouse";
    if (size_t(i) >= bsp.has_tree.size() || !bsp.has_tree[size_t(i)])
        ImGui::Text("object %d (%s): no tree", id, how);
    else if (bsp.object_first[size_t(i)] < 0)
        ImGui::Text("object %d (%s): tree not entered", id, how);
    else
        ImGui::Text("object %d (%s): tree of %d nodes", id, how, int(bsp.object_count[size_t(i)]));
}

void historyRow(const BspNodeRecord& node) {
    char marks[kMaxBspHistory + 1];
    bspHistoryMarks(node, marks);
    if (!marks[0]) {
        ImGui::TextUnformatted("  never queried");
        return;
    }
    ImGui::TextUnformatted("  answers, latest first (V visible, H hidden):");
    ImGui::TextUnformatted(" ");
    for (int k = 0; marks[k]; ++k) {
        ImGui::PushID(k);
        ImGui::SameLine(0.0f, scaledPixels(2.0f));
        const Rgb c = swatchColor(bspQuerySwatch(marks[k] == 'V'));
        ImGui::ColorButton(marks[k] == 'V' ? "visible" : "hidden", ImVec4(c.r, c.g, c.b, 1.0f),
                           kSwatchFlags, ImVec2(scaledPixels(8), scaledPixels(13)));
        ImGui::PopID();
    }
    ImGui::Text("  %s", marks);
}

void focusedNode(const BspOqSnapshot& bsp, const BspOqPanelInput& input) {
    const BspNodeRecord* node = bspNodeOf(bsp, input.focus_node);
    if (!node) {
        ImGui::TextDisabled("point at (click) a box: its node's queries");
        return;
    }
    const char* how = input.node_pinned ? "picked" : "under the mouse";
    swatch("focused node", bspNodeStateSwatch(node->state));
    if (node->object < 0)
        ImGui::Text("scene node %d (%s): %s", int(node->node), how, bspNodeStateName(node->state));
    else
        ImGui::Text("object %d node %d (%s): %s",
                    input.scene && size_t(node->object) < input.scene->objects.size()
                        ? input.scene->objects[size_t(node->object)].id
                        : int(node->object),
                    int(node->node), how, bspNodeStateName(node->state));
    ImGui::Text("  depth %d, %s, tested on %s", int(node->depth), node->leaf ? "leaf" : "inner",
                node->shrunk ? "shrunk box" : "its cell");
    ImGui::Text("  holds %d %s", int(node->contents),
                node->object < 0 ? "objects" : "triangle pieces");
    ImGui::Text("  query skipped %d more frames", int(node->skip));
    historyRow(*node);
}

}  // namespace

void drawBspOqPanel(const BspOqSnapshot& bsp, const BspOqPanelInput& input, BspOqViewState& view) {
    if (!bsp.valid) return;
    char title[96];
    std::snprintf(title, sizeof title, "BSP trees + occlusion queries (%s)###bsp", input.algo);
    if (!ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen)) return;
    header(bsp);
    focusedObject(bsp, input);
    focusedNode(bsp, input);
    nodeStates(bsp, view, bspShownTree(bsp, input.focus_object));
    queries(bsp, view);
    counters(bsp);
}

}  // namespace gridcull
