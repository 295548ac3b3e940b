#include "ui/rgvc/rgvc_panel.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

namespace gridcull {

namespace {

constexpr ImGuiColorEditFlags kSwatchFlags = ImGuiColorEditFlags_NoTooltip |
                                             ImGuiColorEditFlags_NoDragDrop |
                                             ImGuiColorEditFlags_AlphaPreview;

// One toggle: checkbox, colour swatch (as drawn, with its opacity), name, meaning.
bool layerToggle(RgvcLayer layer, RgvcViewState& view) {
    ImGui::PushID(int(layer));
    bool& on = view.show[int(layer)];
    const bool changed = ImGui::Checkbox("##show", &on);
    ImGui::SameLine();
    const Rgb c = swatchColor(rgvcLayerSwatch(layer));
    // O and H are veils: show their swatch over the world's dark fill as drawn.
    const float alpha = std::max(rgvcLayerAlpha(layer), 0.6f);
    ImGui::ColorButton(rgvcLayerName(layer), ImVec4(c.r, c.g, c.b, alpha), kSwatchFlags,
                       ImVec2(13, 13));
    ImGui::SameLine();
    if (on)
        ImGui::Text("%-8s %s", rgvcLayerName(layer), rgvcLayerMeaning(layer));
    else
        ImGui::TextDisabled("%-8s %s", rgvcLayerName(layer), rgvcLayerMeaning(layer));
    ImGui::PopID();
    return changed;
}

// The first ids of a list and how many there are, in a fixed buffer (drawn every frame).
void idList(const char* name, const std::vector<int>& ids) {
    constexpr size_t kShown = 12;
    char text[160];
    int used = std::snprintf(text, sizeof text, "%s ids:", name);
    for (size_t k = 0; k < ids.size() && k < kShown && used > 0 && size_t(used) < sizeof text; ++k)
        used += std::snprintf(text + used, sizeof text - size_t(used), " %d", ids[k]);
    if (ids.empty())
        std::snprintf(text + used, sizeof text - size_t(used), " -");
    else if (ids.size() > kShown && used > 0 && size_t(used) < sizeof text)
        std::snprintf(text + used, sizeof text - size_t(used), " ... (%zu)", ids.size());
    ImGui::TextWrapped("%s", text);
}

void voxelInfo(const RgvcVoxelInfo* info) {
    if (!info || !info->valid) {
        ImGui::TextDisabled("voxel: point at the grid in the view");
        return;
    }
    ImGui::Text("voxel (%d, %d)  O %d  Os %d  H %d", info->voxel.x, info->voxel.y, int(info->o),
                int(info->os), int(info->h));
    idList("I", info->ids_i);
    idList("T", info->ids_t);
    if (info->visit_order < 0)
        ImGui::TextUnformatted("not visited by the traversal");
    else
        ImGui::Text("visited in layer %lld (visit %lld)%s", (long long)info->layer,
                    (long long)info->visit_order,
                    info->visited_occluded ? ", already occluded" : "");
}

void memoryRows(const RgvcMatrixMemory& m) {
    const auto kib = [](size_t bytes) { return double(bytes) / 1024.0; };
    ImGui::Text("KiB: O %.1f  Os %.1f  H %.1f  T %.1f", kib(m.occluder), kib(m.static_occluder),
                kib(m.occlusion), kib(m.tbv));
    ImGui::Text("     I %.1f + %.1f  scratch %.1f  = %.1f", kib(m.identifiers_static),
                kib(m.identifiers_dynamic), kib(m.traversal), kib(m.total()));
}

bool layerStepper(const RgvcSnapshot& rgvc, RgvcViewState& view) {
    const int64_t shown = rgvcShownLayer(rgvc, view.layer);
    if (shown < 0) {
        ImGui::TextDisabled("no layer traversed (viewer sees no voxel)");
        return false;
    }
    bool changed = false;
    int value = int(shown);
    const int first = int(rgvc.first_layer), last = int(rgvc.last_layer);
    if (ImGui::Button("<") && value > first) {
        view.layer = value - 1;
        changed = true;
    }
    ImGui::SameLine();
    if (ImGui::Button(">")) {
        view.layer = value + 1 >= last ? -1 : value + 1;
        changed = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("all")) {
        view.layer = -1;
        changed = true;
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderInt("##layer", &value, first, last,
                         view.layer < 0 ? "layer %d (all)" : "layer %d")) {
        view.layer = value >= last ? -1 : value;
        changed = true;
    }
    int64_t count = 0;
    for (const RgvcVisit& v : rgvc.visits) count += v.layer <= shown ? 1 : 0;
    ImGui::Text("layers %d..%d%s, visits %lld/%zu", first, last,
                rgvc.terminated_early ? " (early end)" : "", (long long)count, rgvc.visits.size());
    return changed;
}

bool occluderPicker(const RgvcSnapshot& rgvc, RgvcViewState& view) {
    const int n = int(rgvc.occluders.size());
    if (n == 0) {
        ImGui::TextDisabled("no extended occluders this frame");
        return false;
    }
    int value = std::clamp(view.occluder, -1, n - 1);
    ImGui::SetNextItemWidth(-1.0f);
    const bool changed =
        ImGui::SliderInt("##occluder", &value, -1, n - 1,
                         value < 0 ? "occluder: none (or click one)" : "occluder %d");
    if (changed) view.occluder = value;
    if (value >= 0) {
        const RgvcOccluderView& o = rgvc.occluders[size_t(value)];
        ImGui::Text("of %d: initial (%d, %d), layer %lld, %d polygon(s)", n, o.occluder.initial.x,
                    o.occluder.initial.y, (long long)o.layer, o.polygon_count);
        ImGui::Text("steps %d %d %d %d, legs x %d y %d, marked %lld", o.occluder.steps[0].count,
                    o.occluder.steps[1].count, o.occluder.steps[2].count, o.occluder.steps[3].count,
                    o.occluder.parts[0].leg_x, o.occluder.parts[0].leg_y, (long long)o.voxels_occluded);
    }
    return changed;
}

}  // namespace

bool drawRgvcPanel(const RgvcSnapshot& rgvc, RgvcViewState& view, const RgvcVoxelInfo* voxel) {
    if (!rgvc.valid) return false;
    if (!ImGui::CollapsingHeader("Regular grid (rgvc)", ImGuiTreeNodeFlags_DefaultOpen))
        return false;
    bool changed = false;
    for (int l = 0; l < kRgvcLayerCount; ++l) changed |= layerToggle(RgvcLayer(l), view);
    changed |= layerStepper(rgvc, view);
    changed |= occluderPicker(rgvc, view);
    memoryRows(rgvc.memory);
    voxelInfo(voxel);
    return changed;
}

}  // namespace gridcull
