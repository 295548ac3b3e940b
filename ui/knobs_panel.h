// Knobs: every option of the selected algorithm's family and of the oracle, from
// the family registry, as controls: a slider over the knob's range (logarithmic
// where it spans decades), "auto" for a knob whose default is derived at run
// time. Edits wait for Apply, which re-makes the cullers and re-runs up to the
// current frame; the panel then shows what that cost and the median cull time
// before and after, the two sides of the trade; under them the trade curve
// (ui/trade_panel.h) over every setting. A new family's knobs appear
// here without a line of its own.
#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ui/frame_snapshot.h"
#include "ui/trade_panel.h"

namespace gridcull {

struct KnobsPanelState {
    std::map<std::string, double> edits;  // flag -> value not applied yet
    std::vector<std::string> to_auto;     // flags to return to their automatic default
};

struct KnobsAction {
    bool apply = false;
    std::vector<std::pair<std::string, double>> set;  // flag, value
    std::vector<std::string> unset;                   // back to the default
    TradeAction trade;  // the trade curve under the knobs (ui/trade_panel.h)
};

// Draws into the current ImGui window (a collapsed header until opened).
KnobsAction drawKnobsPanel(const FrameSnapshot& snapshot, KnobsPanelState& state);

}  // namespace gridcull
