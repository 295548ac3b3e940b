#include "ui/knobs_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "culling/registry/registry.h"

namespace gridcull {

namespace {

// A range spanning more than this many times its low end gets a logarithmic
// slider: otherwise the useful small values crowd into its first pixels.
constexpr double kLogarithmicSpan = 100.0;

bool isAuto(const Knob& knob, const KnobValues& applied, const KnobsPanelState& state) {
    if (knob.automatic.empty()) return false;
    if (state.edits.count(knob.flag)) return false;
    if (std::find(state.to_auto.begin(), state.to_auto.end(), knob.flag) != state.to_auto.end())
        return true;
    return !applied.has(knob.flag);
}

void knobTooltip(const Knob& knob) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::TextUnformatted(knob.help.c_str());
    ImGui::Text("--%s, %s, default %s", knob.flag.c_str(), knobRangeText(knob).c_str(),
                knobDefaultText(knob).c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

// `width`: where the flags start, the same for every knob so they line up.
void drawKnob(const Knob& knob, const KnobValues& applied, KnobsPanelState& state, float width) {
    ImGui::PushID(knob.flag.c_str());
    const float left = ImGui::GetCursorPosX();
    const bool automatic = isAuto(knob, applied, state);
    if (!knob.automatic.empty()) {
        bool on = automatic;
        if (ImGui::Checkbox(knob.automatic.c_str(), &on)) {
            state.edits.erase(knob.flag);
            state.to_auto.erase(std::remove(state.to_auto.begin(), state.to_auto.end(), knob.flag),
                                state.to_auto.end());
            if (on && applied.has(knob.flag)) state.to_auto.push_back(knob.flag);
            if (!on) state.edits[knob.flag] = knob.min;
        }
        knobTooltip(knob);
        ImGui::SameLine();
    }
    const auto edit = state.edits.find(knob.flag);
    double value = edit != state.edits.end() ? edit->second : applied.get(knob);
    if (automatic) value = knob.min;
    ImGui::BeginDisabled(automatic);
    ImGui::SetNextItemWidth(std::max(width - (ImGui::GetCursorPosX() - left), 40.0f));
    const bool logarithmic = knob.min > 0.0 && knob.max / knob.min > kLogarithmicSpan;
    const ImGuiSliderFlags flags =
        ImGuiSliderFlags_AlwaysClamp | (logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
    bool changed = false;
    if (knob.kind == KnobKind::Integer && knob.min == 0.0 && knob.max == 1.0) {
        bool on = value != 0.0;  // a switch (a section 6 extension, say)
        changed = ImGui::Checkbox(knob.flag.c_str(), &on);
        value = on ? 1.0 : 0.0;
    } else if (knob.kind == KnobKind::Integer) {
        int v = int(std::lround(value));
        changed =
            ImGui::SliderInt(knob.flag.c_str(), &v, int(knob.min), int(knob.max), "%d", flags);
        value = v;
    } else {
        changed = ImGui::SliderScalar(knob.flag.c_str(), ImGuiDataType_Double, &value, &knob.min,
                                      &knob.max, "%.4g", flags);
    }
    ImGui::EndDisabled();
    knobTooltip(knob);
    if (changed) {
        if (!applied.has(knob.flag) && knob.automatic.empty() && value == knob.default_value)
            state.edits.erase(knob.flag);
        else if (applied.has(knob.flag) && value == applied.get(knob))
            state.edits.erase(knob.flag);
        else
            state.edits[knob.flag] = value;
    }
    ImGui::PopID();
}

// `whose`: the algorithm named in the heading (titles may hold letters the
// panel's font lacks, such as the c with caron of a paper's author).
void drawFamilyKnobs(const FamilyEntry& family, const std::string& whose, const KnobValues& applied,
                     KnobsPanelState& state, float width) {
    ImGui::TextDisabled("knobs of %s", whose.c_str());
    if (family.knobs.empty()) ImGui::TextUnformatted("  nothing to turn");
    for (const Knob& knob : family.knobs) drawKnob(knob, applied, state, width);
}

void drawCost(const FrameSnapshot& snapshot) {
    const KnobApplyCost& cost = snapshot.knob_cost;
    if (!cost.valid) return;
    ImGui::TextWrapped(
        "Last change re-ran %d frames%s. Over them, PVS/exact went from %.2f "
        "to %.2f.",
        cost.frames, snapshot.show_timings ? "" : " (times hidden in shots)", cost.pvs_ratio_before,
        cost.pvs_ratio_after);
    if (snapshot.show_timings)
        ImGui::TextWrapped("It took %.0f ms; the median cull went from %.2f ms to %.2f ms.",
                           cost.rerun_ms, cost.cull_ms_before, cost.cull_ms_after);
}

}  // namespace

KnobsAction drawKnobsPanel(const FrameSnapshot& snapshot, KnobsPanelState& state) {
    KnobsAction action;
    if (!ImGui::CollapsingHeader("Knobs")) return action;
    const KnobValues& applied = *snapshot.knobs;
    const std::string& algo = (*snapshot.algo_names)[size_t(snapshot.algo_index)];
    const FamilyEntry* family = familyOfAlgorithm(algo);
    const FamilyEntry* reference = familyOfAlgorithm(referenceAlgorithm());
    const float width = ImGui::GetContentRegionAvail().x * 0.62f;
    if (family && family != reference) drawFamilyKnobs(*family, algo, applied, state, width);
    if (reference)
        drawFamilyKnobs(*reference, "the oracle (" + referenceAlgorithm() + ")", applied, state,
                        width);

    const bool pending = !state.edits.empty() || !state.to_auto.empty();
    ImGui::BeginDisabled(!pending);
    char label[64];
    std::snprintf(label, sizeof label, "Apply (re-runs frames 0 to %d)", snapshot.frame);
    if (ImGui::Button(label)) {
        action.apply = true;
        action.set.assign(state.edits.begin(), state.edits.end());
        action.unset = state.to_auto;
        state.edits.clear();
        state.to_auto.clear();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard")) {
        state.edits.clear();
        state.to_auto.clear();
    }
    ImGui::EndDisabled();
    drawCost(snapshot);
    // The same trade measured over every setting the family sweeps.
    if (snapshot.trade) action.trade = drawTradePanel(*snapshot.trade, algo);
    return action;
}

}  // namespace gridcull
