#include "ui/rgvc/rgvc_panel3d.h"

#include <algorithm>

#include <imgui.h>

#include "ui/ui_units.h"

#include "ui/rgvc/rgvc_slice.h"
#include "ui/rgvc/rgvc_voxel_boxes.h"

namespace gridcull {

namespace {

constexpr const char* kAxisNames[3] = {"x", "y", "z"};
constexpr const char* kFaceSigns[2] = {"-", "+"};

// A legend row without a toggle: a swatch and what it marks.
void swatchRow(Swatch swatch, const char* meaning) {
    const Rgb c = swatchColor(swatch);
    ImGui::ColorButton(meaning, ImVec4(c.r, c.g, c.b, 1.0f),
                       ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop,
                       ImVec2(scaledPixels(13), scaledPixels(13)));
    ImGui::SameLine();
    ImGui::TextUnformatted(meaning);
}

}  // namespace

bool drawRgvcVoxelModeControls(const RgvcSnapshot& s, RgvcViewState& view) {
    bool changed = false;
    ImGui::TextUnformatted("show:");
    ImGui::SameLine();
    int mode = int(view.mode);
    changed |= ImGui::RadioButton("boxes", &mode, int(RgvcVoxelMode::Boxes));
    ImGui::SameLine();
    changed |= ImGui::RadioButton("slice", &mode, int(RgvcVoxelMode::Slice));
    view.mode = RgvcVoxelMode(mode);
    if (view.mode != RgvcVoxelMode::Slice) {
        swatchRow(RgvcVoxelBoxes::kFrameSwatch, "box edges");
        return changed;
    }
    ImGui::SameLine();
    for (int a = 0; a < 3; ++a) {
        ImGui::SameLine();
        ImGui::PushID(a);
        int axis = view.slice_axis;
        if (ImGui::RadioButton(kAxisNames[a], &axis, a)) {
            view.slice_axis = axis;
            view.slice_index = -1;  // through the viewer again
            changed = true;
        }
        ImGui::PopID();
    }
    const int axis = std::clamp(view.slice_axis, 0, 2);
    int index = rgvcSliceIndex(s, view);
    swatchRow(kRgvcSliceBackdrop, "slice voxels no shown layer holds");
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderInt("##slice", &index, 0, s.grid.resolution[axis] - 1,
                         axis == 0   ? "slice x = %d"
                         : axis == 1 ? "slice y = %d"
                                     : "slice z = %d")) {
        view.slice_index = index;
        changed = true;
    }
    return changed;
}

bool drawRgvcOccluderPicker3d(const RgvcSnapshot& s, RgvcViewState& view, const RgvcCap3d* cap) {
    const int n = int(s.occluders3d.size());
    if (n == 0) {
        ImGui::TextDisabled("no occluders this frame");
        return false;
    }
    int value = std::clamp(view.occluder, -1, n - 1);
    ImGui::SetNextItemWidth(-1.0f);
    const bool changed =
        ImGui::SliderInt("##occluder3d", &value, -1, n - 1,
                         value < 0 ? "occluder: none (or click one)" : "occluder %d");
    if (changed) view.occluder = value;
    if (value < 0) return changed;
    const RgvcOccluder3d& o = s.occluders3d[size_t(value)];
    ImGui::TextWrapped("Occluder %d of %d is voxel (%d, %d, %d), met at chess layer %d; its "
                       "pass marked %lld direction-map cells occluded.",
                       value, n, o.voxel.x, o.voxel.y, o.voxel.z, int(o.layer),
                       (long long)o.cells_covered);
    if (cap && cap->valid && cap->occluder == value) {
        int outer = 0;
        for (const BitmapLoop& loop : cap->vectorizer.loops()) outer += loop.hole ? 0 : 1;
        ImGui::TextWrapped("Its layer's cap, on the %s%s face of the chess cube, joins %lld "
                           "blocking voxels into %d polygon%s with %d hole%s.",
                           kFaceSigns[cap->sign > 0 ? 1 : 0], kAxisNames[cap->axis],
                           (long long)cap->blocking, outer, outer == 1 ? "" : "s", cap->holes,
                           cap->holes == 1 ? "" : "s");
    }
    return changed;
}

}  // namespace gridcull
