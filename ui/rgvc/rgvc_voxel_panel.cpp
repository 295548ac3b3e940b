#include "ui/rgvc/rgvc_voxel_panel.h"

#include <cstdio>

#include <imgui.h>

namespace gridcull {

namespace {

// The first ids of a list and how many there are, in a fixed buffer (drawn every frame).
template <typename Id, typename Print>
void idList(const char* name, const std::vector<Id>& ids, Print&& print) {
    constexpr size_t kShown = 10;
    char text[200];
    int used = std::snprintf(text, sizeof text, "%s ids:", name);
    for (size_t k = 0; k < ids.size() && k < kShown && used > 0 && size_t(used) < sizeof text; ++k)
        used += print(text + used, sizeof text - size_t(used), ids[k]);
    if (ids.empty())
        std::snprintf(text + used, sizeof text - size_t(used), " -");
    else if (ids.size() > kShown && used > 0 && size_t(used) < sizeof text)
        std::snprintf(text + used, sizeof text - size_t(used), " ... (%zu)", ids.size());
    ImGui::TextWrapped("%s", text);
}

void voxelName(char* out, size_t size, const glm::ivec3& v, int dimensions) {
    if (dimensions == 3)
        std::snprintf(out, size, "(%d, %d, %d)", v.x, v.y, v.z);
    else
        std::snprintf(out, size, "(%d, %d)", v.x, v.y);
}

}  // namespace

bool rgvcOccluderButton(RgvcViewState& view, int32_t index) {
    char label[40];
    std::snprintf(label, sizeof label, "occluder %d##%d", int(index), int(index));
    if (!ImGui::SmallButton(label)) return false;
    view.occluder = index;
    return true;
}

bool drawRgvcVoxelInfo(const RgvcSnapshot& s, RgvcViewState& view, const RgvcVoxelInfo* info,
                       bool hovered) {
    if (!info || !info->valid) {
        ImGui::TextDisabled(s.dimensions == 3 ? "voxel: point at a box (or the slice)"
                                              : "voxel: point at the grid in the view");
        return false;
    }
    char name[64];
    voxelName(name, sizeof name, info->voxel, info->dimensions);
    ImGui::Text("voxel %s%s", name, hovered ? "" : " (clicked)");
    ImGui::Text("O %d  Os %d  H %d", int(info->o), int(info->os), int(info->h));
    if (info->o && info->o_layer != kRgvcNoLayer) {
        ImGui::SameLine();
        ImGui::Text(" O since layer %d (revealed)", int(info->o_layer));
    }
    idList("I", info->ids_i,
           [](char* out, size_t size, int id) { return std::snprintf(out, size, " %d", id); });
    idList("T", info->ids_t, [](char* out, size_t size, const RgvcTbvAtVoxel& t) {
        return t.revealed == kRgvcNoLayer
                   ? std::snprintf(out, size, " %d", t.id)
                   : std::snprintf(out, size, " %d (revealed at layer %d)", t.id, int(t.revealed));
    });
    if (info->visit_order < 0)
        ImGui::TextUnformatted("not visited by the traversal");
    else
        ImGui::Text("visited in layer %lld (visit %lld)%s", (long long)info->layer,
                    (long long)info->visit_order,
                    info->visited_occluded ? ", already occluded" : "");
    if (!info->h) return false;
    // Why it is occluded: the occluder whose polygon (2D) or layer pass (3D) hid it.
    const bool known =
        info->cause >= 0 &&
        size_t(info->cause) < (s.dimensions == 3 ? s.occluders3d.size() : s.occluders.size());
    if (!known) {
        ImGui::Text("in H since layer %d; its occluder is not known", int(info->h_layer));
        return false;
    }
    const int32_t occluder_layer = s.dimensions == 3
                                       ? s.occluders3d[size_t(info->cause)].layer
                                       : int32_t(s.occluders[size_t(info->cause)].layer);
    ImGui::Text("in H since layer %d, hidden by", int(info->h_layer));
    ImGui::SameLine();
    const bool picked = rgvcOccluderButton(view, info->cause);
    ImGui::SameLine();
    ImGui::Text("(layer %d)", int(occluder_layer));
    return picked;
}

bool drawRgvcObjectVoxels(const RgvcSnapshot& s, RgvcViewState& view,
                          const RgvcObjectVoxels* object, ObjectState state) {
    if (!object || object->index < 0) return false;
    ImGui::Text("object %d, %s:", object->id, objectStateName(state));
    if (object->under_tbv) {
        ImGui::TextWrapped("hidden under its TBV (in T, not in I): not looked at this frame");
        return false;
    }
    if (object->revealed != kRgvcNoLayer)
        ImGui::Text("its TBV was revealed at layer %d; then written into O and I",
                    int(object->revealed));
    ImGui::Text("I voxels %zu: open %lld, occluded %lld, not reached %lld", object->voxels.size(),
                (long long)object->open, (long long)object->occluded, (long long)object->unreached);
    bool changed = false;
    for (size_t k = 0; k < object->voxels.size() && k < size_t(kRgvcListedObjectVoxels); ++k) {
        const RgvcObjectVoxel& v = object->voxels[k];
        char name[64];
        voxelName(name, sizeof name, v.voxel, s.dimensions);
        ImGui::PushID(int(k));
        if (v.layer < 0) {
            ImGui::Text("  %s not reached", name);
        } else if (!v.occluded) {
            ImGui::Text("  %s layer %d, open", name, int(v.layer));
        } else {
            const size_t count = s.dimensions == 3 ? s.occluders3d.size() : s.occluders.size();
            ImGui::Text("  %s layer %d, occluded by", name, int(v.layer));
            ImGui::SameLine();
            if (v.cause >= 0 && size_t(v.cause) < count)
                changed |= rgvcOccluderButton(view, v.cause);
            else
                ImGui::TextUnformatted("?");
        }
        ImGui::PopID();
    }
    if (object->voxels.size() > size_t(kRgvcListedObjectVoxels))
        ImGui::TextDisabled("  ... %zu more", object->voxels.size() - kRgvcListedObjectVoxels);
    return changed;
}

void drawRgvcMemory(const RgvcMatrixMemory& m, int dimensions) {
    const auto kib = [](size_t bytes) { return double(bytes) / 1024.0; };
    ImGui::Text("KiB: O %.1f  Os %.1f  H %.1f  T %.1f", kib(m.occluder), kib(m.static_occluder),
                kib(m.occlusion), kib(m.tbv));
    ImGui::Text("     I static %.1f  I dynamic %.1f", kib(m.identifiers_static),
                kib(m.identifiers_dynamic));
    if (dimensions == 3)
        ImGui::Text("     scratch %.1f  direction map %.1f  = %.1f", kib(m.traversal),
                    kib(m.direction_map), kib(m.total()));
    else
        ImGui::Text("     scratch %.1f  = %.1f", kib(m.traversal), kib(m.total()));
}

}  // namespace gridcull
