#include "ui/lazy_grid/lazy_grid_panel.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "culling/lazy_grid/lazy_grid_options.h"
#include "ui/lazy_grid/lazy_grid_overlay.h"
#include "ui/legend_swatch.h"

namespace gridcull {

namespace {

constexpr ImGuiColorEditFlags kSwatchFlags = ImGuiColorEditFlags_NoTooltip |
                                             ImGuiColorEditFlags_NoDragDrop |
                                             ImGuiColorEditFlags_AlphaPreview;
const ImVec2 kSwatchSize(13, 13);

// Swatches show a fill over the view's dark background as the overlay blends
// it, but never fainter than this so a faint class still shows its hue.
constexpr float kMinSwatchAlpha = 0.45f;

void swatch(const char* id, Swatch s, float alpha) {
    const Rgb c = swatchColor(s);
    ImGui::ColorButton(id, ImVec4(c.r, c.g, c.b, std::max(alpha, kMinSwatchAlpha)), kSwatchFlags,
                       kSwatchSize);
    ImGui::SameLine();
}

const char* variantText(const LazyGridSnapshot& lazy) {
    if (lazy.variant == LazyGridVariant::ZBuffer)
        return "z-buffer variant, lazy update (3.2, Fig. 4)";
    if (lazy.update == LazyGridUpdate::BusyTight)
        return "occlusion buffer, tight busy update (Fig. 6)";
    return lazy.update == LazyGridUpdate::Busy ? "occlusion buffer, busy update (7, Fig. 6)"
                                               : "occlusion buffer, lazy update (3.1, Fig. 6)";
}

int log2Floor(int v) {
    int e = 0;
    while (v > 1) {
        v >>= 1;
        ++e;
    }
    return e;
}

// Powers of two only: each change re-runs every frame so far, and the paper's
// 32 sits in the middle.
void cellSizeSlider(const LazyGridSnapshot& lazy, LazyGridPanelState& state, FamilyAction& action) {
    if (!state.dragging)
        state.cell_size_log2 =
            std::clamp(log2Floor(lazy.cell_size), kLazyCellSizeMinLog2, kLazyCellSizeMaxLog2);
    const int shown = state.dragging ? 1 << state.cell_size_log2 : lazy.cell_size;
    char label[64];
    // The slider moves the exponent; its text is the size (no % left for ImGui).
    std::snprintf(label, sizeof label, "%d px", shown);
    ImGui::Text("grid %d x %d cells of", lazy.cells_x, lazy.cells_y);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::SliderInt("##cell size", &state.cell_size_log2, kLazyCellSizeMinLog2,
                     kLazyCellSizeMaxLog2, label, ImGuiSliderFlags_AlwaysClamp);
    state.dragging = ImGui::IsItemActive();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Cell side in pixels (--lazy-cell-size); re-runs up to this frame");
    if (ImGui::IsItemDeactivatedAfterEdit()) {
        const int size = 1 << state.cell_size_log2;
        if (size != lazy.cell_size) action.knobs.emplace_back(kLazyCellSizeFlag, size);
    }
}

void counters(const LazyGridSnapshot& lazy) {
    const LazyGridCounters& c = lazy.counters;
    ImGui::Text("pixel-level queries %lld, cell updates %lld", (long long)c.pixel_queries,
                (long long)c.cell_updates);
    ImGui::Text("pixels read %lld, occlusion tests %lld", (long long)c.pixels_read,
                (long long)c.occlusion_tests);
    if (c.probability_skips > 0)
        ImGui::Text("queries saved by probability %lld", (long long)c.probability_skips);
}

// The colour key of the cells, with how many are in each state at frame end.
void cellStates(const LazyGridSnapshot& lazy) {
    const LazyCellCounts counts = countLazyCells(lazy);
    LazyCellClass classes[kLazyCellClassCount];
    const int n = lazyCellClassesOf(lazy.variant, classes);
    for (int k = 0; k < n; ++k) {
        const LazyCellClass c = classes[k];
        // Drawn by the overlay's own cell code, over the view's background.
        SwatchDraw key(kSwatchSize.x, viewBackgroundColor());
        drawLazyCell(c, lazyCellLegendAlpha(c), key.rect(), key);
        ImGui::SameLine();
        ImGui::Text("%-15s %4lld  %s", lazyCellClassName(c), (long long)counts.of(c),
                    lazyCellClassMeaning(c));
    }
}

// What decided the test, as a sentence; the paper's name of the step (Fig. 2
// and 3) in the tooltip, for reading the two side by side.
const char* decisionSentence(OcclusionStep step) {
    switch (step) {
        case OcclusionStep::InternalWithoutPixelQuery:
            return "A cell wholly inside its box was known to be free, so the box is "
                   "potentially visible and its objects are drawn; no pixel was read.";
        case OcclusionStep::BorderWithoutPixelQuery:
            return "A cell on its box's border was known to be free, so the box is "
                   "potentially visible and drawn; no pixel was read.";
        case OcclusionStep::InternalWithPixelQuery:
            return "An outdated cell inside its box was brought up to date by reading its "
                   "pixels and found free, so the box is potentially visible and drawn.";
        case OcclusionStep::BorderWithPixelQuery:
            return "The pixels of a border cell under its box were read and some were free, "
                   "so the box is potentially visible and drawn.";
        case OcclusionStep::Occluded:
            return "No cell under its box was free: the box is occluded and culled.";
        case OcclusionStep::OffScreen:
            return "Its box covers no pixel of the image: culled.";
    }
    return "";
}

void decisionResult(const LazyGridTest& test) {
    if (!test.in_frustum) {
        ImGui::TextWrapped("Its box lies outside the view frustum: culled, no cell read.");
        return;
    }
    ImGui::TextWrapped("%s", decisionSentence(test.step));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the paper's step (Fig. 2 and 3): %s", occlusionStepName(test.step));
}

// The cell that made a box potentially visible: its last touch, found free.
void freeCell(const LazyGridSnapshot& lazy, const LazyGridTest& test) {
    if (test.occluded || test.touch_count == 0) return;
    const CellTouch& last = lazy.touches[size_t(test.first_touch + test.touch_count - 1)];
    if (!last.free || lazy.cells_x <= 0) return;
    swatch("free cell", lazyFreeTouchSwatch(), 1.0f);
    ImGui::Text("found free: %s cell (%d, %d)",
                last.role == CellRole::Internal ? "internal" : "border", last.cell % lazy.cells_x,
                last.cell / lazy.cells_x);
}

void focusedObject(const LazyGridPanelInput& input, const LazyGridSnapshot& lazy) {
    const int index = input.focus_object;
    if (index < 0 || index >= int(input.scene->objects.size())) {
        ImGui::TextDisabled("point at (click) an object: its test shows here");
        return;
    }
    const SceneObject& object = input.scene->objects[size_t(index)];
    ImGui::Text("object %d, %s (%s)", object.id, shapeName(object.shape, 3),
                input.focus_pinned ? "picked" : "under the mouse");
    const LazyDecision d = describeLazyDecision(lazy, index);
    if (!d.test) {
        ImGui::TextDisabled("not reached by the traversal");
        return;
    }
    if (d.own_box)
        ImGui::TextUnformatted("its own box was tested");
    else
        ImGui::Text("an enclosing box was tested (BVH node %d)", d.test->node);
    decisionResult(*d.test);
    if (!d.test->in_frustum) return;
    const PixelRect& r = d.test->box.rect;
    if (!r.empty())
        ImGui::Text("rect (%d, %d)-(%d, %d) px, znear %.2f", r.x0, r.y0, r.x1, r.y1,
                    d.test->box.znear);
    ImGui::Text("cells: %d internal, %d border, %d read by a query", d.internal, d.border,
                d.pixel_queries);
    freeCell(lazy, *d.test);
}

bool layerToggle(LazyGridLayer layer, LazyGridViewState& view) {
    ImGui::PushID(int(layer));
    bool& on = view.show[int(layer)];
    const bool changed = ImGui::Checkbox("##show", &on);
    ImGui::SameLine();
    swatch(lazyGridLayerName(layer), lazyGridLayerSwatch(layer), 1.0f);
    if (on)
        ImGui::Text("%-8s %s", lazyGridLayerName(layer), lazyGridLayerMeaning(layer));
    else
        ImGui::TextDisabled("%-8s %s", lazyGridLayerName(layer), lazyGridLayerMeaning(layer));
    ImGui::PopID();
    return changed;
}

}  // namespace

void drawLazyGridPanel(const LazyGridSnapshot& lazy, const LazyGridPanelInput& input,
                       LazyGridViewState& view, LazyGridPanelState& state, FamilyAction& action) {
    if (!lazy.valid) return;
    char title[96];
    std::snprintf(title, sizeof title, "Lazy occlusion grid (%s)###lazy grid", input.algo);
    if (!ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::Text("%s", variantText(lazy));
    ImGui::Text("image %d x %d px, the culling camera's view", lazy.width, lazy.height);
    cellSizeSlider(lazy, state, action);
    counters(lazy);
    cellStates(lazy);
    focusedObject(input, lazy);
    if (input.view_mode != ViewMode::CullingCamera)
        ImGui::TextDisabled("overlay: its cells also drawn in the frustum");
    for (int l = 0; l < kLazyGridLayerCount; ++l) layerToggle(LazyGridLayer(l), view);
}

}  // namespace gridcull
