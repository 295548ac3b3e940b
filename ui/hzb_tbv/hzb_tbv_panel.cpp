// The hzb panel (ui/hzb_tbv/hzb_tbv_panel.h).
#include "ui/hzb_tbv/hzb_tbv_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "ui/hzb_tbv/hzb_pyramid_images.h"
#include "ui/hzb_tbv/hzb_tbv_overlay.h"

namespace gridcull {

namespace {

constexpr ImGuiColorEditFlags kSwatchFlags = ImGuiColorEditFlags_NoTooltip |
                                             ImGuiColorEditFlags_NoDragDrop |
                                             ImGuiColorEditFlags_AlphaPreview;
const ImVec2 kSwatchSize(13, 13);

void swatch(const char* id, Swatch s, float alpha = 1.0f) {
    const Rgb c = swatchColor(s);
    ImGui::ColorButton(id, ImVec4(c.r, c.g, c.b, alpha), kSwatchFlags, kSwatchSize);
    ImGui::SameLine();
}

// A grey as the pyramid images show it: white at `grey` over black.
void greySwatch(const char* id, float grey) {
    const Rgb w = swatchColor(Swatch::White), b = swatchColor(Swatch::NearBlack);
    const auto mix = [grey](float hi, float lo) { return lo + grey * (hi - lo); };
    ImGui::ColorButton(id, ImVec4(mix(w.r, b.r), mix(w.g, b.g), mix(w.b, b.b), 1.0f), kSwatchFlags,
                       kSwatchSize);
    ImGui::SameLine();
}

const char* modeText(const HzbTbvSnapshot& hzb) {
    if (!hzb.uses_tbvs) return "no TBVs: every moving object in T each frame";
    return hzb.mode == TbvUpdateMode::Implicit ? "TBVs, implicit update (TBVi, 3.6)"
                                               : "TBVs, explicit update (TBVe, 3.3)";
}

// Seconds as the panel prints them; "never" for a TBV that does not expire.
void secondsText(char* out, size_t size, double s) {
    if (!std::isfinite(s))
        std::snprintf(out, size, "never");
    else
        std::snprintf(out, size, "%.2f s", s);
}

void objectStates(const HzbTbvSnapshot& hzb) {
    ImGui::Text("dynamic objects (D): %zu", hzb.objects.size());
    for (int k = 0; k < kHzbObjectStatusCount; ++k) {
        const auto status = HzbObjectStatus(k);
        // `hzb` has no TBVs: its objects are visible or culled only; the TBV
        // algorithms never cull without one.
        const bool without_tbvs =
            status == HzbObjectStatus::Visible || status == HzbObjectStatus::Culled;
        if (hzb.uses_tbvs ? status == HzbObjectStatus::Culled : !without_tbvs) continue;
        ImGui::Text("  %-11s %5lld  %s", hzbObjectStatusName(status),
                    (long long)hzb.status_count[size_t(k)], hzbObjectStatusMeaning(status));
    }
}

void tbvKey(const HzbTbvSnapshot& hzb, HzbTbvViewState& view) {
    const HzbTbvBandCounts counts = countHzbTbvBands(hzb);
    ImGui::Checkbox("TBVs##show", &view.show_tbvs);
    ImGui::SameLine();
    ImGui::TextUnformatted("by validity left (wire boxes, as in T)");
    for (int b = 0; b < kHzbTbvBandCount; ++b) {
        const auto band = HzbTbvBand(b);
        swatch(hzbTbvBandName(band), hzbTbvBandSwatch(band));
        ImGui::Text("%-10s %4lld  %s", hzbTbvBandName(band), (long long)counts.of(band),
                    hzbTbvBandMeaning(band));
    }
}

void expiryRows(const HzbTbvSnapshot& hzb);

void expirationQueue(const HzbTbvSnapshot& hzb) {
    char title[80];
    std::snprintf(title, sizeof title, "expiration queue Q: %zu TBVs###Q", hzb.queue_size);
    if (!ImGui::TreeNodeEx(title, ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (hzb.next_expiries.empty()) ImGui::TextDisabled("(empty)");
    expiryRows(hzb);
    ImGui::TreePop();
}

void expiryRows(const HzbTbvSnapshot& hzb) {
    if (hzb.next_expiries.empty()) return;
    const int rows = std::min(int(hzb.next_expiries.size()), kHzbExpiryRows);
    for (int k = 0; k < rows; ++k) {
        const HzbExpiry& e = hzb.next_expiries[size_t(k)];
        char at[32], left[32];
        secondsText(at, sizeof at, e.expiry);
        secondsText(left, sizeof left, e.remaining);
        ImGui::Text("object %-6d expires %-9s left %s", e.object_id, at, left);
    }
    if (hzb.queue_size > size_t(rows))
        ImGui::TextDisabled("... %zu later", hzb.queue_size - size_t(rows));
}

void focusedObject(const HzbTbvSnapshot& hzb, const HzbTbvPanelInput& input) {
    const int index = input.focus_object;
    if (!input.scene || index < 0 || index >= int(input.scene->objects.size())) {
        ImGui::TextDisabled("point at (click) an object: its state shows here");
        return;
    }
    const SceneObject& object = input.scene->objects[size_t(index)];
    const char* how = input.focus_pinned ? "picked" : "under the mouse";
    const HzbTbvObject* o = hzb.objectAt(index);
    if (!o) {
        ImGui::Text("object %d (%s): static, always in T", object.id, how);
        return;
    }
    ImGui::Text("object %d (%s): %s, %s", object.id, how, hzbObjectStatusName(o->status),
                o->in_pvs ? "in the PVS" : "not in the PVS");
    char period[32];
    secondsText(period, sizeof period, o->period);
    if (!o->has_tbv) {
        if (hzb.uses_tbvs) ImGui::Text("  no TBV; next validity period %s", period);
        return;
    }
    char created[32], expiry[32], left[32];
    secondsText(created, sizeof created, o->created);
    secondsText(expiry, sizeof expiry, o->expiry);
    secondsText(left, sizeof left, o->remaining);
    const HzbTbvBand band = hzbTbvBandOf(*o);
    swatch("focused TBV", hzbTbvBandSwatch(band));
    ImGui::Text("TBV%s made %s, expires %s", o->new_tbv ? " (new)" : "", created, expiry);
    ImGui::Text("  left %s (%s); next period %s", left, hzbTbvBandName(band), period);
}

void octreeNodes(const HzbTbvSnapshot& hzb, HzbTbvViewState& view) {
    ImGui::Text("octree T: %d nodes, depth <= %d", hzb.octree_nodes, hzb.octree_max_depth);
    ImGui::Text("octree nodes the traversal reached: %zu", hzb.nodes.size());
    for (int k = 0; k < kHzbNodeOutcomeCount; ++k) {
        const auto outcome = HzbNodeOutcome(k);
        ImGui::PushID(k);
        ImGui::Checkbox("##node", &view.show_nodes[k]);
        ImGui::SameLine();
        swatch(hzbNodeOutcomeName(outcome), hzbNodeOutcomeSwatch(outcome));
        const long long n = (long long)hzb.node_count[size_t(k)];
        if (view.show_nodes[k])
            ImGui::Text("%-14s %4lld %s", hzbNodeOutcomeName(outcome), n,
                        hzbNodeOutcomeMeaning(outcome));
        else
            ImGui::TextDisabled("%-14s %4lld %s", hzbNodeOutcomeName(outcome), n,
                                hzbNodeOutcomeMeaning(outcome));
        ImGui::PopID();
    }
    const HzbOverlayCounts counts = countHzbNodesShown(hzb, view);
    if (counts.nodes_drawn < counts.nodes_shown)
        ImGui::Text("nodes drawn: the first %d of %d, front to back (cap %d)", counts.nodes_drawn,
                    counts.nodes_shown, kHzbMaxNodesDrawn);
    else
        ImGui::Text("nodes drawn: %d (cap %d)", counts.nodes_drawn, kHzbMaxNodesDrawn);
}

void pyramid(const HzbTbvSnapshot& hzb, HzbTbvViewState& view) {
    ImGui::Text("Z-pyramid: level 0 %d x %d, %d levels", hzb.pyramid_width, hzb.pyramid_height,
                hzb.pyramid_level_count);
    const int first = hzbFirstPyramidImage(hzb, view);
    ImGui::Checkbox("images##pyramid", &view.show_pyramid);
    if (first < 0) return;
    ImGui::SameLine();
    const int lo = hzb.pyramid_levels.front().level, hi = hzb.pyramid_levels.back().level;
    int level = hzb.pyramid_levels[size_t(first)].level;
    char label[48];
    std::snprintf(label, sizeof label, "from level %d%s", level,
                  view.pyramid_level < 0 ? " (auto)" : "");
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderInt("##pyramid level", &level, lo, hi, label, ImGuiSliderFlags_AlwaysClamp))
        view.pyramid_level = level;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "The finest Z-pyramid level shown (--hzb-pyramid-level); %d levels from it",
            kHzbPyramidImages);
    greySwatch("near", 1.0f);
    ImGui::TextUnformatted("near");
    ImGui::SameLine();
    greySwatch("far", kHzbFarGrey);
    ImGui::TextUnformatted("far (per images shown)");
    ImGui::SameLine();
    greySwatch("empty", 0.0f);
    ImGui::TextUnformatted("empty");
}

void counters(const HzbTbvSnapshot& hzb) {
    const CullStats& c = hzb.stats;
    ImGui::Text("occlusion tests %lld, object updates %lld",
                (long long)c.get(Counter::OcclusionTests),
                (long long)c.get(Counter::ObjectUpdates));
    if (!hzb.uses_tbvs) return;
    const TbvFrameCounters& t = hzb.tbv_counters;
    ImGui::Text("TBVs made %lld, expired %lld, revealed %lld, violated %lld",
                (long long)t.tbv_created, (long long)t.tbv_expired, (long long)t.tbv_revealed,
                (long long)(t.tbv_violated + t.tbv_invalidated));
    ImGui::Text("messages: state %lld, TBV %lld", (long long)t.state_fetches,
                (long long)t.tbv_messages);
}

}  // namespace

void drawHzbTbvPanel(const HzbTbvSnapshot& hzb, const HzbTbvPanelInput& input,
                     HzbTbvViewState& view) {
    if (!hzb.valid) return;
    char title[96];
    std::snprintf(title, sizeof title, "Octree + Z-pyramid (%s)###hzb", input.algo);
    if (!ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::TextUnformatted(modeText(hzb));
    objectStates(hzb);
    focusedObject(hzb, input);
    if (hzb.uses_tbvs) {
        tbvKey(hzb, view);
        expirationQueue(hzb);
    }
    octreeNodes(hzb, view);
    pyramid(hzb, view);
    counters(hzb);
}

}  // namespace gridcull
