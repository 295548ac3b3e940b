#include "ui/rgvc/rgvc_panel.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "ui/legend_swatch.h"
#include "ui/ui_units.h"

#include "ui/rgvc/rgvc_panel3d.h"
#include "ui/rgvc/rgvc_voxel_panel.h"

namespace gridcull {

namespace {

// One toggle: checkbox, colour swatch (as the overlay draws it), name, meaning.
bool layerToggle(RgvcLayer layer, RgvcViewState& view, int dimensions) {
    ImGui::PushID(int(layer));
    bool& on = view.show[int(layer)];
    const bool changed = ImGui::Checkbox("##show", &on);
    ImGui::SameLine();
    // As drawn: 2D fills are veils over the world's fill (O and H among
    // them), 3D draws every fill opaque over the view.
    if (dimensions == 3)
        paintSwatch(scaledPixels(13), viewBackgroundColor(), {rgvcLayerSwatch(layer), 1.0f});
    else
        paintSwatch(scaledPixels(13), worldFillColor(), rgvcLayerPaint(layer));
    ImGui::SameLine();
    const char* meaning = rgvcLayerMeaning(layer, dimensions);
    if (on)
        ImGui::Text("%-8s %s", rgvcLayerName(layer), meaning);
    else
        ImGui::TextDisabled("%-8s %s", rgvcLayerName(layer), meaning);
    ImGui::PopID();
    return changed;
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
    // The per-layer history (ui/rgvc/rgvc_history.h).
    if (view.layer >= 0)
        ImGui::TextDisabled("O H I T as they stood after layer %d", value);
    else
        ImGui::TextDisabled("O H I T at the end of the frame");
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
        ImGui::TextWrapped(
            "Occluder %d of %d grows from voxel (%d, %d), met at chess layer %lld, and casts "
            "%d occlusion polygon%s.",
            value, n, o.occluder.initial.x, o.occluder.initial.y, (long long)o.layer,
            o.polygon_count, o.polygon_count == 1 ? "" : "s");
        const RgvcExtendedOccluder& occ = o.occluder;
        // Steps 1 to 4 as voxels added; a step 3 the convex L skipped says so.
        const char* shape = occ.isStaircase()                         ? "a staircase of two Ls"
                            : occ.variant == RgvcExtension::Staircase ? "an L (staircase variant)"
                                                                      : "a convex L";
        char step3[48] = "skipped step 3";
        if (occ.steps[2].run) std::snprintf(step3, sizeof step3, "%d", occ.steps[2].count);
        ImGui::TextWrapped(
            "Extended into %s: its four steps added %d, %d, %s and %d voxels, and its "
            "shadow marked %lld voxels occluded.",
            shape, occ.steps[0].count, occ.steps[1].count, step3, occ.steps[3].count,
            (long long)o.voxels_occluded);
        // Each L: its corner and legs (a staircase has two, meeting at the initial voxel).
        for (int i = 0; i < occ.part_count; ++i) {
            const RgvcOccluderL& l = occ.parts[size_t(i)];
            ImGui::TextWrapped("%s turns at voxel (%d, %d), its legs %d voxels along x and %d "
                               "along y.",
                               occ.isStaircase() ? (i == 0 ? "The L of steps 1 and 2"
                                                           : "The L of steps 3 and 4")
                                                 : "The L",
                               l.corner.x, l.corner.y, l.leg_x, l.leg_y);
        }
    }
    return changed;
}

}  // namespace

bool drawRgvcPanel(const RgvcSnapshot& rgvc, RgvcViewState& view, const RgvcPanelInput& input) {
    if (!rgvc.valid) return false;
    if (!ImGui::CollapsingHeader("Regular grid (rgvc)", ImGuiTreeNodeFlags_DefaultOpen))
        return false;
    bool changed = false;
    for (const RgvcLayer l : kRgvcLayerOrder)
        if (rgvcLayerApplies(l, rgvc.dimensions)) changed |= layerToggle(l, view, rgvc.dimensions);
    if (rgvc.dimensions == 3) changed |= drawRgvcVoxelModeControls(rgvc, view);
    changed |= layerStepper(rgvc, view);
    if (rgvc.dimensions == 3)
        changed |= drawRgvcOccluderPicker3d(rgvc, view, input.cap);
    else
        changed |= occluderPicker(rgvc, view);
    drawRgvcMemory(rgvc.memory, rgvc.dimensions);
    changed |= drawRgvcVoxelInfo(rgvc, view, input.voxel, input.voxel_hovered);
    changed |= drawRgvcObjectVoxels(rgvc, view, input.object, input.object_state);
    return changed;
}

}  // namespace gridcull
