// The hzb view's bands, colours and meanings (ui/hzb_tbv/hzb_tbv_view.h).
#include "ui/hzb_tbv/hzb_tbv_view.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace gridcull {

double hzbTbvFractionLeft(const HzbTbvObject& object) {
    const double period = object.expiry - object.created;
    if (!std::isfinite(object.expiry) || !(period > 0.0)) return 1.0;
    return std::clamp(object.remaining / period, 0.0, 1.0);
}

HzbTbvBand hzbTbvBandOf(const HzbTbvObject& object) {
    const double f = hzbTbvFractionLeft(object);
    if (f > 2.0 / 3.0) return HzbTbvBand::Long;
    return f >= 1.0 / 3.0 ? HzbTbvBand::Middle : HzbTbvBand::Short;
}

const char* hzbTbvBandName(HzbTbvBand band) {
    switch (band) {
        case HzbTbvBand::Long:
            return "long-lived";
        case HzbTbvBand::Middle:
            return "half-way";
        case HzbTbvBand::Short:
            return "expiring";
    }
    return "?";
}

const char* hzbTbvBandMeaning(HzbTbvBand band) {
    switch (band) {
        case HzbTbvBand::Long:
            return "> 2/3 of validity period left";
        case HzbTbvBand::Middle:
            return "1/3 to 2/3 of it left";
        case HzbTbvBand::Short:
            return "< 1/3 left: expires soon";
    }
    return "";
}

Swatch hzbTbvBandSwatch(HzbTbvBand band) {
    switch (band) {
        case HzbTbvBand::Long:
            return Swatch::BluishGreen;
        case HzbTbvBand::Middle:
            return Swatch::Orange;
        case HzbTbvBand::Short:
            return Swatch::ReddishPurple;
    }
    return Swatch::White;
}

Swatch hzbNodeOutcomeSwatch(HzbNodeOutcome outcome) {
    switch (outcome) {
        case HzbNodeOutcome::FrustumCulled:
            return Swatch::DimGrey;
        case HzbNodeOutcome::ZCulled:
            return Swatch::White;
        case HzbNodeOutcome::Entered:
            return Swatch::Grey;
    }
    return Swatch::White;
}

float hzbNodeOutcomeAlpha(HzbNodeOutcome outcome) {
    // Entered nodes are the most and say the least: they recede.
    return outcome == HzbNodeOutcome::Entered ? 0.45f : 0.85f;
}

float hzbNodeOutcomeWidth(HzbNodeOutcome outcome) {
    return outcome == HzbNodeOutcome::ZCulled ? kFineLine : kHairline;
}

const char* hzbNodeOutcomeMeaning(HzbNodeOutcome outcome) {
    switch (outcome) {
        case HzbNodeOutcome::FrustumCulled:
            return "outside the frustum";
        case HzbNodeOutcome::ZCulled:
            return "hidden by Z-pyramid";
        case HzbNodeOutcome::Entered:
            return "entries tested";
    }
    return "";
}

const char* hzbObjectStatusMeaning(HzbObjectStatus status) {
    switch (status) {
        case HzbObjectStatus::Visible:
            return "seen this frame";
        case HzbObjectStatus::Hidden:
            return "skipped till it ends";
        case HzbObjectStatus::Expired:
            return "validity ran out";
        case HzbObjectStatus::Revealed:
            return "TBV found visible";
        case HzbObjectStatus::Violated:
            return "fuzzy TBV broken";
        case HzbObjectStatus::Culled:
            return "not seen (no TBVs)";
    }
    return "";
}

std::vector<OverlayPreset> hzbTbvOverlayPresets() {
    return {OverlayPreset::Occlusion, OverlayPreset::Traversal, OverlayPreset::Tbvs,
            OverlayPreset::All};
}

void hzbTbvApplyPreset(HzbTbvViewState& view, OverlayPreset preset) {
    const bool all = preset == OverlayPreset::All;
    const bool traversal = all || preset == OverlayPreset::Traversal;
    view.show_tbvs = all || preset == OverlayPreset::Tbvs;
    view.show_pyramid = all || preset == OverlayPreset::Occlusion;
    for (int o = 0; o < kHzbNodeOutcomeCount; ++o) view.show_nodes[o] = traversal;
    // The nodes the pyramid hid are its answers: occlusion shows them too.
    if (preset == OverlayPreset::Occlusion)
        view.show_nodes[int(HzbNodeOutcome::ZCulled)] = true;
}

int hzbFirstPyramidImage(const HzbTbvSnapshot& snapshot, const HzbTbvViewState& view) {
    const std::vector<HzbPyramidLevel>& levels = snapshot.pyramid_levels;
    if (levels.empty()) return -1;
    if (view.pyramid_level >= 0) {
        // Levels are captured finest first, consecutive: the nearest by number.
        int best = 0;
        for (int i = 0; i < int(levels.size()); ++i)
            if (std::abs(levels[size_t(i)].level - view.pyramid_level) <
                std::abs(levels[size_t(best)].level - view.pyramid_level))
                best = i;
        return best;
    }
    for (int i = 0; i < int(levels.size()); ++i)
        if (std::max(levels[size_t(i)].width, levels[size_t(i)].height) <= kHzbAutoPyramidSide)
            return i;
    return int(levels.size()) - 1;
}

HzbTbvBandCounts countHzbTbvBands(const HzbTbvSnapshot& snapshot) {
    HzbTbvBandCounts counts;
    for (const HzbTbvObject& o : snapshot.objects)
        if (o.has_tbv) ++counts.count[int(hzbTbvBandOf(o))];
    return counts;
}

}  // namespace gridcull
